#include "SpherusSimulator.h"

#include "ArenaSetup.h"

#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

namespace thyrix {

SpherusSimulator::SpherusSimulator(const Options& options, std::unique_ptr<Controller> controller)
    : Simulator(options.timestep) {
  if (options.objects < 0)
    throw InvalidArgument("SpherusSimulator.objects", "must not be negative");
  const real size = options.size;
  addArenaWalls(*this, size);
  spherus_ = &registerObject(std::make_unique<Spherus>(std::move(controller)));
  const Vector2 middle{size / 2, size / 2};
  spherus_->place(middle, pi<real> / 2);

  // Rejection sampling: keep a gap of one radius to everything placed before.
  MTRandom random(options.seed);
  const real r = options.objectRadius;
  const real clearance =
      spherus_->parameters().maxLinkLength / 2 + spherus_->parameters().radius + 2 * r;
  std::vector<Vector2> placed;
  scatterPoints(
      random, placed, options.objects, r, size,
      [&](Vector2 p) { return distance(p, middle) < clearance; }, "SpherusSimulator.objects");
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
