#pragma once
/// @file SpherusVectorEnvironment.h
/// @brief The C++ core of thyrix.envs.SpherusVectorEnv: several SpherusEnvironments stepped
/// together on a thread pool, with autoreset.

#include "SpherusEnvironment.h"

#include <Evolution/ThreadPool.h>

#include <cstdint>
#include <span>
#include <vector>

namespace thyrix::python {

/// `count` SpherusEnvironments; world i is reset with seed `s + i` by reset(s), so it follows
/// the trajectory of a single environment reset with that seed, whatever the threads. An
/// episode that ends in step() is reset at once to its stream's next episode (autoreset); the
/// step then returns the new episode's first observation and keeps the last one apart.
class SpherusVectorEnvironment {
 public:
  /// @throws InvalidArgument naming "SpherusVectorEnv.num_envs" (0) or
  ///         "SpherusVectorEnv.threads" (0), or as SpherusEnvironment
  SpherusVectorEnvironment(std::size_t count, std::size_t threads, const SpherusTask& task);

  /// Worlds.
  [[nodiscard]] std::size_t size() const { return environments_.size(); }
  /// Threads stepping them, the caller's included.
  [[nodiscard]] std::size_t threadCount() const { return pool_.threadCount(); }

  /// Resets world i with seed `seed + i` and writes the observations (count x 35).
  void reset(std::uint64_t seed, std::span<real> observations);

  /// Starts every world's next episode in its stream and writes the observations.
  void resetNext(std::span<real> observations);

  /// One step of every world: row i of @p actions (count x 5, finite) drives world i.
  /// Writes the observations (count x 35), rewards, terminated and truncated flags (count
  /// each) and, for each world whose episode ended, its last observation into row i of
  /// @p finalObservations (other rows untouched). Call without the GIL: nothing here touches
  /// Python.
  void step(std::span<const real> actions, std::span<real> observations, std::span<double> rewards,
            std::span<bool> terminated, std::span<bool> truncated,
            std::span<real> finalObservations);

  /// World i's environment.
  [[nodiscard]] const SpherusEnvironment& environment(std::size_t i) const {
    return environments_[i];
  }

 private:
  std::vector<SpherusEnvironment> environments_;
  ThreadPool pool_;
};

}  // namespace thyrix::python
