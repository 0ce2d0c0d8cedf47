#include <Agents/PacSimulator.h>

#include <Agents/ArenaSetup.h>

#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

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
  addArenaWalls(*this, size);
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
  scatterPoints(
      random, placed, options.food, r, size,
      [&](Vector2 p) {
        return distance(p, homes[0]) < clearance || distance(p, homes[1]) < clearance;
      },
      "PacSimulator.food");
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
