#include <ThyrixLite/BaraffSolver.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

/// Tolerance, relative to the scale of A, below which a rate counts as zero.
constexpr real relativeTolerance = std::is_same_v<real, float> ? real(1e-5) : real(1e-11);

/// BaraffSolver::solve() for an island of the one row @p row, @p pivots its pivot count.
bool solveOne(ContactConstraint& row, std::span<SolverBody> bodies, int& pivots) {
  // pivot() on a 1 x 1 matrix, step by step (the same operations, the same bits): contact 0
  // needs no force if its slack is not negative; else it is driven, if its rate is above the
  // tolerance, by the step that closes its slack, and clamped (the factor's check passes
  // whenever the rate's did). Most islands of a small world are one contact.
  SolverBody& bodyA = bodies[row.a];
  SolverBody& bodyB = bodies[row.b];
  const real a = rigidCoupling(row, row, bodies);
  const real rateTolerance = relativeTolerance * std::max(real(0), a);
  const real slack = row.normalVelocity(bodyA, bodyB) - row.target;
  real force = 0;
  pivots = 0;
  if (!(slack >= 0)) {
    pivots = 1;
    if (!(a > rateTolerance)) return false;  // nothing bounds the step
    force += -slack / a;                     // force_ += step * direction_, direction_ being 1
  }
  row.force = std::max(real(0), force);
  row.applyImpulse(row.force, bodyA, bodyB);
  return true;
}

/// BaraffSolver::solve() for an island of the two rows @p row0 and @p row1 when pivot() would
/// take one of its usual paths (each row driven at most once, and clamped): its operations
/// in closed form, the same bits, @p pivots its pivot count. False, with nothing written,
/// for any other path (a row that blocks the other, a release, a failure): solve() then runs
/// pivot() itself. Most islands of a small world that are not one contact are two.
bool solveTwo(ContactConstraint& row0, ContactConstraint& row1, std::span<SolverBody> bodies,
              int& pivots) {
  // buildMatrix(): A (symmetric), its scale; then the slacks. The forces move as pivot()'s do,
  // by step * direction even where the direction is 0 or 1: a NaN or infinite step must leave
  // the same values (0 * inf is NaN), which the forces' final clamp alone does not make plain.
  const real a00 = rigidCoupling(row0, row0, bodies);
  const real a01 = rigidCoupling(row0, row1, bodies);
  const real a11 = rigidCoupling(row1, row1, bodies);
  const real rateTolerance = relativeTolerance * std::max(std::max(real(0), a00), a11);
  real s0 = row0.normalVelocity(bodies[row0.a], bodies[row0.b]) - row0.target;
  real s1 = row1.normalVelocity(bodies[row1.a], bodies[row1.b]) - row1.target;
  real f0 = 0;
  real f1 = 0;
  pivots = 0;
  const bool clamped0 = !(s0 >= 0);
  real l00 = 0;  // the factor's first entry, once row 0 is clamped
  if (clamped0) {
    // Row 0 driven alone: direction (1, 0), rates (a00, a01); it blocks itself and is clamped.
    pivots = 1;
    if (!(a00 > rateTolerance)) return false;
    const real step = -s0 / a00;
    f0 += step * real(1);
    f1 += step * real(0);
    s1 += step * a01;
    l00 = std::sqrt(a00);
  }
  if (!(s1 >= 0)) {
    ++pivots;
    if (clamped0) {
      // Row 1 driven with row 0 clamped: direction (x, 1), x from the factor; row 1 must block
      // first (row 0's force reaching zero is a release), and be clamped.
      const real x = (-a01 / l00) / l00;
      const real rate1 = a11 + a01 * x;
      if (!(rate1 > rateTolerance)) return false;
      const real step = -s1 / rate1;
      if (x < -relativeTolerance && std::max(real(0), -f0 / x) < step) return false;
      const real l10 = a01 / l00;
      if (a11 - l10 * l10 <= rateTolerance) return false;
      f0 += step * x;
      f1 += step * real(1);
    } else {
      // Row 1 driven alone (row 0 holds): direction (0, 1), rates (a01, a11); row 0 must not
      // start to approach first.
      if (!(a11 > rateTolerance)) return false;
      const real step = -s1 / a11;
      if (a01 < -rateTolerance && std::max(real(0), -s0 / a01) < step) return false;
      f0 += step * real(0);
      f1 += step * real(1);
    }
  }
  row0.force = std::max(real(0), f0);
  row0.applyImpulse(row0.force, bodies[row0.a], bodies[row0.b]);
  row1.force = std::max(real(0), f1);
  row1.applyImpulse(row1.force, bodies[row1.a], bodies[row1.b]);
  return true;
}

}  // namespace

