#pragma once
/// @file GaussSeidelSolver.h
/// @brief Projected Gauss-Seidel on the contact LCP, working on body velocities.

#include <ThyrixLite/ContactSolver.h>

#include <span>

namespace thyrix {

/// Projected Gauss-Seidel (Preda and Florian 2005): sweeps the contacts in a fixed order,
/// `f_k <- max(0, f_k - (w_k - c_k) / A_kk)`, updating the two bodies' velocities after each
/// contact, so the matrix A is never formed. Starts from the forces already in the rows
/// (warm start) with the body velocities consistent with them.
class GaussSeidelSolver {
 public:
  /// Solves the rows listed in @p island. @return the number of sweeps done.
  static int solve(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
                   std::span<SolverBody> bodies, const ContactSolverSettings& settings);

  /// The same method on an LCP given directly: @p matrix (row-major, n x n, symmetric positive
  /// semi-definite, positive diagonal) and @p slack, `b - c` at zero force; @p forces holds the
  /// starting forces and receives the result. @return the number of sweeps done.
  static int solveMatrix(std::span<const real> matrix, std::span<const real> slack,
                         std::span<real> forces, const ContactSolverSettings& settings);
};

}  // namespace thyrix
