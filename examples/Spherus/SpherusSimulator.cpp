#include "SpherusSimulator.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <algorithm>

namespace thyrix {

SpherusSimulator::SpherusSimulator(const Options& options, std::unique_ptr<Controller> controller)
    : Simulator(options.timestep) {
  if (options.objects < 0)
    throw InvalidArgument("SpherusSimulator.objects", "must not be negative");
  const real size = options.size;
  registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  registerObject(std::make_unique<Border>(Vector2{0, size}, Vector2{0, -1}));
  registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
  registerObject(std::make_unique<Border>(Vector2{size, 0}, Vector2{-1, 0}));
  spherus_ = &registerObject(std::make_unique<Spherus>(std::move(controller)));
  const Vector2 middle{size / 2, size / 2};
  spherus_->place(middle, pi<real> / 2);

  // Rejection sampling: keep a gap of one radius to everything placed before.
  MTRandom random(options.seed);
  const real r = options.objectRadius;
  const real clearance =
      spherus_->parameters().maxLinkLength / 2 + spherus_->parameters().radius + 2 * r;
  std::vector<Vector2> placed;
  int attempts = 0;
  while (static_cast<int>(placed.size()) < options.objects) {
    if (++attempts > 1000 * (options.objects + 1))
      throw InvalidArgument("SpherusSimulator.objects", "do not fit in the arena");
    const Vector2 p{static_cast<real>(random.uniform(2 * r, size - 2 * r)),
                    static_cast<real>(random.uniform(2 * r, size - 2 * r))};
    if (distance(p, middle) < clearance) continue;
    if (std::any_of(placed.begin(), placed.end(),
                    [&](Vector2 q) { return distance(p, q) < 3 * r; }))
      continue;
    placed.push_back(p);
  }
  for (const Vector2 p : placed) {
    auto& circle = registerObject(std::make_unique<Circle>(r, real(1)));
    circle.r = p;
    obstacles_.push_back(&circle);
  }
  // Room for more simultaneous contacts than the arena sees (a few), so that no step ever
  // allocates, not even the first one with a contact.
  reserveContacts(contactCapacity);
}

}  // namespace thyrix