void BaraffSolver::buildMatrix(std::span<const std::uint32_t> island,
                               std::span<const ContactConstraint> rows,
                               std::span<const SolverBody> bodies) {
  const std::size_t n = size_;
  matrix_.assign(n * n, 0);
  scale_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const ContactConstraint& ri = rows[island[i]];
    for (std::size_t j = i; j < n; ++j) {
      const real value = rigidCoupling(ri, rows[island[j]], bodies);
      matrix_[i * n + j] = value;
      matrix_[j * n + i] = value;
    }
    scale_ = std::max(scale_, matrix_[i * n + i]);
  }
}

void BaraffSolver::reserve(std::size_t contacts) {
  matrix_.reserve(contacts * contacts);
  factor_.reserve(contacts * contacts);
  for (auto* buffer : {&slack_, &force_, &direction_, &slackRate_, &solution_})
    buffer->reserve(contacts);
  state_.reserve(contacts);
  clamped_.reserve(contacts);
}

bool BaraffSolver::clamp(std::size_t i) {
  const std::size_t n = size_;
  const std::size_t c = clamped_.size();
  // New row l of L: L l = A_Ci (forward substitution), then the diagonal sqrt(A_ii - l.l).
  real* row = &factor_[c * n];
  real diagonal = matrix_[i * n + i];
  for (std::size_t j = 0; j < c; ++j) {
    real sum = matrix_[i * n + clamped_[j]];
    for (std::size_t k = 0; k < j; ++k) sum -= row[k] * factor_[j * n + k];
    row[j] = sum / factor_[j * n + j];
    diagonal -= row[j] * row[j];
  }
  if (diagonal <= relativeTolerance * scale_) return false;  // A_CC would be (numerically) singular
  row[c] = std::sqrt(diagonal);
  clamped_.push_back(i);
  state_[i] = State::Clamped;
  return true;
}

void BaraffSolver::release(std::size_t position) {
  const std::size_t n = size_;
  const std::size_t c = clamped_.size();
  // Deleting row and column p of L leaves L' with L' L'^T = A' - x x^T on the trailing block,
  // x being the deleted column below the diagonal: restore it with a rank-one update.
  for (std::size_t i = position + 1; i < c; ++i) {
    solution_[i] = factor_[i * n + position];  // x, kept in solution_ as scratch
    for (std::size_t j = position; j < i; ++j) factor_[(i - 1) * n + j] = factor_[i * n + j + 1];
    for (std::size_t j = 0; j < position; ++j) factor_[(i - 1) * n + j] = factor_[i * n + j];
  }
  for (std::size_t k = position; k + 1 < c; ++k) {
    const real x = solution_[k + 1];
    const real lkk = factor_[k * n + k];
    const real r = std::hypot(lkk, x);
    const real cosine = r / lkk;
    const real sine = x / lkk;
    factor_[k * n + k] = r;
    for (std::size_t i = k + 1; i + 1 < c; ++i) {
      real& lik = factor_[i * n + k];
      lik = (lik + sine * solution_[i + 1]) / cosine;
      solution_[i + 1] = cosine * solution_[i + 1] - sine * lik;
    }
  }
  state_[clamped_[position]] = State::NotClamped;
  clamped_.erase(clamped_.begin() + static_cast<std::ptrdiff_t>(position));
}

void BaraffSolver::computeDirection(std::size_t d) {
  const std::size_t n = size_;
  const std::size_t c = clamped_.size();
  // Solve A_CC x = -A_Cd with the factor: L y = -A_Cd, then L^T x = y.
  for (std::size_t i = 0; i < c; ++i) {
    real sum = -matrix_[clamped_[i] * n + d];
    for (std::size_t k = 0; k < i; ++k) sum -= factor_[i * n + k] * solution_[k];
    solution_[i] = sum / factor_[i * n + i];
  }
  for (std::size_t i = c; i-- > 0;) {
    real sum = solution_[i];
    for (std::size_t k = i + 1; k < c; ++k) sum -= factor_[k * n + i] * solution_[k];
    solution_[i] = sum / factor_[i * n + i];
  }
  std::fill(direction_.begin(), direction_.end(), real(0));
  direction_[d] = 1;
  for (std::size_t i = 0; i < c; ++i) direction_[clamped_[i]] = solution_[i];
  // dw = A df, over the columns where df is non-zero.
  for (std::size_t i = 0; i < n; ++i) {
    const real* row = &matrix_[i * n];
    real sum = row[d];
    for (const std::size_t k : clamped_) sum += row[k] * direction_[k];
    slackRate_[i] = sum;
  }
}

