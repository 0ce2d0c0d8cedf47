#include "PacSimulator.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace thyrix {

PacSimulator::PacSimulator(const Options& options, std::unique_ptr<Controller> first,
                           std::unique_ptr<Controller> second)
    : Simulator(options.timestep), options_(options) {
  if (options.food < 0) throw InvalidArgument("PacSimulator.food", "must not be negative");
  const real size = options.size;
  const real reach = options.pac.ringRadius + options.pac.radius;  // mouth closed
  if (!(size >= 6 * reach) || !std::isfinite(size))
    throw InvalidArgument("PacSimulator.size", "must leave room for the two Pacs (at least " +
                                                   std::to_string(6 * reach) + ")");
  registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  registerObject(std::make_unique<Border>(Vector2{0, size}, Vector2{0, -1}));
  registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
  registerObject(std::make_unique<Border>(Vector2{size, 0}, Vector2{-1, 0}));
  std::unique_ptr<Controller> controllers[2] = {std::move(first), std::move(second)};
  const Vector2 homes[2] = {{size / 4, size / 2}, {3 * size / 4, size / 2}};
  const real headings[2] = {0, pi<real>};
  for (std::size_t i = 0; i < 2; ++i) {
    pacs_[i] = &registerObject(std::make_unique<Pac>(std::move(controllers[i]), options.pac));
    pacs_[i]->place(homes[i], headings[i]);
  }
  for (Circle* circle : pacs_[1]->circles()) circle->color = colors::orange;

  // Rejection sampling: clear of the Pacs (with their mouths open) and a gap of one radius to
  // every food circle placed before.
  MTRandom random(options.seed);
  const real r = options.foodRadius;
  const real clearance = real(1.5) * reach + 2 * r;
  std::vector<Vector2> placed;
  int attempts = 0;
  while (static_cast<int>(placed.size()) < options.food) {
    if (++attempts > 1000 * (options.food + 1))
      throw InvalidArgument("PacSimulator.food", "do not fit in the arena");
    const Vector2 p{static_cast<real>(random.uniform(2 * r, size - 2 * r)),
                    static_cast<real>(random.uniform(2 * r, size - 2 * r))};
    if (distance(p, homes[0]) < clearance || distance(p, homes[1]) < clearance) continue;
    if (std::any_of(placed.begin(), placed.end(),
                    [&](Vector2 q) { return distance(p, q) < 3 * r; }))
      continue;
    placed.push_back(p);
  }
  for (const Vector2 p : placed) {
    auto& circle = registerObject(std::make_unique<Circle>(r, options.foodMass));
    circle.r = p;
    circle.color = colors::green;
    food_.push_back(&circle);
  }
}

int PacSimulator::foodInside(const Pac& pac) const {
  return static_cast<int>(std::count_if(food_.begin(), food_.end(),
                                        [&pac](const Circle* f) { return pac.contains(f->r); }));
}

}  // namespace thyrix
