#include <ThyrixLite/GaussSeidelSolver.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace thyrix {
namespace {

constexpr std::uint32_t noBody = ~std::uint32_t{0};

/// Where the island's row @p p goes among its @p n local rows. Rows come in detection order,
/// where a body's contacts follow one another; then every row would wait for the previous
/// one's velocity update (a sweep is latency-bound). Each block of 32 rows is taken as four
/// streams of 8 in turn (0, 8, 16, 24, 1, 9, ...): a row then seldom shares a body with the
/// three before it, and rows overlap in the processor, while the order stays nearly the same,
/// and so does the convergence. A fixed pattern rather than a search for conflict-free rows:
/// no unpredictable branch. Measured on piles of 1000 and 10000 circles: sweeps about 25%
/// faster with two streams than without, pile1000 5% faster again with four; the largest
/// overlap over 8 seeds and both solvers 0.96% of the radius (two streams: 1.14%).
std::size_t interleaved(std::size_t p, std::size_t n) {
  constexpr std::size_t streams = 4;
  constexpr std::size_t stream = 8;  // rows per stream and block
  constexpr std::size_t block = streams * stream;
  if (p >= n / block * block) return p;  // the last, partial block keeps its order
  const std::size_t start = p / block * block;
  const std::size_t j = p - start;
  return start + j % stream * streams + j / stream;
}

}  // namespace

void GaussSeidelSolver::reserve(std::size_t bodies, std::size_t rows) {
  for (auto* buffer : {&forces_, &changes_, &direction_}) buffer->reserve(rows);
  rows_.reserve(rows);
  turning_.reserve(rows);
  // Each row may bring two bodies of its own (a fixed body gets one copy per row).
  bodies_.reserve(2 * rows);
  globalBody_.reserve(2 * rows);
  localBody_.reserve(bodies);
}

int GaussSeidelSolver::solve(std::span<const std::uint32_t> island,
                             std::span<ContactConstraint> rows, std::span<SolverBody> bodies,
                             const ContactSolverSettings& settings) {
  gather(island, rows, bodies, settings.relaxation);
  const bool accelerate = settings.accelerateGaussSeidel;
  if (accelerate) {
    // resize, not assign: assign would reallocate to the exact size at each new largest
    // island (a growing pile: nearly every step), resize grows geometrically.
    direction_.resize(rows_.size());
    std::fill(direction_.begin(), direction_.end(), real(0));
  }
  real lastNorm = 0;  // squared norm of the previous sweep's change
  int sweeps = 0;
  while (sweeps < settings.gaussSeidelMaxIterations) {
    ++sweeps;
    // Symmetric Gauss-Seidel: alternate sweep directions, so that a correction travels through
    // a long chain of contacts both ways (the weight down, the floor's reaction up).
    const bool backward = sweeps % 2 == 0;
    const SweepResult result = turningIsland_
                                   ? (backward ? sweep<true, true>() : sweep<false, true>())
                                   : (backward ? sweep<true, false>() : sweep<false, false>());
    if (result.largestChange <= settings.gaussSeidelTolerance) break;
    // The last sweep is not followed by a conjugate step: the result is a projected sweep's.
    if (!accelerate || sweeps == settings.gaussSeidelMaxIterations) continue;
    if (lastNorm > 0 && result.squaredNorm <= lastNorm) {
      const real beta = result.squaredNorm / lastNorm;
      turningIsland_ ? conjugateStep<true>(beta) : conjugateStep<false>(beta);
    } else {  // first sweep, or the change grew: restart along the change itself
      std::copy(changes_.begin(), changes_.end(), direction_.begin());
    }
    lastNorm = result.squaredNorm;
  }
  scatter(island, rows, bodies);
  return sweeps;
}

void GaussSeidelSolver::gather(std::span<const std::uint32_t> island,
                               std::span<const ContactConstraint> rows,
                               std::span<const SolverBody> bodies, real relaxation) {
  const std::size_t n = island.size();
  if (localBody_.size() < bodies.size()) localBody_.resize(bodies.size(), noBody);
  // Each row brings at most two bodies: the local arrays are sized once, then filled through
  // plain pointers (one pass, no growth checks).
  if (bodies_.size() < 2 * n) {
    bodies_.resize(2 * n);
    globalBody_.resize(2 * n);
  }
  rows_.resize(n);
  turning_.resize(n);
  forces_.resize(n);
  changes_.resize(n);
  Body* const local = bodies_.data();
  std::uint32_t* const global = globalBody_.data();
  std::uint32_t* const localOf = localBody_.data();
  std::uint32_t used = 0;
  const auto localIndex = [&](std::uint32_t body, const SolverBody& b) {
    // A body that cannot move gets a private copy in each row: rows that share only a wall
    // then do not wait on each other's (null) updates of its velocity.
    if (b.inverseMass == 0 && b.inverseInertia == 0) {
      local[used] = {b.v, b.omega};
      global[used] = noBody;
      return used++;
    }
    std::uint32_t index = localOf[body];
    if (index == noBody) {
      index = used++;
      localOf[body] = index;
      local[index] = {b.v, b.omega};
      global[index] = body;
    }
    return index;
  };
  // A lever arm matters if its body turns or can be turned (a fixed wall's does not).
  const auto turns = [](real arm, const SolverBody& body) {
    return arm != 0 && (body.inverseInertia != 0 || body.omega != 0);
  };
  bool turning = false;
  for (std::size_t p = 0; p < n; ++p) {
    const ContactConstraint& c = rows[island[p]];
    const std::size_t q = interleaved(p, n);
    const SolverBody& bodyA = bodies[c.a];
    const SolverBody& bodyB = bodies[c.b];
    const real response = c.selfResponse(bodyA, bodyB);
    // A row nothing can move along takes no force (its zero diagonal would poison the island).
    const real inverseScaled = response > 0 ? relaxation / response : 0;
    const std::uint32_t a = localIndex(c.a, bodyA);
    const std::uint32_t b = localIndex(c.b, bodyB);
    // The starting force's velocities, added here in island order (no pass of its own), by
    // ContactConstraint::applyImpulse's formula written for the local bodies (same bits).
    const real force = c.force;
    local[a].v -= c.normal * (force * bodyA.inverseMass);
    local[a].omega -= c.armA * force * bodyA.inverseInertia;
    local[b].v += c.normal * (force * bodyB.inverseMass);
    local[b].omega += c.armB * force * bodyB.inverseInertia;
    rows_[q] = {a,
                b,
                c.normal * bodyA.inverseMass,
                c.normal * bodyB.inverseMass,
                c.normal * inverseScaled,
                c.target * inverseScaled,
                response};
    // Kept for every row, read only if one of them turns.
    turning_[q] = {c.armA * inverseScaled, c.armB * inverseScaled, -c.armA * bodyA.inverseInertia,
                   c.armB * bodyB.inverseInertia};
    turning = turning || turns(c.armA, bodyA) || turns(c.armB, bodyB);
    forces_[q] = force;
  }
  turningIsland_ = turning;
  bodyCount_ = used;
}