bool BaraffSolver::solve(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
                         std::span<SolverBody> bodies) {
  const std::size_t n = island.size();
  if (n == 1) return solveOne(rows[island[0]], bodies, pivots_);
  if (n == 2 && solveTwo(rows[island[0]], rows[island[1]], bodies, pivots_)) return true;
  size_ = n;
  buildMatrix(island, rows, bodies);
  slack_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ContactConstraint& row = rows[island[i]];
    slack_[i] = row.normalVelocity(bodies[row.a], bodies[row.b]) - row.target;
  }
  if (!pivot()) return false;
  for (std::size_t i = 0; i < n; ++i) {
    ContactConstraint& row = rows[island[i]];
    row.force = std::max(real(0), force_[i]);
    row.applyImpulse(row.force, bodies[row.a], bodies[row.b]);
  }
  return true;
}

bool BaraffSolver::solveMatrix(std::span<const real> matrix, std::span<const real> slack,
                               std::span<real> forces) {
  const std::size_t n = slack.size();
  size_ = n;
  matrix_.assign(matrix.begin(), matrix.end());
  slack_.assign(slack.begin(), slack.end());
  scale_ = 0;
  for (std::size_t i = 0; i < n; ++i) scale_ = std::max(scale_, matrix_[i * n + i]);
  if (!pivot()) return false;
  for (std::size_t i = 0; i < n; ++i) forces[i] = std::max(real(0), force_[i]);
  return true;
}

bool BaraffSolver::pivot() {
  const std::size_t n = size_;
  pivots_ = 0;
  force_.assign(n, 0);
  direction_.resize(n);
  slackRate_.resize(n);
  state_.assign(n, State::Unprocessed);
  clamped_.clear();
  factor_.resize(n * n);
  solution_.resize(n);

  const real rateTolerance = relativeTolerance * scale_;
  const int maxPivots = 10 * static_cast<int>(n) + 50;
  for (std::size_t d = 0; d < n; ++d) {
    if (slack_[d] >= 0) {
      state_[d] = State::NotClamped;
      continue;
    }
    // Drive contact d until w_d = c_d, pivoting whatever blocks the way.
    while (true) {
      if (++pivots_ > maxPivots) return false;
      computeDirection(d);
      real step = realMax;
      std::size_t blocker = n;
      if (slackRate_[d] > rateTolerance) {
        step = -slack_[d] / slackRate_[d];
        blocker = d;
      }
      for (const std::size_t i : clamped_) {
        if (direction_[i] < -relativeTolerance) {
          const real s = std::max(real(0), -force_[i] / direction_[i]);
          if (s < step) {
            step = s;
            blocker = i;
          }
        }
      }
      for (std::size_t i = 0; i < d; ++i) {
        if (state_[i] == State::NotClamped && slackRate_[i] < -rateTolerance) {
          const real s = std::max(real(0), -slack_[i] / slackRate_[i]);
          if (s < step) {
            step = s;
            blocker = i;
          }
        }
      }
      if (blocker == n) return false;  // nothing bounds the step: contradictory targets
      for (std::size_t i = 0; i < n; ++i) {
        force_[i] += step * direction_[i];
        slack_[i] += step * slackRate_[i];
      }
      if (blocker == d) {
        slack_[d] = 0;
        if (!clamp(d)) return false;
        break;
      }
      if (state_[blocker] == State::Clamped) {  // its force reached zero: release it
        force_[blocker] = 0;
        release(static_cast<std::size_t>(std::find(clamped_.begin(), clamped_.end(), blocker) -
                                         clamped_.begin()));
      } else {  // it started to approach: clamp it
        slack_[blocker] = 0;
        if (!clamp(blocker)) return false;
      }
    }
  }

  return true;
}

}  // namespace thyrix
