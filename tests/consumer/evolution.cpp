// Evolves through the installed thyrix::Evolution: CMA-ES finds the gravity that carries a
// circle to x = 1 in 10 steps of 0.01 s. Quasistatic, x = 10 * 0.01 * g, so g = 10.
#include <Evolution/CmaEs.h>
#include <Evolution/Evaluate.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

struct Reach {
  long steps() const { return 10; }
  std::unique_ptr<thyrix::Simulator> makeWorld(const std::vector<double>& g, std::uint64_t) const {
    auto world = std::make_unique<thyrix::Simulator>(thyrix::real(0.01));
    world->setGravity({static_cast<thyrix::real>(g[0]), 0});
    world->registerObject(std::make_unique<thyrix::Circle>(thyrix::real(0.5), thyrix::real(1)));
    return world;
  }
  double fitness(const thyrix::Simulator& world) const {
    const double x = static_cast<double>(world.objects[0].r.x);
    return -(x - 1) * (x - 1);
  }
};

int main() {
  thyrix::CmaEs strategy({0.0}, 5.0, 8);
  thyrix::EvaluationOptions options;
  options.threads = 2;
  for (int generation = 0; generation < 60; ++generation)
    strategy.tell(thyrix::evaluate(Reach{}, strategy.ask(), options));
  const double g = strategy.mean()[0];
  const bool ok = std::abs(g - 10) < 1e-2;
  std::printf("consumer_evolution: g = %g %s\n", g, ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
