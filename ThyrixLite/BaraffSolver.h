#pragma once
/// @file BaraffSolver.h
/// @brief Baraff's pivoting method for the frictionless contact LCP.

#include <ThyrixLite/ContactSolver.h>

#include <cstdint>
#include <span>
#include <vector>

namespace thyrix {

/// Baraff, "Fast contact force computation for nonpenetrating rigid bodies", SIGGRAPH 1994,
/// section 4 (frictionless case). Contacts are driven one at a time to complementarity while the
/// clamped set C (`w = c`, force free) and the not-clamped set NC (`f = 0`, `w >= c`) stay
/// consistent; each pivot moves one index between the sets.
///
/// The island's matrix `A = J D^-1 J^T` is formed densely; the Cholesky factor of `A_CC` is
/// updated as indices join C (one new row) or leave it (a rank-one update), so a pivot costs
/// O(|C|^2) rather than a refactorization. The work buffers are kept between calls, so a
/// warmed-up solver allocates nothing.
class BaraffSolver {
 public:
  /// Solves the rows listed in @p island (their forces must be zero on entry) and adds the
  /// velocity the forces cause to @p bodies.
  /// @return false if the method could not finish (a singular `A_CC`, an unbounded direction
  ///         from contradictory targets, or too many pivots); the rows and bodies are then
  ///         left as on entry, for another solver to take over.
  bool solve(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
             std::span<SolverBody> bodies);

  /// The same method on an LCP given directly: the symmetric positive semi-definite matrix
  /// @p matrix (row-major, n x n) and the slack `b - c` of every row at zero force; writes the
  /// forces to @p forces. Used for islands whose bodies are not all rigid (articulated agents),
  /// whose matrix is built from test-force responses. @return false as for solve().
  bool solveMatrix(std::span<const real> matrix, std::span<const real> slack,
                   std::span<real> forces);

  /// Makes room for islands of up to @p contacts contacts without further allocation.
  void reserve(std::size_t contacts);

  /// Pivots done by the last call (for statistics and tests).
  [[nodiscard]] int lastPivotCount() const { return pivots_; }

 private:
  enum class State : std::uint8_t { Unprocessed, Clamped, NotClamped };

  void buildMatrix(std::span<const std::uint32_t> island, std::span<const ContactConstraint> rows,
                   std::span<const SolverBody> bodies);
  /// The pivoting itself, on matrix_ and slack_ (size_ rows): fills force_.
  bool pivot();
  /// Fills direction_ (df) and slackRate_ (dw) for raising f_d by 1 while C stays at w = c.
  void computeDirection(std::size_t d);
  /// Adds contact @p i to C, extending the factor by one row; false if A_CC would be singular.
  bool clamp(std::size_t i);
  /// Removes the contact at position @p position of C, updating the factor.
  void release(std::size_t position);

  std::size_t size_ = 0;
  std::vector<real> matrix_;     // A, size_ x size_, row-major
  std::vector<real> slack_;      // w - c per contact
  std::vector<real> force_;      // f per contact
  std::vector<real> direction_;  // df
  std::vector<real> slackRate_;  // dw = A df
  std::vector<State> state_;
  std::vector<std::size_t> clamped_;  // C, in the order contacts joined it
  std::vector<real> factor_;          // Cholesky factor L of A_CC, row stride size_
  std::vector<real> solution_;        // the solve of A_CC x = -A_Cd
  real scale_ = 1;                    // largest diagonal entry of A, for tolerances
  int pivots_ = 0;
};

}  // namespace thyrix
