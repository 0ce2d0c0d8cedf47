#pragma once
/// @file PeerScenes.h
/// @brief The scenes of the peer comparison (issue 7) as plain data, shared by the Thyrix,
/// Box2D and Chipmunk versions so that all three start from the same layout, and the
/// engine-neutral measures taken on their results (hashes, penetration).
///
/// Units: metres, seconds, kilograms for the peers. Peers simulate Newtonian bodies with
/// linear and angular damping `peerDamping`; Thyrix bodies get the quasistatic mass
/// `peerDamping x (peer mass)`, so that a force F moves a body at F / (m c) in every engine.

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace thyrix::peers {

/// A point or a vector, in double whatever the engines use inside.
struct Point {
  double x = 0;
  double y = 0;
};

/// Linear and angular damping of the peers' bodies (1/s).
inline constexpr double peerDamping = 10;
/// Mass of every dynamic body of the peers (kg). Thyrix bodies get peerDamping times this, the
/// quasistatic mass 1 of Thyrix's own scenes (SpherusSimulator, scenes::addPile): a force of
/// 1 N then moves a body at 1 m/s in every engine, Spherus's full speed. (With 1 kg the arena
/// agent would crawl at 0.1 m/s, and the golden-angle pushes would keep it within about 1 m
/// of its start, touching nothing in 100000 steps.)
inline constexpr double peerMass = 0.1;
/// Quasistatic mass of a Thyrix body standing for a peer body of peerMass (N s/m).
inline constexpr double thyrixMass = peerDamping * peerMass;

/// The agent of the arena scenes: two circles joined at a distance (Spherus's body).
struct AgentLayout {
  Point circle[2];  ///< centres of the two circles
};

/// arena: a walled square arena (10 x 10 m), agents of two circles joined at a distance, and
/// balls. With one agent, the layout is the one SpherusSimulator builds from the same seed, so
/// the arena and the spherus scenes differ only by Spherus's sensors and controller.
struct ArenaLayout {
  double size = 10;                 ///< side of the arena; walls at 0 and size
  double agentRadius = 0.25;        ///< radius of each agent circle
  std::vector<AgentLayout> agents;  ///< the agents, each 0.6 m long along x
  double ballRadius = 0.2;          ///< radius of the balls
  std::vector<Point> balls;         ///< centres of the balls
  double timestep = 0.01;           ///< s
  double pushForce = 1;             ///< force on each agent circle (N)
  long stepsPerTurn = 1000;         ///< the push turns by the golden angle this often
  /// Distance between an agent's circles' centres (the rest length of the joint or link).
  [[nodiscard]] double linkLength() const;
};

/// The arena of SpherusSimulator for @p seed (1 in the benchmarks): one agent at (4.7, 5) and
/// (5.3, 5), @p balls balls placed at random without overlap by SpherusSimulator's rule.
ArenaLayout arenaLayout(int balls, std::uint32_t seed);

/// crowd (issue 27): @p agents agents and @p balls balls in a walled arena of side @p size.
/// The agents sit at the centres of a grid of cells (5 columns), the balls are placed by
/// arenaLayout's rule, clear of every agent.
ArenaLayout crowdLayout(int agents, int balls, double size, std::uint32_t seed);

/// The direction of the push on agent @p agent at step @p step: +x turned by @p agent golden
/// angles, then by one more every `stepsPerTurn` steps (so it never repeats, sweeps every
/// direction, and the agents of a crowd head different ways).
Point arenaPushDirection(const ArenaLayout& layout, long step, std::size_t agent);

/// The push directions of arenaPushDirection, step after step, computed only when the push
/// turns: the harness's own trigonometry is not what the engines are timed for (per step, it
/// was 4% of Thyrix's arena step).
class ArenaPush {
 public:
  explicit ArenaPush(const ArenaLayout& layout)
      : layout_(layout), directions_(layout.agents.size()) {}
  /// Moves on to the next step (the first at the first call): direction() is then its pushes.
  void next() {
    if (step_ % layout_.stepsPerTurn == 0)
      for (std::size_t k = 0; k < directions_.size(); ++k)
        directions_[k] = arenaPushDirection(layout_, step_, k);
    ++step_;
  }
  /// The direction of the push on agent @p agent at this step.
  [[nodiscard]] Point direction(std::size_t agent) const { return directions_[agent]; }

 private:
  ArenaLayout layout_;
  long step_ = 0;
  std::vector<Point> directions_;
};

/// pileN: circles of radius 0.5 in a grid of ceil(sqrt N) columns at pitch 1.2 with x jitter
/// +-0.1, in an open box (floor y = 0, walls x = -0.1 and x = width), pushed down by g = 10.
/// The same rule as scenes::addPile, so the Thyrix core benchmarks build the same piles.
struct PileLayout {
  double radius = 0.5;           ///< radius of every circle
  double width = 0;              ///< the right wall's x; the left wall is at x = -0.1
  double leftWall = -0.1;        ///< the left wall's x
  double top = 0;                ///< highest circle top at the start (for the peers' walls)
  std::vector<Point> circles;    ///< centres, row by row from the floor up
  double gravity = 10;           ///< m/s^2, downward
  double timestep = 1.0 / 60.0;  ///< s
};

/// The pile of @p count circles for @p seed.
PileLayout pileLayout(int count, std::uint32_t seed);

/// The largest penetration in a pile state (circle-circle and circle-wall), in metres, from
/// the centres alone: one measure, the same for every engine.
double largestPenetration(const PileLayout& layout, std::span<const Point> centres);

/// chainN: N capsules of half length 0.5 and radius 0.125 laid along x, capsule i centred at
/// (i + 0.5, 0); revolute joint i at (i, 0) joins capsule i - 1 (the ground for i = 0) to
/// capsule i; neighbours do not collide; weight g = 10 downward.
struct ChainLayout {
  int links = 0;                 ///< number of capsules
  double halfLength = 0.5;       ///< half the distance between a capsule's cap centres
  double radius = 0.125;         ///< capsule radius
  double gravity = 10;           ///< m/s^2, downward
  double timestep = 1.0 / 60.0;  ///< s
  /// Moment of inertia of a capsule of peerMass about its centre, the same in both peers:
  /// Chipmunk's cpMomentForSegment rule (a box of the capsule's full length and width).
  [[nodiscard]] double inertia() const;
  /// Centre of capsule @p i.
  [[nodiscard]] Point centre(int i) const { return {2 * halfLength * i + halfLength, 0}; }
  /// Joint @p i, between capsule i - 1 (or the ground) and capsule i.
  [[nodiscard]] Point joint(int i) const { return {2 * halfLength * i, 0}; }
};

/// The chain of @p links capsules.
ChainLayout chainLayout(int links);

/// FNV-1a over the bits of the values mixed in: equal hashes mean bit-identical states (of
/// one engine; engines are not expected to agree bit for bit).
class StateHash {
 public:
  template <class T>
  void mix(T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (const unsigned char byte : bytes) {
      hash_ ^= byte;
      hash_ *= 1099511628211ull;
    }
  }
  [[nodiscard]] std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

/// The 64-bit hash folded to 32 bits, exact in a double (a Google Benchmark counter).
inline double hashCounter(std::uint64_t hash) {
  return static_cast<double>((hash ^ (hash >> 32)) & 0xffffffffull);
}

}  // namespace thyrix::peers
