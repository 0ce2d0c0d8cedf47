#pragma once
/// @file SpherusTask.h
/// @brief Spherus's evolution tasks (ground covered, balls pushed to the walls) as a Task for
/// thyrix::evaluate().

#include <Agents/SpherusSimulator.h>
#include <Controller/NeuralNetwork.h>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace thyrix {

/// What a Spherus is rewarded for.
enum class SpherusGoal {
  Distance,  ///< the straight distance from its start to its end (m)
  Clear      ///< how far the balls were pushed toward the walls, summed (m)
};

/// "distance" or "clear". @throws std::invalid_argument naming --task otherwise
SpherusGoal parseSpherusGoal(std::string_view text);
/// "distance" or "clear".
std::string_view toString(SpherusGoal goal);

/// One episode: a SpherusSimulator that remembers where the agent and the balls started.
class SpherusEpisode : public SpherusSimulator {
 public:
  /// The arena of @p options driven by @p controller; the starts are noted.
  SpherusEpisode(const Options& options, std::unique_ptr<Controller> controller);
  /// The agent's centre at the start.
  [[nodiscard]] Vector2 start() const { return start_; }
  /// The balls' centres at the start, in obstacles() order.
  [[nodiscard]] const std::vector<Vector2>& ballStarts() const { return ballStarts_; }

 private:
  Vector2 start_;
  std::vector<Vector2> ballStarts_;
};

/// A Task (Evolution/Evaluate.h) over parameter vectors of a NeuralController: each episode is
/// a SpherusEpisode whose layout (and, with randomPose, the agent's start) is seeded by the
/// episode's seed, run for `steps` steps.
struct SpherusTask {
  SpherusGoal goal = SpherusGoal::Distance;  ///< what the fitness measures
  NetworkSpec network;                       ///< the controller's network (35 in, 5 out)
  long stepCount = 1000;                     ///< steps of an episode
  SpherusSimulator::Options arena;           ///< the arena (its seeds are the episode's)
  bool randomPose = true;  ///< start the agent at a pose drawn from the episode's seed

  /// The episode's length.
  [[nodiscard]] long steps() const { return stepCount; }
  /// A fresh episode driven by @p parameters (network's order), laid out from @p seed.
  /// @throws InvalidArgument naming "NeuralController.parameters" (count or non-finite)
  [[nodiscard]] std::unique_ptr<SpherusEpisode> makeWorld(const std::vector<double>& parameters,
                                                          std::uint64_t seed) const;
  /// Distance: |end - start| of the agent's centre. Clear: the sum over balls of the decrease
  /// of the gap between the ball's edge and its nearest wall.
  [[nodiscard]] double fitness(const SpherusEpisode& episode) const;
};

/// Parses "ff:H1[,H2...]" (a feed-forward network with these hidden layers), "ff" (no hidden
/// layer) or "ctrnn:N" (a CTRNN of N neurons), with tanh units, for Spherus's 35 sensors and
/// 5 effectors. @throws std::invalid_argument naming --network
NetworkSpec parseSpherusNetwork(std::string_view text);

}  // namespace thyrix
