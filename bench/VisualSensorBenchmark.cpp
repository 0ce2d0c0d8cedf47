// The visual sensor's update: 14 pixels against 100 objects (circles, or half circles and half
// capsules) in a walled arena, for fields of view from 90 to 360 degrees. The eye turns a little
// at each iteration so that the objects in view change.

#include <Scenes.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/VisualSensor.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <benchmark/benchmark.h>

#include <memory>

namespace thyrix {
namespace {

/// 100 objects in a 10 x 10 arena: circles of radius 0.2 at random, the last @p capsules of
/// them replaced by capsules (l = 0.3, R = 0.1) at random poses; the eye is on the first circle.
struct Arena {
  explicit Arena(int capsules) {
    scenes::addWalls(simulator, 10, 10);
    circles = scenes::addRandomCircles(simulator, 100 - capsules, real(0.2), 10, 3);
    MTRandom random(5);
    for (int i = 0; i < capsules; ++i) {
      auto& capsule =
          simulator.registerObject(std::make_unique<CappedRectangle>(real(0.3), real(0.1), 1));
      capsule.r = {static_cast<real>(random.uniform(0.5, 9.5)),
                   static_cast<real>(random.uniform(0.5, 9.5))};
      capsule.alpha = static_cast<real>(random.uniform(-3.14, 3.14));
    }
  }
  Simulator simulator;
  std::vector<PhysicalObject*> circles;
};

void visualSensorUpdate(benchmark::State& state, int capsules) {
  Arena arena(capsules);
  const int pixels = 14;
  const real field = static_cast<real>(state.range(0)) * pi<real> / 180;
  PhysicalObject& body = *arena.circles[0];
  VisualSensor sensor(body, {real(0.2), 0}, 0, pixels, field / pixels);
  real sum = 0;
  for (auto _ : state) {
    body.alpha += real(0.01);
    sensor.update(arena.simulator.objects);
    benchmark::DoNotOptimize(sum += sensor.activations()[pixels / 2]);
  }
  state.counters["objects"] = static_cast<double>(arena.simulator.objects.size());
}

void BM_VisualSensorCircles(benchmark::State& state) { visualSensorUpdate(state, 0); }
void BM_VisualSensorMixed(benchmark::State& state) { visualSensorUpdate(state, 50); }
BENCHMARK(BM_VisualSensorCircles)->Arg(90)->Arg(180)->Arg(270)->Arg(360);
BENCHMARK(BM_VisualSensorMixed)->Arg(90)->Arg(180)->Arg(270)->Arg(360);

}  // namespace
}  // namespace thyrix
