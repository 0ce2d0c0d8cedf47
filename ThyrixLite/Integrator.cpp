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

void Integrator::integrateExcept(const ObjectList& objects,
                                 std::span<const std::uint32_t> customObjects, real dt) const {
  std::size_t begin = 0;
  const auto integrateRun = [&objects, dt, &begin](std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) objects[i].PhysicalObject::integrate(dt);
  };
  for (const std::uint32_t custom : customObjects) {
    integrateRun(custom);
    objects[custom].integrate(dt);
    begin = custom + std::size_t{1};
  }
  integrateRun(objects.size());
}

}  // namespace thyrix
