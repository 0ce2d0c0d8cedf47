#pragma once
/// @file IunctusSimulator.h
/// @brief The Iunctus arena: walls, one Iunctus and circular objects to catch.

#include <Agents/Iunctus.h>
#include <Agents/IunctusGrasper.h>

#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// A square walled arena with one Iunctus left of the centre, facing +x (limb open), and
/// circles placed without overlap: the first 1.5 m straight ahead of the base's centre, so a
/// scripted grasp finds it at once; the others at random, clear of the agent and of each other.
/// The same options give the same world.
class IunctusSimulator : public Simulator {
 public:
  /// How the arena is made.
  struct Options {
    int objects = 1;                ///< circles to catch
    real objectRadius = real(0.2);  ///< their radius (m)
    real size = 8;                  ///< side of the arena (m)
    std::uint32_t seed = 1;         ///< layout seed
    real timestep = real(0.01);     ///< s
  };

  /// @throws InvalidArgument naming "IunctusSimulator.objects" (negative or more than fit) or
  /// "IunctusSimulator.size" (too small for the agent and the first object)
  IunctusSimulator(const Options& options, std::unique_ptr<Controller> controller);

  /// Contacts the buffers are sized for at construction.
  static constexpr std::size_t contactCapacity = 32;

  /// Replaces the agent's controller with the scripted grasper, which catches the first object
  /// and carries it @p carryDistance (m), and returns it (owned by the agent).
  /// @throws InvalidArgument naming "IunctusSimulator.objects" when there is no object
  IunctusGrasper& useGrasper(real carryDistance = 2);

  /// The agent.
  [[nodiscard]] Iunctus& iunctus() const { return *iunctus_; }
  /// The circles, the first one ahead of the agent.
  [[nodiscard]] const std::vector<Circle*>& objectsToCatch() const { return objects_; }

 private:
  Iunctus* iunctus_;
  std::vector<Circle*> objects_;
};

}  // namespace thyrix
