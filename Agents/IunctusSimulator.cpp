#include <Agents/IunctusSimulator.h>

#include <Agents/ArenaSetup.h>

#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>

namespace thyrix {

IunctusSimulator::IunctusSimulator(const Options& options, std::unique_ptr<Controller> controller)
    : Simulator(options.timestep) {
  if (options.objects < 0)
    throw InvalidArgument("IunctusSimulator.objects", "must not be negative");
  const real size = options.size;
  // The agent sits 2 m from the left wall and its open limb reaches 2.85 m up: the arena must
  // hold that and the first object ahead.
  if (!(size >= 6)) throw InvalidArgument("IunctusSimulator.size", "must be at least 6 m");
  addArenaWalls(*this, size);
  iunctus_ = &registerObject(std::make_unique<Iunctus>(std::move(controller)));
  const Vector2 start{2, size / 2 - 1};
  iunctus_->place(start, 0);

  // The first object straight ahead; the others by rejection sampling, a gap of one radius to
  // everything placed before and clear of the agent's reach.
  MTRandom random(options.seed);
  const real r = options.objectRadius;
  const real reach = iunctus_->parameters().baseRadius + 3 * iunctus_->parameters().linkLength;
  std::vector<Vector2> placed;
  if (options.objects > 0) placed.push_back(start + Vector2{real(1.5), 0});
  scatterPoints(
      random, placed, options.objects, r, size,
      [&](Vector2 p) { return distance(p, start) < reach + r; }, "IunctusSimulator.objects");
  for (const Vector2 p : placed) {
    auto& circle = registerObject(std::make_unique<Circle>(r, real(1)));
    circle.r = p;
    objects_.push_back(&circle);
  }
  reserveContacts(contactCapacity);
}

}  // namespace thyrix

namespace thyrix {

IunctusGrasper& IunctusSimulator::useGrasper(real carryDistance) {
  if (objects_.empty()) throw InvalidArgument("IunctusSimulator.objects", "nothing to grasp");
  auto grasper = std::make_unique<IunctusGrasper>(*iunctus_, *objects_.front(), carryDistance);
  IunctusGrasper& result = *grasper;
  iunctus_->setController(std::move(grasper));
  return result;
}

}  // namespace thyrix
