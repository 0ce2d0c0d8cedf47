#include <ThyrixLite/Integrator.h>

namespace thyrix {

void Integrator::integrate(const ObjectList& objects, real dt) const {
  for (PhysicalObject& object : objects) object.integrate(dt);
}

void Integrator::integrate(const ObjectList& objects,
                           std::span<const std::uint8_t> defaultIntegration, real dt) const {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    PhysicalObject& object = objects[i];
    if (defaultIntegration[i] != 0)
      object.PhysicalObject::integrate(dt);
    else
      object.integrate(dt);
  }
}

}  // namespace thyrix
