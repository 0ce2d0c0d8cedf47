// Builds a world through the installed headers and checks one closed-form step: v = F / m.
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  thyrix::Simulator simulator;
  auto& circle = simulator.registerObject(std::make_unique<thyrix::Circle>(0.5, 2.0));
  circle.externalForce = {4, 0};
  simulator.advanceTime();
  const bool ok = std::abs(circle.v.x - 2) < 1e-5 && std::abs(circle.r.x - 0.02) < 1e-6;
  std::printf("consumer: v = (%g, %g) %s\n", static_cast<double>(circle.v.x),
              static_cast<double>(circle.v.y), ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
