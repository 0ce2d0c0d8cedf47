// Calling the original controll() by hand must not compile; the error names control().
#include <ThyrixLite/PhysicalObject.h>

void runController(thyrix::PhysicalObject& object) {
#ifdef THYRIX_OLD_NAME
  object.controll();
#else
  object.control();
#endif
}