template <bool turning>
void GaussSeidelSolver::apply(std::size_t p, real change) {
  const Row& row = rows_[p];
  Body& bodyA = bodies_[row.a];
  Body& bodyB = bodies_[row.b];
  bodyA.v -= row.pushA * change;
  bodyB.v += row.pushB * change;
  if constexpr (turning) {
    bodyA.omega += turning_[p].turnA * change;
    bodyB.omega += turning_[p].turnB * change;
  }
}

template <bool backward, bool turning>
GaussSeidelSolver::SweepResult GaussSeidelSolver::sweep() {
  SweepResult result;
  const std::size_t n = rows_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = backward ? n - 1 - i : i;
    const Row& row = rows_[p];
    Body& bodyA = bodies_[row.a];
    Body& bodyB = bodies_[row.b];
    const real force = forces_[p];
    const real start = force + row.scaledTarget;
    // The normal velocity w times relaxation / A_kk, a force.
    real scaledVelocity = dot(row.scaledNormal, bodyB.v - bodyA.v);
    if constexpr (turning)
      scaledVelocity += turning_[p].scaledArmB * bodyB.omega - turning_[p].scaledArmA * bodyA.omega;
    // The new force max(0, start - scaledVelocity) is start - min(start, scaledVelocity): the
    // accumulated force is clamped, not the increment. No test for a zero change: the branch
    // would be unpredictable, and adding zero is cheaper than a mispredicted jump.
    const real reached = std::min(start, scaledVelocity);
    const real newForce = start - reached;
    const real change = newForce - force;  // exact when close to the force (Sterbenz)
    // In double the velocities follow scaledTarget - reached, the same change but for
    // roundings, computed without waiting for the new force: the chain velocity -> min ->
    // velocity, on which a row sharing a body waits, is one subtraction shorter (2% of a
    // pile's step). Its roundings add up over many sweeps, to 4e-12 of the velocities after
    // 2000; in float that would be 6e-4, so float follows the change itself.
    apply<turning>(p, std::is_same_v<real, double> ? row.scaledTarget - reached : change);
    forces_[p] = newForce;
    changes_[p] = change;
    result.largestChange = std::max(result.largestChange, std::abs(change) * row.response);
    result.squaredNorm += change * change;
  }
  return result;
}

template <bool turning>
void GaussSeidelSolver::conjugateStep(real beta) {
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    const real step = beta * direction_[p];
    direction_[p] = step + changes_[p];
    // The forces stay feasible (the next sweep would project them anyway), and the velocities
    // follow them. Written as the change max(step, -f), the clamp compiles without a branch
    // (max(0, f + step) did not, and mispredicted on rows at the bound).
    const real change = std::max(step, -forces_[p]);
    forces_[p] += change;
    apply<turning>(p, change);
  }
}

void GaussSeidelSolver::scatter(std::span<const std::uint32_t> island,
                                std::span<ContactConstraint> rows, std::span<SolverBody> bodies) {
  for (std::size_t p = 0; p < island.size(); ++p)
    rows[island[p]].force = forces_[interleaved(p, island.size())];
  for (std::size_t l = 0; l < bodyCount_; ++l) {
    const std::uint32_t body = globalBody_[l];
    if (body == noBody) continue;  // a fixed body's copy
    bodies[body].v = bodies_[l].v;
    bodies[body].omega = bodies_[l].omega;
    localBody_[body] = noBody;
  }
}

int GaussSeidelSolver::solveMatrix(std::span<const real> matrix, std::span<const real> slack,
                                   std::span<real> forces, const ContactSolverSettings& settings) {
  const std::size_t n = slack.size();
  int sweep = 0;
  while (sweep < settings.gaussSeidelMaxIterations) {
    ++sweep;
    real largestChange = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const real* row = &matrix[k * n];
      // A row nothing can move along (an immovable part against a fixed body) takes no force:
      // dividing by its zero diagonal would poison the whole island.
      if (!(row[k] > 0)) continue;
      real residual = slack[k];
      for (std::size_t j = 0; j < n; ++j) residual += row[j] * forces[j];
      const real newForce = std::max(real(0), forces[k] - settings.relaxation * residual / row[k]);
      largestChange = std::max(largestChange, std::abs(newForce - forces[k]) * row[k]);
      forces[k] = newForce;
    }
    if (largestChange <= settings.gaussSeidelTolerance) break;
  }
  return sweep;
}

}  // namespace thyrix
