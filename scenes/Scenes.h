#pragma once
/// @file Scenes.h
/// @brief Scenes shared by the tests, the benchmarks and the demos, so all three exercise the
/// same worlds. Every scene is built from an explicit seed and is reproducible.

#include <ThyrixLite/Simulator.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace thyrix::scenes {

/// Adds four borders enclosing the box [0, width] x [0, height], normals inward.
void addWalls(Simulator& simulator, real width, real height);

/// A square arena of @p size with @p count circles of radius @p radius placed at random
/// without overlap (a fixed seed gives a fixed layout). Returns the circles.
std::vector<PhysicalObject*> addRandomCircles(Simulator& simulator, int count, real radius,
                                              real size, std::uint32_t seed);

/// A pile: @p count circles of radius 0.5 in a grid of @p columns columns (0: ceil(sqrt count))
/// at pitch 1.2 with x jitter +-0.1, inside an open box (floor at y = 0 and two walls).
/// Returns the circles.
std::vector<PhysicalObject*> addPile(Simulator& simulator, int count, std::uint32_t seed,
                                     int columns = 0);

/// A mixed pile of circles and capsules for solver tests: @p count bodies jammed into the
/// corner of a box, overlapping slightly at random. Returns the bodies.
std::vector<PhysicalObject*> addMixedPile(Simulator& simulator, int count, std::uint32_t seed);

/// Pushes every body of @p bodies with @p force (call before each step).
void push(const std::vector<PhysicalObject*>& bodies, Vector2 force);

/// An FNV-1a hash of every object's position, angle and velocity bits: equal hashes mean
/// bit-identical states.
std::uint64_t stateHash(const Simulator& simulator);

/// The largest overlap among this step's contacts (0 if none overlap).
real largestOverlap(const Simulator& simulator);

}  // namespace thyrix::scenes
