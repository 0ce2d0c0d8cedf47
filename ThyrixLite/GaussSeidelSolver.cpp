#include <ThyrixLite/GaussSeidelSolver.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>
#include <Tools/Wide.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

// Unrolling a loop by two or four, where the compiler takes the request (GCC and Clang);
// others (MSVC would warn about an unknown pragma) unroll as they see fit.
#if defined(__GNUC__)
#define THYRIX_UNROLL_TWO _Pragma("GCC unroll 2")
#define THYRIX_UNROLL_FOUR _Pragma("GCC unroll 4")
#else
#define THYRIX_UNROLL_TWO
#define THYRIX_UNROLL_FOUR
#endif

namespace thyrix {
namespace {

/// Where the island's row of rank @p p (in sweep order, see sweepOrder()) goes among its @p n
/// local rows. Rows come in detection order or by height, where a body's contacts follow one
/// another or are close; then every row would wait for the previous
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

/// A bound on a sweep's sum of squared changes above which its largest |change_k| A_kk is
/// certainly above @p tolerance, for @p n rows whose least A_kk is @p leastResponse; +inf
/// when none is known. With m the largest |change_k| and R the least A_kk, the sum S is at
/// most about n m^2, so S > 4 n (tolerance / R)^2 gives m > 1.8 tolerance / R, and the change
/// of largest magnitude alone has m A_kk >= m R > tolerance, roundings included: the margin
/// covers the sum's relative error (n epsilon <= 0.1) and the quotient's, and the squares and
/// the product stay far from underflow (tolerance / R >= sqrt(least normal), tolerance
/// normal). A pile's sweeps change forces far above the tolerance: their convergence test then
/// needs no pass over the changes.
real convergenceBound(real tolerance, real leastResponse, std::size_t n) {
  constexpr real infinity = std::numeric_limits<real>::infinity();
  constexpr real least = std::numeric_limits<real>::min();
  const real ratio = tolerance / leastResponse;
  const bool known = tolerance >= least && leastResponse > 0 && ratio >= std::sqrt(least) &&
                     ratio < infinity &&
                     static_cast<real>(n) * std::numeric_limits<real>::epsilon() <= real(0.1);
  if (!known) return infinity;                      // NaN or unsuited values included
  return 4 * static_cast<real>(n) * ratio * ratio;  // may be +inf: then not used either
}

}  // namespace

void GaussSeidelSolver::reserve(std::size_t bodies, std::size_t rows) {
  for (auto* buffer : {&forces_, &changes_, &direction_, &responses_}) buffer->reserve(rows);
  slot_.reserve(rows);
  rowResponses_.reserve(rows);
  bucketStart_.reserve(rows + 1);
  rows_.reserve(rows);
  turning_.reserve(rows);
  // The bodies, then up to two copies of fixed bodies a row.
  velocities_.reserve(bodies + 2 * rows);
  omegas_.reserve(bodies + 2 * rows);
}

int GaussSeidelSolver::solve(std::span<const std::uint32_t> island,
                             std::span<ContactConstraint> rows, std::span<SolverBody> bodies,
                             const ContactSolverSettings& settings) {
  const real leastResponse = gather(island, rows, bodies, settings.relaxation);
  const real tolerance = settings.gaussSeidelTolerance;
  const real bound = convergenceBound(tolerance, leastResponse, rows_.size());
  const bool accelerate = settings.accelerateGaussSeidel;
  const int maxSweeps =
      ordered_ ? settings.gaussSeidelMaxIterationsInHeightOrder : settings.gaussSeidelMaxIterations;
  // The first sweep restarts the direction (lastNorm is 0): it needs no zeroing. resize, not
  // assign: assign would reallocate to the exact size at each new largest island (a growing
  // pile: nearly every step), resize grows geometrically.
  if (accelerate) direction_.resize(rows_.size());
  real lastNorm = 0;  // squared norm of the previous sweep's change
  int sweeps = 0;
  while (sweeps < maxSweeps) {
    ++sweeps;
    // Symmetric Gauss-Seidel: alternate sweep directions, so that a correction travels through
    // a long chain of contacts both ways (the weight down, the floor's reaction up).
    const bool backward = sweeps % 2 == 0;
    const real squaredNorm = turningIsland_
                                 ? (backward ? sweep<true, true>() : sweep<false, true>())
                                 : (backward ? sweep<true, false>() : sweep<false, false>());
    // Converged when the largest change is within the tolerance; a large squared norm rules
    // that out without a pass over the changes (see convergenceBound()). Written !(a > b): a
    // NaN norm leaves the decision to largestChange(), which skips NaN changes.
    if (!(squaredNorm > bound) && largestChange() <= tolerance) break;
    // The last sweep is not followed by a conjugate step: the result is a projected sweep's.
    if (!accelerate || sweeps == maxSweeps) continue;
    if (lastNorm > 0 && squaredNorm <= lastNorm) {
      const real beta = squaredNorm / lastNorm;
      turningIsland_ ? conjugateStep<true>(beta) : conjugateStep<false>(beta);
    } else {  // first sweep, or the change grew: restart along the change itself
      // Swapped, not copied: the next sweep writes every change anew.
      std::swap(direction_, changes_);
    }
    lastNorm = squaredNorm;
  }
  scatter(island, rows, bodies);
  return sweeps;
}

void GaussSeidelSolver::sweepOrder(std::span<const std::uint32_t> island,
                                   std::span<const ContactConstraint> rows, real low, real high) {
  const std::size_t n = island.size();
  slot_.resize(n);
  std::uint32_t* const slot = slot_.data();
  constexpr real infinity = std::numeric_limits<real>::infinity();
  const real range = high - low;
  ordered_ = range > 0 && range < infinity;
  if (!ordered_) {  // all keys equal (no gravity): island order
    for (std::size_t p = 0; p < n; ++p) slot[p] = static_cast<std::uint32_t>(interleaved(p, n));
    return;
  }
  // A counting sort into n buckets of equal width: nearly the order of the keys, in a few
  // passes without a comparison. A NaN key goes to the first bucket.
  const std::size_t buckets = n;
  const real scale = static_cast<real>(buckets) / range;
  const real last = static_cast<real>(buckets - 1);
  bucketStart_.assign(buckets + 1, 0);
  std::uint32_t* const start = bucketStart_.data();
  for (std::size_t p = 0; p < n; ++p) {
    const real t = (rows[island[p]].order - low) * scale;
    const auto bucket = t > 0 ? static_cast<std::uint32_t>(std::min(t, last)) : std::uint32_t{0};
    slot[p] = bucket;
    ++start[bucket + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  for (std::size_t p = 0; p < n; ++p)
    slot[p] = static_cast<std::uint32_t>(interleaved(start[slot[p]]++, n));
}

real GaussSeidelSolver::gather(std::span<const std::uint32_t> island,
                               std::span<const ContactConstraint> rows,
                               std::span<const SolverBody> bodies, real relaxation) {
  const std::size_t n = island.size();
  // The island's bodies keep their own indices in the local velocities (so a body needs no
  // local number: whether a row's body is met for the first time was an unpredictable
  // branch); a body that cannot move gets a private copy in each row after them, so that rows
  // that share only a wall do not wait on each other's (null) updates of its velocity. The
  // arrays are sized once, then filled through plain pointers (no growth checks).
  const std::size_t privateStart = bodies.size();
  if (velocities_.size() < privateStart + 2 * n) {
    velocities_.resize(privateStart + 2 * n);
    omegas_.resize(privateStart + 2 * n);
  }
  rows_.resize(n);
  forces_.resize(n);
  changes_.resize(n);
  responses_.resize(n);
  rowResponses_.resize(n);
  Vector2* const velocity = velocities_.data();
  real* const omega = omegas_.data();
  RowResponse* const rowResponse = rowResponses_.data();
  // relaxation / A_kk; a row nothing can move along takes no force (its zero diagonal would
  // poison the island).
  const auto inverseScaledOf = [relaxation](real response) {
    return response > 0 ? relaxation / response : 0;
  };
  // A first pass, short enough for many rows to be under way at once: every row copies its
  // bodies' velocities, before any row adds its force's (a body's rows all copy the same
  // values, so no test for its first), and finds the range of the keys for sweepOrder() and
  // its A_kk and its division, which the row's copy below would otherwise wait on.
  constexpr real infinity = std::numeric_limits<real>::infinity();
  real low = infinity;
  real high = -infinity;
  // The least A_kk, NaN if one is NaN (for the convergence bound).
  real leastResponse = infinity;
  for (std::size_t p = 0; p < n; ++p) {
    const ContactConstraint& c = rows[island[p]];
    const SolverBody& bodyA = bodies[c.a];
    const SolverBody& bodyB = bodies[c.b];
    velocity[c.a] = bodyA.v;
    omega[c.a] = bodyA.omega;
    velocity[c.b] = bodyB.v;
    omega[c.b] = bodyB.omega;
    // NaN keys are skipped (std::min and std::max keep the first argument).
    low = std::min(low, c.order);
    high = std::max(high, c.order);
    const real response = c.selfResponse(bodyA, bodyB);
    rowResponse[p] = {response, inverseScaledOf(response)};
    // A NaN, once taken, stays: a later row's response must not replace it (the least of the
    // rows after a NaN could exceed an A_kk before it, and the bound would then be wrong).
    if (response < leastResponse || std::isnan(response)) leastResponse = response;
  }
  sweepOrder(island, rows, low, high);
  const std::uint32_t* const slot = slot_.data();
  auto privateSlot = static_cast<std::uint32_t>(privateStart);
  const auto localIndex = [&](std::uint32_t body, const SolverBody& b) {
    if (b.inverseMass != 0 || b.inverseInertia != 0) return body;
    velocity[privateSlot] = b.v;
    omega[privateSlot] = b.omega;
    return privateSlot++;
  };
  // A lever arm matters if its body turns or can be turned (a fixed wall's does not).
  const auto turns = [](real arm, const SolverBody& body) {
    return arm != 0 && (body.inverseInertia != 0 || body.omega != 0);
  };
  const auto turningOf = [](const ContactConstraint& c, const SolverBody& bodyA,
                            const SolverBody& bodyB, real inverseScaled) {
    return Turning{c.armA * inverseScaled, c.armB * inverseScaled, -c.armA * bodyA.inverseInertia,
                   c.armB * bodyB.inverseInertia};
  };
  bool turning = false;
  for (std::size_t p = 0; p < n; ++p) {
    const ContactConstraint& c = rows[island[p]];
    const std::size_t q = slot[p];
    const SolverBody& bodyA = bodies[c.a];
    const SolverBody& bodyB = bodies[c.b];
    const real response = rowResponse[p].response;
    const real inverseScaled = rowResponse[p].inverseScaled;
    const std::uint32_t a = localIndex(c.a, bodyA);
    const std::uint32_t b = localIndex(c.b, bodyB);
    // The starting force's velocities, added here in island order (no pass of its own), by
    // ContactConstraint::applyImpulse's formula written for the local bodies (same bits).
    const real force = c.force;
    velocity[a] -= c.normal * (force * bodyA.inverseMass);
    omega[a] -= c.armA * force * bodyA.inverseInertia;
    velocity[b] += c.normal * (force * bodyB.inverseMass);
    omega[b] += c.armB * force * bodyB.inverseInertia;
    rows_[q] = {c.normal * bodyA.inverseMass,       c.normal * bodyB.inverseMass,
                c.normal * inverseScaled,           c.target * inverseScaled,
                a * std::uint32_t{sizeof(Vector2)}, b * std::uint32_t{sizeof(Vector2)}};
    responses_[q] = response;
    forces_[q] = force;
    if (turning) {
      turning_[q] = turningOf(c, bodyA, bodyB, inverseScaled);
    } else if (turns(c.armA, bodyA) || turns(c.armB, bodyB)) {
      // The first row that turns: the turning parts of the rows before it, which were not
      // written (most islands never turn), by the same formulas (same bits).
      turning = true;
      turning_.resize(n);
      for (std::size_t r = 0; r <= p; ++r) {
        const ContactConstraint& d = rows[island[r]];
        const SolverBody& dA = bodies[d.a];
        const SolverBody& dB = bodies[d.b];
        turning_[slot[r]] = turningOf(d, dA, dB, inverseScaledOf(d.selfResponse(dA, dB)));
      }
    }
  }
  turningIsland_ = turning;
  return leastResponse;
}

real GaussSeidelSolver::largestChange() const {
  // The sweep's former measure, exactly: NaN changes are skipped as std::max skips them.
  real largest = 0;
  for (std::size_t p = 0; p < changes_.size(); ++p)
    largest = std::max(largest, std::abs(changes_[p]) * responses_[p]);
  return largest;
}

namespace {

/// The island's body at byte offset @p offset of @p velocity (rows name their bodies so: no
/// multiplication to find them).
inline Vector2& at(Vector2* velocity, std::uint32_t offset) {
  return *reinterpret_cast<Vector2*>(reinterpret_cast<char*>(velocity) + offset);
}

/// The angular velocity in @p omega of the body at byte offset @p offset of the velocities.
inline real& omegaAt(real* omega, std::uint32_t offset) { return omega[offset / sizeof(Vector2)]; }

/// `scaledNormal . (vB - vA)`, the row's normal velocity times relaxation / A_kk: the
/// difference and the products of x and y together (a sweep is bound by its instructions), the
/// x product added first, so the same bits as Vector2's dot().
inline real scaledNormalVelocity(const Vector2& scaledNormal, const Vector2& vA,
                                 const Vector2& vB) {
  using Pair = simd::Wide<real, 2>;
  static_assert(std::is_standard_layout_v<Vector2> && sizeof(Vector2) == 2 * sizeof(real),
                "a Vector2 is read as its two coordinates, x first");
  const Pair products = Pair::load(&scaledNormal.x) * (Pair::load(&vB.x) - Pair::load(&vA.x));
  return products.at(0) + products.at(1);
}

/// Adds to @p velocity and @p omega (the island's) the change @p amount of row @p p's force,
/// through its bodies at byte offsets `row.a` and `row.b`, its pushes and, in an island that
/// turns (@p turning), its turns in `turns[p]` (not read otherwise: turning_ is then not
/// filled). B's velocity is read after A's is stored: the same result if they were one body.
/// Everything the row gives is read before the first store.
template <bool turning, class Row, class Turning>
inline void push(Vector2* velocity, real* omega, const Row& row, const Turning* turns,
                 std::size_t p, real amount) {
  const std::uint32_t a = row.a;
  const std::uint32_t b = row.b;
  const Vector2 byA = row.pushA * amount;
  const Vector2 byB = row.pushB * amount;
  if constexpr (turning) {
    const real turnA = turns[p].turnA;
    const real turnB = turns[p].turnB;
    at(velocity, a) -= byA;
    at(velocity, b) += byB;
    omegaAt(omega, a) += turnA * amount;
    omegaAt(omega, b) += turnB * amount;
  } else {
    at(velocity, a) -= byA;
    at(velocity, b) += byB;
  }
}

/// One sweep over the @p n rows @p rows (see GaussSeidelSolver::sweep()), their turning parts
/// @p turns, the island's velocities @p velocity and @p omega, the forces @p forces; records
/// the changes in @p changes. @return the sum of the squared changes.
template <bool backward, bool turning, class Row, class Turning>
THYRIX_ALWAYS_INLINE real sweepRows(std::size_t n, const Row* rows, const Turning* turns,
                                    Vector2* velocity, real* omega, real* forces, real* changes) {
  real squaredNorm = 0;
  // Four rows an iteration: a quarter of the loop overhead (the rows still go one after the
  // other; 25.3 to 24.7 instructions a row in AVX).
  THYRIX_UNROLL_FOUR
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = backward ? n - 1 - i : i;
    const Row& row = rows[p];
    const std::uint32_t a = row.a;
    const std::uint32_t b = row.b;
    const real scaledTarget = row.scaledTarget;
    const real force = forces[p];
    const real start = force + scaledTarget;
    // The normal velocity w times relaxation / A_kk, a force.
    real scaledVelocity = scaledNormalVelocity(row.scaledNormal, at(velocity, a), at(velocity, b));
    if constexpr (turning)
      scaledVelocity +=
          turns[p].scaledArmB * omegaAt(omega, b) - turns[p].scaledArmA * omegaAt(omega, a);
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
    const real amount = std::is_same_v<real, double> ? scaledTarget - reached : change;
    push<turning>(velocity, omega, row, turns, p, amount);
    forces[p] = newForce;
    changes[p] = change;
    squaredNorm += change * change;
  }
  return squaredNorm;
}

/// One conjugate step (see GaussSeidelSolver::conjugateStep()) over the @p n rows @p rows,
/// with the directions @p direction and the last sweep's @p changes.
template <bool turning, class Row, class Turning>
THYRIX_ALWAYS_INLINE void conjugateRows(std::size_t n, real beta, const Row* rows,
                                        const Turning* turns, Vector2* velocity, real* omega,
                                        real* forces, real* direction, const real* changes) {
  // Two rows an iteration: half the loop overhead (the rows still go one after the other).
  THYRIX_UNROLL_TWO
  for (std::size_t p = 0; p < n; ++p) {
    const real step = beta * direction[p];
    direction[p] = step + changes[p];
    // The forces stay feasible (the next sweep would project them anyway), and the velocities
    // follow them. Written as the change max(step, -f), the clamp compiles without a branch
    // (max(0, f + step) did not, and mispredicted on rows at the bound).
    const real change = std::max(step, -forces[p]);
    forces[p] += change;
    push<turning>(velocity, omega, rows[p], turns, p, change);
  }
}

#if defined(THYRIX_AVX_DISPATCH)
// The same loops compiled for AVX, chosen at run time: its three-operand instructions need
// none of the register copies SSE2's two-operand ones take (a sweep is bound by its
// instructions: 34 a row in SSE2, 29 in AVX). The same operations in the same order, and AVX
// brings no fused multiply-add (that is FMA's), so the same bits.
template <bool backward, bool turning, class Row, class Turning>
[[gnu::target("avx")]] real sweepRowsAvx(std::size_t n, const Row* rows, const Turning* turns,
                                         Vector2* velocity, real* omega, real* forces,
                                         real* changes) {
  return sweepRows<backward, turning>(n, rows, turns, velocity, omega, forces, changes);
}
template <bool turning, class Row, class Turning>
[[gnu::target("avx")]] void conjugateRowsAvx(std::size_t n, real beta, const Row* rows,
                                             const Turning* turns, Vector2* velocity, real* omega,
                                             real* forces, real* direction, const real* changes) {
  conjugateRows<turning>(n, beta, rows, turns, velocity, omega, forces, direction, changes);
}

#endif

}  // namespace

template <bool backward, bool turning>
real GaussSeidelSolver::sweep() {
#if defined(THYRIX_AVX_DISPATCH)
  if (processorHasAvx())
    return sweepRowsAvx<backward, turning>(rows_.size(), rows_.data(), turning_.data(),
                                           velocities_.data(), omegas_.data(), forces_.data(),
                                           changes_.data());
#endif
  return sweepRows<backward, turning>(rows_.size(), rows_.data(), turning_.data(),
                                      velocities_.data(), omegas_.data(), forces_.data(),
                                      changes_.data());
}

template <bool turning>
void GaussSeidelSolver::conjugateStep(real beta) {
#if defined(THYRIX_AVX_DISPATCH)
  if (processorHasAvx()) {
    conjugateRowsAvx<turning>(rows_.size(), beta, rows_.data(), turning_.data(), velocities_.data(),
                              omegas_.data(), forces_.data(), direction_.data(), changes_.data());
    return;
  }
#endif
  conjugateRows<turning>(rows_.size(), beta, rows_.data(), turning_.data(), velocities_.data(),
                         omegas_.data(), forces_.data(), direction_.data(), changes_.data());
}

void GaussSeidelSolver::scatter(std::span<const std::uint32_t> island,
                                std::span<ContactConstraint> rows, std::span<SolverBody> bodies) {
  // Each row gives back its bodies' velocities (a body's rows all give the same; a fixed
  // body's own entry still holds the velocity it was given).
  const Vector2* const velocity = velocities_.data();
  const real* const omega = omegas_.data();
  for (std::size_t p = 0; p < island.size(); ++p) {
    ContactConstraint& row = rows[island[p]];
    row.force = forces_[slot_[p]];
    bodies[row.a].v = velocity[row.a];
    bodies[row.a].omega = omega[row.a];
    bodies[row.b].v = velocity[row.b];
    bodies[row.b].omega = omega[row.b];
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

#undef THYRIX_UNROLL_TWO
#undef THYRIX_UNROLL_FOUR
