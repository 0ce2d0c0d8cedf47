#include "PeerScenes.h"

#include <Tools/MTRandom.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace thyrix::peers {

double ArenaLayout::linkLength() const {
  const AgentLayout& a = agents.front();
  return std::hypot(a.circle[1].x - a.circle[0].x, a.circle[1].y - a.circle[0].y);
}

namespace {

/// SpherusSimulator's rejection sampling, draw for draw (x then y from one stream), so that
/// the spherus scene has the arena's very balls: keep clear of every agent's reach (half its
/// longest link, its radius and a ball diameter) and 1.5 diameters from every ball placed
/// before.
void placeBalls(ArenaLayout& layout, int balls, std::uint32_t seed) {
  MTRandom random(seed);
  const double r = layout.ballRadius;
  const double maxLinkLength = 1;
  const double clearance = maxLinkLength / 2 + layout.agentRadius + 2 * r;
  const auto near = [](double x, double y, Point q, double distance) {
    return std::hypot(x - q.x, y - q.y) < distance;
  };
  while (static_cast<int>(layout.balls.size()) < balls) {
    const double x = random.uniform(2 * r, layout.size - 2 * r);
    const double y = random.uniform(2 * r, layout.size - 2 * r);
    if (std::any_of(layout.agents.begin(), layout.agents.end(), [&](const AgentLayout& a) {
          const Point middle{(a.circle[0].x + a.circle[1].x) / 2,
                             (a.circle[0].y + a.circle[1].y) / 2};
          return near(x, y, middle, clearance);
        }))
      continue;
    if (std::any_of(layout.balls.begin(), layout.balls.end(),
                    [&](Point q) { return near(x, y, q, 3 * r); }))
      continue;
    layout.balls.push_back({x, y});
  }
}

/// An agent centred at @p middle, 0.6 m long along x.
AgentLayout agentAt(Point middle) {
  return {{{middle.x - 0.3, middle.y}, {middle.x + 0.3, middle.y}}};
}

}  // namespace

ArenaLayout arenaLayout(int balls, std::uint32_t seed) {
  ArenaLayout layout;
  layout.agents.push_back(agentAt({layout.size / 2, layout.size / 2}));
  placeBalls(layout, balls, seed);
  return layout;
}

ArenaLayout crowdLayout(int agents, int balls, double size, std::uint32_t seed) {
  ArenaLayout layout;
  layout.size = size;
  const int columns = std::min(agents, 5);
  const int rows = (agents + columns - 1) / columns;
  for (int k = 0; k < agents; ++k)
    layout.agents.push_back(
        agentAt({size * (k % columns + 0.5) / columns, size * (k / columns + 0.5) / rows}));
  placeBalls(layout, balls, seed);
  return layout;
}

Point arenaPushDirection(const ArenaLayout& layout, long step, std::size_t agent) {
  const double goldenAngle = std::numbers::pi * (3 - std::sqrt(5.0));
  const double turns = static_cast<double>(step / layout.stepsPerTurn + static_cast<long>(agent));
  const double angle = goldenAngle * turns;
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
