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
};

}  // namespace thyrix
