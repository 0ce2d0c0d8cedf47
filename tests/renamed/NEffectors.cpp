// An agent's effector count under its original name must not compile; the error names
// effectorCount.
#include <Agents/Iunctus.h>
#include <Agents/Pac.h>
#include <Agents/Spherus.h>

int effectorsOf(const thyrix::Pac& pac) {
#ifdef THYRIX_OLD_NAME
  return thyrix::Spherus::nEffectors + thyrix::Iunctus::nEffectors + pac.nEffectors;
#else
  return thyrix::Spherus::effectorCount + thyrix::Iunctus::effectorCount + pac.effectorCount;
#endif
}
