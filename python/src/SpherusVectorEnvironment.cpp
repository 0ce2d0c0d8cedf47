#include "SpherusVectorEnvironment.h"

#include <Agents/Spherus.h>
#include <ThyrixLite/InvalidArgument.h>

namespace thyrix::python {

namespace {

constexpr std::size_t actionSize = Spherus::effectorCount;
constexpr std::size_t observationSize = Spherus::sensorCount;

std::size_t checkedThreads(std::size_t threads) {
  if (threads == 0) throw InvalidArgument("SpherusVectorEnv.threads", "must be at least 1 (got 0)");
  return threads;
}

}  // namespace

SpherusVectorEnvironment::SpherusVectorEnvironment(std::size_t count, std::size_t threads,
                                                   const SpherusTask& task)
    : pool_(checkedThreads(threads)) {
  if (count == 0) throw InvalidArgument("SpherusVectorEnv.num_envs", "must be at least 1 (got 0)");
  environments_.reserve(count);
  for (std::size_t i = 0; i < count; ++i) environments_.emplace_back(task);
}

void SpherusVectorEnvironment::reset(std::uint64_t seed, std::span<real> observations) {
  pool_.forEach(environments_.size(), [&](std::size_t i) {
    environments_[i].reset(seed + i);
    environments_[i].observe(observations.subspan(i * observationSize, observationSize));
  });
}

void SpherusVectorEnvironment::resetNext(std::span<real> observations) {
  pool_.forEach(environments_.size(), [&](std::size_t i) {
    environments_[i].resetNext();
    environments_[i].observe(observations.subspan(i * observationSize, observationSize));
  });
}

void SpherusVectorEnvironment::step(std::span<const real> actions, std::span<real> observations,
                                    std::span<double> rewards, std::span<bool> terminated,
                                    std::span<bool> truncated, std::span<real> finalObservations) {
  pool_.forEach(environments_.size(), [&](std::size_t i) {
    SpherusEnvironment& environment = environments_[i];
    const std::span<real> observation = observations.subspan(i * observationSize, observationSize);
    const StepOutcome outcome =
        environment.step(actions.subspan(i * actionSize, actionSize), observation);
    rewards[i] = outcome.reward;
    terminated[i] = outcome.terminated;
    truncated[i] = outcome.truncated;
    if (outcome.terminated || outcome.truncated) {
      std::copy(observation.begin(), observation.end(),
                finalObservations.begin() + static_cast<std::ptrdiff_t>(i * observationSize));
      environment.resetNext();
      environment.observe(observation);
    }
  });
}

}  // namespace thyrix::python
