#include <ThyrixLite/Integrator.h>

namespace thyrix {

void Integrator::integrate(const ObjectList& objects, real dt) const {
  for (PhysicalObject& object : objects) object.integrate(dt);
}

void Integrator::integrateExcept(const ObjectList& objects,
                                 std::span<const std::uint32_t> customObjects, real dt) const {
  forEachInRuns(
      objects, customObjects,
      [dt](PhysicalObject& object) { object.PhysicalObject::integrate(dt); },
      [dt](PhysicalObject& object) { object.integrate(dt); });
}

}  // namespace thyrix
