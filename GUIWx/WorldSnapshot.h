#pragma once
/// @file WorldSnapshot.h
/// @brief A copy of what the view shows of a world at one step: the drawing, the shapes that
/// can be grabbed, the counters and the agent's activity. The window draws only from snapshots,
/// never from a world being stepped.

#include <GUIWx/DrawingRecorder.h>

#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/ContactSolver.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/World.h>
#include <ThyrixLite/WorldDrawing.h>

#include <cstdint>
#include <string>
#include <vector>

namespace thyrix {

/// A circle or capsule of a movable object, where it was at the snapshot, for picking with the
/// mouse. A circle has `a == b`; a capsule is the segment `a`-`b` swept by `radius`.
struct PickShape {
  ShapeType type = ShapeType::Circle;  ///< Circle or Capsule
  Vector2 a;                           ///< circle centre, or one end of the capsule's segment
  Vector2 b;                           ///< circle centre, or the other end
  real radius = 0;                     ///< radius (m)
  std::uint32_t object = 0;            ///< index of the object in Simulator::objects
};

/// What the simulation thread publishes after a step (WorldSnapshot::capture plus the runner's
/// counters). A snapshot is immutable once published: readers share it through a
/// `shared_ptr<const WorldSnapshot>`.
struct WorldSnapshot {
  /// The drawing calls of drawWorld() with the options in force.
  DrawingRecorder drawing;
  /// The circles and capsules of the movable objects, in registration order (later ones are
  /// drawn on top); none when the world is not a Simulator (nothing can be dragged).
  std::vector<PickShape> shapes;
  /// The box the view fits: worldBounds() of the world, widened to take in each border's
  /// anchor point (so the walls of an arena show).
  BoundingBox bounds;
  /// Which world this is: 1 for the first, one more at each reset. A drag names the world it
  /// grabbed in, so a command meant for an old world is ignored.
  std::uint64_t generation = 0;
  /// Publication number, one more per snapshot.
  std::uint64_t serial = 0;
  /// Whether the world is a Simulator (objects can be dragged, contacts are counted and drawn).
  bool isSimulator = false;
  /// Steps done (World::stepCount).
  std::uint64_t step = 0;
  /// Simulated time (s).
  double time = 0;
  /// Contacts of the last step (0 for a world that is not a Simulator).
  std::size_t contacts = 0;
  /// Steps per second actually simulated recently (0 while paused).
  double stepsPerSecond = 0;
  /// Whether the simulation thread is stepping.
  bool running = false;
  /// The contact solver in use.
  ContactSolverKind solver = ContactSolverKind::Baraff;
  /// The agent's sensor activations (SimulationSetup::agentSignals), empty without an agent.
  std::vector<real> sensors;
  /// The agent's effector activations, empty without an agent.
  std::vector<real> effectors;
  /// Whether an object is being dragged; then the grabbed point and the mouse target (m).
  bool dragging = false;
  Vector2 dragPoint;   ///< the grabbed point of the dragged body, world coordinates
  Vector2 dragTarget;  ///< where the mouse pulls it, world coordinates
  /// Why there is no world or the run stopped (an exception from the factory or a step).
  std::string error;

  /// Fills drawing, shapes, bounds, step, time, contacts and solver from @p world (shapes,
  /// contacts and solver only when it is a Simulator), reusing the memory of an earlier
  /// capture. Reads the world only.
  void capture(const World& world, const DrawOptions& options);
  /// Empties the world part (no world: drawing, shapes, counters).
  void clearWorld();
};

}  // namespace thyrix
