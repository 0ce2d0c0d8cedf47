#include <Agents/SpherusSimulator.h>

#include <Agents/ArenaSetup.h>

#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <string>

namespace thyrix {

SpherusSimulator::SpherusSimulator(const Options& options, std::unique_ptr<Controller> controller)
    : Simulator(options.timestep) {
  if (options.objects < 0)
    throw InvalidArgument("SpherusSimulator.objects", "must not be negative");
  const real size = options.size;
  const SpherusParameters parameters;
  // The farthest any part of the agent reaches from its centre, whatever its link length.
  const real reach = parameters.maxLinkLength / 2 + parameters.radius;
  Vector2 centre{size / 2, size / 2};
  real heading = pi<real> / 2;
  if (options.poseSeed) {
    if (!(size > 4 * reach))
      throw InvalidArgument("SpherusSimulator.size",
                            "must exceed 4 agent reaches (" + std::to_string(4 * reach) +
                                " m) for a random pose (got " + std::to_string(size) + ")");
    MTRandom poseRandom(*options.poseSeed);
    heading = static_cast<real>(poseRandom.uniform(0, 2 * pi<double>));
    centre.x = static_cast<real>(poseRandom.uniform(2 * reach, size - 2 * reach));
    centre.y = static_cast<real>(poseRandom.uniform(2 * reach, size - 2 * reach));
  }
  addArenaWalls(*this, size);
  spherus_ = &registerObject(std::make_unique<Spherus>(std::move(controller), parameters));
  spherus_->place(centre, heading);

  // Rejection sampling: keep a gap of one radius to everything placed before.
  MTRandom random(options.seed);
  const real r = options.objectRadius;
  const real clearance = reach + 2 * r;
  std::vector<Vector2> placed;
  scatterPoints(
      random, placed, options.objects, r, size,
      [&](Vector2 p) { return distance(p, centre) < clearance; }, "SpherusSimulator.objects");
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
