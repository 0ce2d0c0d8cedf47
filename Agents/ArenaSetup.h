#pragma once
/// @file ArenaSetup.h
/// @brief What the example simulators' arenas share: four walls, and objects scattered at
/// random without overlap.

#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace thyrix {

/// Registers four borders enclosing the square [0, size] x [0, size], normals inward.
void addArenaWalls(Simulator& simulator, real size);

/// Rejection sampling in the square arena of @p size: appends to @p placed points for circles
/// of radius @p radius until it holds @p count, each at least 2 radius from the walls, 3 radius
/// (a gap of one radius) from every point before it, and where @p keptOut(p) is false.
/// @throws InvalidArgument naming @p field, before any draw, when more circles are asked
/// for than the arena's area can hold at that spacing, or when 1000 (count + 1) draws did not
/// fit them.
template <class KeptOut>
void scatterPoints(MTRandom& random, std::vector<Vector2>& placed, int count, real radius,
                   real size, KeptOut&& keptOut, std::string_view field) {
  // Centres 3 radii apart: disks of 1.5 radii around them do not overlap and lie in the square
  // of side size - radius, so that area bounds the count (a search would take long to fail).
  const double side = std::max(0.0, static_cast<double>(size) - static_cast<double>(radius));
  const auto most = static_cast<long long>(side * side / (2.25 * pi<double> * radius * radius));
  if (count > most)
    throw InvalidArgument(std::string(field), "do not fit in the arena (at most " +
                                                  std::to_string(most) + " at this spacing)");
  int attempts = 0;
  while (static_cast<int>(placed.size()) < count) {
    if (++attempts > 1000 * (count + 1))
      throw InvalidArgument(std::string(field), "do not fit in the arena");
    const Vector2 p{static_cast<real>(random.uniform(2 * radius, size - 2 * radius)),
                    static_cast<real>(random.uniform(2 * radius, size - 2 * radius))};
    if (keptOut(p)) continue;
    if (std::any_of(placed.begin(), placed.end(),
                    [&](Vector2 q) { return distance(p, q) < 3 * radius; }))
      continue;
    placed.push_back(p);
  }
}

}  // namespace thyrix
