#include <ThyrixLite/BaraffSolver.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

/// Tolerance, relative to the scale of A, below which a rate counts as zero.
constexpr real relativeTolerance = std::is_same_v<real, float> ? real(1e-5) : real(1e-11);

/// `J_i^X D_X^-1 (J_j^X)^T` for one body X shared by rows i and j, with signs sI, sJ (A: -1, B: +1).
real coupling(const ContactConstraint& i, real signI, real armI, const ContactConstraint& j,
              real signJ, real armJ, const SolverBody& body) {
  return signI * signJ *
         (body.inverseMass * dot(i.normal, j.normal) + body.inverseInertia * armI * armJ);
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
      const ContactConstraint& rj = rows[island[j]];
      real value = 0;
      // A body shared by the two rows couples them; fixed bodies have zero inverse mass.
      if (ri.a == rj.a) value += coupling(ri, -1, ri.armA, rj, -1, rj.armA, bodies[ri.a]);
      if (ri.a == rj.b) value += coupling(ri, -1, ri.armA, rj, 1, rj.armB, bodies[ri.a]);
      if (ri.b == rj.a) value += coupling(ri, 1, ri.armB, rj, -1, rj.armA, bodies[ri.b]);
      if (ri.b == rj.b) value += coupling(ri, 1, ri.armB, rj, 1, rj.armB, bodies[ri.b]);
      matrix_[i * n + j] = value;
      matrix_[j * n + i] = value;
    }
    scale_ = std::max(scale_, matrix_[i * n + i]);
  }
}

bool BaraffSolver::computeDirection(std::size_t d) {
  const std::size_t n = size_;
  const std::size_t c = clamped_.size();
  // Cholesky factorization of A_CC (lower triangle, row-major c x c).
  factor_.resize(c * c);
  for (std::size_t i = 0; i < c; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      real sum = matrix_[clamped_[i] * n + clamped_[j]];
      for (std::size_t k = 0; k < j; ++k) sum -= factor_[i * c + k] * factor_[j * c + k];
      if (i == j) {
        if (sum <= relativeTolerance * scale_) return false;  // A_CC (numerically) singular
        factor_[i * c + i] = std::sqrt(sum);
      } else {
        factor_[i * c + j] = sum / factor_[j * c + j];
      }
    }
  }
  // Solve A_CC x = -A_Cd by forward and back substitution.
  solution_.resize(c);
  for (std::size_t i = 0; i < c; ++i) {
    real sum = -matrix_[clamped_[i] * n + d];
    for (std::size_t k = 0; k < i; ++k) sum -= factor_[i * c + k] * solution_[k];
    solution_[i] = sum / factor_[i * c + i];
  }
  for (std::size_t i = c; i-- > 0;) {
    real sum = solution_[i];
    for (std::size_t k = i + 1; k < c; ++k) sum -= factor_[k * c + i] * solution_[k];
    solution_[i] = sum / factor_[i * c + i];
  }
  std::fill(direction_.begin(), direction_.end(), real(0));
  direction_[d] = 1;
  for (std::size_t i = 0; i < c; ++i) direction_[clamped_[i]] = solution_[i];
  // dw = A df, over the columns where df is non-zero.
  for (std::size_t i = 0; i < n; ++i) {
    real sum = matrix_[i * n + d];
    for (const std::size_t k : clamped_) sum += matrix_[i * n + k] * direction_[k];
    slackRate_[i] = sum;
  }
  return true;
}

bool BaraffSolver::solve(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
                         std::span<SolverBody> bodies) {
  const std::size_t n = island.size();
  size_ = n;
  pivots_ = 0;
  buildMatrix(island, rows, bodies);
  slack_.resize(n);
  force_.assign(n, 0);
  direction_.resize(n);
  slackRate_.resize(n);
  state_.assign(n, State::Unprocessed);
  clamped_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ContactConstraint& row = rows[island[i]];
    slack_[i] = row.normalVelocity(bodies[row.a], bodies[row.b]) - row.target;
  }

  const real rateTolerance = relativeTolerance * scale_;
  const int maxPivots = 10 * static_cast<int>(n) + 50;
  for (std::size_t d = 0; d < n; ++d) {
    if (slack_[d] >= 0) {
      state_[d] = State::NotClamped;
      continue;
    }
    // Drive contact d until w_d = c_d, pivoting whatever blocks the way.
    while (true) {
      if (++pivots_ > maxPivots || !computeDirection(d)) return false;
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
        state_[d] = State::Clamped;
        clamped_.push_back(d);
        break;
      }
      if (state_[blocker] == State::Clamped) {  // its force reached zero: release it
        force_[blocker] = 0;
        state_[blocker] = State::NotClamped;
        clamped_.erase(std::find(clamped_.begin(), clamped_.end(), blocker));
      } else {  // it started to approach: clamp it
        slack_[blocker] = 0;
        state_[blocker] = State::Clamped;
        clamped_.push_back(blocker);
      }
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    ContactConstraint& row = rows[island[i]];
    row.force = std::max(real(0), force_[i]);
    row.applyImpulse(row.force, bodies[row.a], bodies[row.b]);
  }
  return true;
}

}  // namespace thyrix
