// An agent's sensor count under its original name must not compile; the error names
// sensorCount.
#include <Agents/Iunctus.h>
#include <Agents/Pac.h>
#include <Agents/Spherus.h>

int sensorsOf(const thyrix::Pac& pac) {
#ifdef THYRIX_OLD_NAME
  return thyrix::Spherus::nSensors + thyrix::Iunctus::nSensors + pac.nSensors;
#else
  return thyrix::Spherus::sensorCount + thyrix::Iunctus::sensorCount + pac.sensorCount();
#endif
}
