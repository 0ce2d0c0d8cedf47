// OrbitWorldWx: GUIWx showing and stepping a World that is not a Simulator: a point moving on
// a circle of radius 3 m about (5, 5) at 1 rad/s from angle 0, drawn as a red disc of radius
// 0.4 m. It takes the shared GUI options (--screenshot, --after, --geometry ...); orbit_check.py
// checks its screenshot against the closed form.

#include <GUIWx/GuiOptions.h>
#include <GUIWx/SimulationApp.h>

#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/World.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace {

using thyrix::real;
using thyrix::Vector2;

/// A process of one point on a circle, stepped and drawn through World's interface alone.
class OrbitWorld : public thyrix::World {
 public:
  OrbitWorld() : World(real(0.01)) {}

  void advanceTime() override {
    World::advanceTime();
    angle_ = static_cast<real>(time());  // 1 rad/s
  }

  void draw(thyrix::GUI& gui) const override {
    const Vector2 centre{5, 5};
    gui.drawCircle(centre + Vector2{std::cos(angle_), std::sin(angle_)} * 3, real(0.4), angle_,
                   thyrix::colors::red, thyrix::colors::black);
  }

 private:
  real angle_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  thyrix::GuiOptions options;
  try {
    for (int i = 1; i < argc;) {
      const int used = thyrix::parseGuiOption(argc, argv, i, options);
      if (used == 0) throw std::invalid_argument(std::string("unknown option: ") + argv[i]);
      i += used;
    }
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "OrbitWorldWx: %s\n%s", error.what(), thyrix::guiOptionsUsage);
    return 2;
  }
  thyrix::SimulationSetup setup;
  setup.title = "OrbitWorldWx - Thyrix";
  setup.makeWorld = [] { return std::make_unique<OrbitWorld>(); };
  return thyrix::runSimulationApp(std::move(setup), options, argv[0]);
}
