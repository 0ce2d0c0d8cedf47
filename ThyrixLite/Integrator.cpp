#include <ThyrixLite/Integrator.h>

namespace thyrix {

void Integrator::integrate(const ObjectList& objects, real dt) const {
  for (PhysicalObject& object : objects) object.integrate(dt);
}

}  // namespace thyrix
