#include "PeerScenes.h"

#include <Tools/MTRandom.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace thyrix::peers {

double ArenaLayout::linkLength() const {
  return std::hypot(agent[1].x - agent[0].x, agent[1].y - agent[0].y);
}

ArenaLayout arenaLayout(int balls, std::uint32_t seed) {
  ArenaLayout layout;
  const double middle = layout.size / 2;
  layout.agent[0] = {middle - 0.3, middle};
  layout.agent[1] = {middle + 0.3, middle};
  // SpherusSimulator's rejection sampling, draw for draw (x then y from one stream), so that
  // the spherus scene has these very balls: keep clear of the agent's reach (half its longest
  // link, its radius and a ball diameter) and 1.5 diameters from every ball placed before.
  MTRandom random(seed);
  const double r = layout.ballRadius;
  const double maxLinkLength = 1;
  const double clearance = maxLinkLength / 2 + layout.agentRadius + 2 * r;
  while (static_cast<int>(layout.balls.size()) < balls) {
    const double x = random.uniform(2 * r, layout.size - 2 * r);
    const double y = random.uniform(2 * r, layout.size - 2 * r);
    if (std::hypot(x - middle, y - middle) < clearance) continue;
    if (std::any_of(layout.balls.begin(), layout.balls.end(),
                    [&](Point q) { return std::hypot(x - q.x, y - q.y) < 3 * r; }))
      continue;
    layout.balls.push_back({x, y});
  }
  return layout;
}

Point arenaPushDirection(const ArenaLayout& layout, long step) {
  const double goldenAngle = std::numbers::pi * (3 - std::sqrt(5.0));
  const double angle = goldenAngle * static_cast<double>(step / layout.stepsPerTurn);
  return {std::cos(angle), std::sin(angle)};
}

PileLayout pileLayout(int count, std::uint32_t seed) {
  // scenes::addPile's rule, draw for draw.
  PileLayout layout;
  MTRandom random(seed);
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const double pitch = 1.2;
  layout.width = pitch * columns + 0.2;
  layout.circles.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const int row = i / columns;
    const int column = i % columns;
    const double x = pitch * (column + 0.5) + random.uniform(-0.1, 0.1);
    const double y = layout.radius + pitch * row;
    layout.circles.push_back({x, y});
    layout.top = std::max(layout.top, y + layout.radius);
  }
  return layout;
}

double largestPenetration(const PileLayout& layout, std::span<const Point> centres) {
  const double r = layout.radius;
  double deepest = 0;
  // Walls: the floor and the two sides.
  for (const Point c : centres)
    deepest = std::max({deepest, r - c.y, r - (c.x - layout.leftWall), r - (layout.width - c.x)});
  // Circle pairs, through a grid of cells one diameter wide: overlapping circles are in the
  // same or neighbouring cells.
  const double cell = 2 * r;
  const auto key = [](long ix, long iy) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) |
           static_cast<std::uint32_t>(iy);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < centres.size(); ++i)
    grid[key(std::lround(std::floor(centres[i].x / cell)),
             std::lround(std::floor(centres[i].y / cell)))]
        .push_back(i);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const long ix = std::lround(std::floor(centres[i].x / cell));
    const long iy = std::lround(std::floor(centres[i].y / cell));
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto found = grid.find(key(ix + dx, iy + dy));
        if (found == grid.end()) continue;
        for (const std::size_t j : found->second)
          if (j > i)
            deepest = std::max(deepest, 2 * r - std::hypot(centres[i].x - centres[j].x,
                                                           centres[i].y - centres[j].y));
      }
  }
  return deepest;
}

double ChainLayout::inertia() const {
  const double length = 2 * halfLength + 2 * radius;
  const double width = 2 * radius;
  return peerMass * (length * length + width * width) / 12;
}

ChainLayout chainLayout(int links) {
  ChainLayout layout;
  layout.links = links;
  return layout;
}

}  // namespace thyrix::peers
