#include "SpherusEnvironment.h"

#include <Evolution/SeedDerivation.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <string>

namespace thyrix::python {

SpherusEnvironment::SpherusEnvironment(const SpherusTask& task) : task_(task) {
  if (task_.stepCount <= 0)
    throw InvalidArgument("SpherusEnv.steps",
                          "must be positive (got " + std::to_string(task_.stepCount) + ")");
}

void SpherusEnvironment::reset(std::uint64_t seed) {
  seed_ = seed;
  episode_ = 0;
  start();
}

void SpherusEnvironment::resetNext() {
  ++episode_;
  start();
}

void SpherusEnvironment::start() {
  const std::uint64_t episodeSeed = deriveSeed(seed_, episode_, 0, 0);
  SpherusSimulator::Options options = task_.arena;
  // As SpherusTask::makeWorld: the layout from the seed's low half, the pose from its high half.
  options.seed = static_cast<std::uint32_t>(episodeSeed);
  if (task_.randomPose) options.poseSeed = static_cast<std::uint32_t>(episodeSeed >> 32);
  world_ = std::make_unique<SpherusEpisode>(options, nullptr);
  step_ = 0;
  score_ = task_.fitness(*world_);
}

StepOutcome SpherusEnvironment::step(std::span<const real> action, std::span<real> observation) {
  const std::span<real> effectors = world_->spherus().effectors();
  std::copy_n(action.begin(), effectors.size(), effectors.begin());
  world_->advanceTime();
  ++step_;
  observe(observation);
  const double score = task_.fitness(*world_);
  StepOutcome outcome;
  outcome.reward = score - score_;
  outcome.truncated = step_ >= task_.stepCount;
  score_ = score;
  return outcome;
}

EnvironmentState SpherusEnvironment::saveState() const {
  return {world_->saveState(), seed_, episode_, step_, score_};
}

void SpherusEnvironment::restoreState(const EnvironmentState& state) {
  // The world of the state's episode, built as start() builds it, then put in the state; the
  // environment is unchanged if the state does not fit it.
  const std::uint64_t seed = seed_;
  const std::uint64_t episode = episode_;
  const long step = step_;
  const double score = score_;
  std::unique_ptr<SpherusEpisode> world = std::move(world_);
  seed_ = state.seed;
  episode_ = state.episode;
  try {
    start();
    world_->restoreState(state.world);
  } catch (...) {
    world_ = std::move(world);
    seed_ = seed;
    episode_ = episode;
    step_ = step;
    score_ = score;
    throw;
  }
  step_ = state.step;
  score_ = state.score;
}

void SpherusEnvironment::observe(std::span<real> observation) const {
  const std::span<const real> sensors = world_->spherus().sensors();
  std::copy(sensors.begin(), sensors.end(), observation.begin());
}

}  // namespace thyrix::python
