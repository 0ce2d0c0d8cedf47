#pragma once
/// @file WorldDrawing.h
/// @brief Drawing a whole simulated world through a GUI, with optional overlays: contact
/// points, normals and forces; and the bounding box of a world, to choose a view.

#include <ThyrixLite/BroadPhase.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/World.h>

namespace thyrix {

/// What drawWorld() draws over the objects. Everything is off by default: the objects alone.
struct DrawOptions {
  /// Each contact point of the last step as a small cross in colors::contact, with a short
  /// line along its normal (from A to B). The marks are sized from the smaller touching shape.
  bool contacts = false;
  /// Each contact force of the last step as a line in colors::contactForce from the contact
  /// point along the normal (the force on B), `force * forceScale` metres long; contacts that
  /// carry no force draw nothing.
  bool contactForces = false;
  /// Length of a contact-force line per newton (m/N).
  real forceScale = real(0.1);
  /// The activation of every tactile sensor: a dot at the middle of its sector, from white
  /// (0) to red (1).
  bool tactile = false;
  /// The central ray of every visual sensor's pixels (PhysicalObject::visualSensors), 1 m
  /// long, from pale to dark cyan with the pixel's activation.
  bool visualRays = false;
};

/// Draws @p world (World::draw: by default every object, in registration order), then the
/// overlays that @p options asks for: the sensors' of its objects, and, when it is a Simulator,
/// the contacts the last step left in `Simulator::contacts` (other worlds have none). Drawing
/// reads the world; it never changes it.
void drawWorld(const World& world, GUI& gui, const DrawOptions& options = {});

/// A box around every object of @p world except borders (which are unbounded), to choose a
/// view: the union of the objects' bounding boxes, padded on every side by 5% of its larger
/// extent. With nothing bounded to show it is the 10 x 10 box [0, 10] x [0, 10].
///
/// The boxes are computed from the primitives' current poses (circle: centre +- radius;
/// capsule: end-cap centres +- radius; a part of a composed body placed from its owner), which
/// is what the simulator stores in `boxMin` and `boxMax` at each step, but is also right before
/// the first step and for a World that never steps. Primitives with non-finite coordinates are
/// left out.
[[nodiscard]] BoundingBox worldBounds(const World& world);

}  // namespace thyrix
