#include <ThyrixLite/BaraffSolver.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

/// Tolerance, relative to the scale of A, below which a rate counts as zero.
constexpr real relativeTolerance = std::is_same_v<real, float> ? real(1e-5) : real(1e-11);

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
