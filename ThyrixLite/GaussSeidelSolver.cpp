#include <ThyrixLite/GaussSeidelSolver.h>

#include <algorithm>
#include <cmath>

namespace thyrix {

int GaussSeidelSolver::solve(std::span<const std::uint32_t> island,
                             std::span<ContactConstraint> rows, std::span<SolverBody> bodies,
                             const ContactSolverSettings& settings) {
  int sweep = 0;
  while (sweep < settings.gaussSeidelMaxIterations) {
    ++sweep;
    real largestChange = 0;  // in velocity units: |delta f| * A_kk
    // Symmetric Gauss-Seidel: alternate sweep directions, so that a correction travels through
    // a long chain of contacts (a pile's weight down to the floor and the floor's reaction
    // back up) in one pair of sweeps instead of one contact per sweep.
    const bool backward = sweep % 2 == 0;
    for (std::size_t position = 0; position < island.size(); ++position) {
      const std::uint32_t k = island[backward ? island.size() - 1 - position : position];
      ContactConstraint& row = rows[k];
      SolverBody& bodyA = bodies[row.a];
      SolverBody& bodyB = bodies[row.b];
      const real selfResponse = row.selfResponse(bodyA, bodyB);
      const real residual = row.normalVelocity(bodyA, bodyB) - row.target;
      // Clamp the accumulated force, not the increment.
      const real newForce =
          std::max(real(0), row.force - settings.relaxation * residual / selfResponse);
      const real change = newForce - row.force;
      if (change == 0) continue;
      row.force = newForce;
      row.applyImpulse(change, bodyA, bodyB);
      largestChange = std::max(largestChange, std::abs(change) * selfResponse);
    }
    if (largestChange <= settings.gaussSeidelTolerance) break;
  }
  return sweep;
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
