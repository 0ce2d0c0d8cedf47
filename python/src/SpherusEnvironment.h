#pragma once
/// @file SpherusEnvironment.h
/// @brief The C++ core of thyrix.envs.SpherusEnv: one Spherus episode at a time, driven by
/// actions from outside, rewarded by the increase of SpherusTask's fitness.

#include <SpherusTask.h>
#include <ThyrixLite/WorldState.h>

#include <cstdint>
#include <memory>
#include <span>

namespace thyrix::python {

/// Everything an environment's next step depends on: its episode's world state, and where it
/// is in its stream of episodes and in the episode.
struct EnvironmentState {
  WorldState world;           ///< the episode's simulator
  std::uint64_t seed = 0;     ///< the stream's seed
  std::uint64_t episode = 0;  ///< the episode's index in the stream
  long step = 0;              ///< steps taken in the episode
  double score = 0;           ///< the task's fitness after the last step
};

/// What one step returns besides the observation.
struct StepOutcome {
  double reward = 0;        ///< the increase of the task's fitness over the step
  bool terminated = false;  ///< never: a Spherus episode has no terminal state
  bool truncated = false;   ///< the episode has run its steps
};

/// One Spherus arena at a time, stepped by actions (the 5 effectors) given before each step.
/// Episode k after reset(s) is laid out from `deriveSeed(s, k, 0, 0)`, as SpherusTask lays out
/// an episode from its seed, so episode 0 has the layout (and pose) of trial 0 of individual 0
/// of generation 0 of `evaluate(seed = s)`. The rewards of an episode sum to the task's fitness
/// at its end (the distance covered, or the balls pushed toward the walls).
class SpherusEnvironment {
 public:
  /// @p task gives the goal, the episode length, the arena and whether the pose is random
  /// (its network is not used: the actions come from outside).
  /// @throws InvalidArgument naming "SpherusEnv.steps" unless the length is positive
  explicit SpherusEnvironment(const SpherusTask& task);

  /// Starts episode 0 of the stream seeded by @p seed.
  void reset(std::uint64_t seed);
  /// Starts the stream's next episode.
  void resetNext();
  /// Sets the effectors to @p action (clamped to [0, 1] by the agent), takes a step and
  /// writes the sensors to @p observation. The action must be finite (checked by the caller).
  StepOutcome step(std::span<const real> action, std::span<real> observation);
  /// Writes the current sensors to @p observation.
  void observe(std::span<real> observation) const;
  /// The environment's state (reset() must have been called).
  [[nodiscard]] EnvironmentState saveState() const;
  /// Puts the environment in @p state: the episode's world built again, then restored.
  /// @throws InvalidArgument naming "WorldState" if the state is not of this task's worlds
  void restoreState(const EnvironmentState& state);

  /// The current episode's world (null before the first reset).
  [[nodiscard]] const SpherusEpisode* world() const { return world_.get(); }
  /// Steps taken in the current episode.
  [[nodiscard]] long stepIndex() const { return step_; }
  /// The seed of the current stream.
  [[nodiscard]] std::uint64_t seed() const { return seed_; }
  /// The current episode's index in its stream.
  [[nodiscard]] std::uint64_t episode() const { return episode_; }
  /// The task.
  [[nodiscard]] const SpherusTask& task() const { return task_; }

 private:
  void start();

  SpherusTask task_;
  std::unique_ptr<SpherusEpisode> world_;
  std::uint64_t seed_ = 0;
  std::uint64_t episode_ = 0;
  long step_ = 0;
  double score_ = 0;
};

}  // namespace thyrix::python
