// The setting's old name must not compile; the error names baraffMaxIslandContacts.
#include <ThyrixLite/Simulator.h>

void solveExactly(thyrix::Simulator& simulator) {
#ifdef THYRIX_OLD_NAME
  simulator.solverSettings().baraffMaxContacts = 1000;
#else
  simulator.solverSettings().baraffMaxIslandContacts = 1000;
#endif
}
