#pragma once
/// @file GaussSeidelSolver.h
/// @brief Projected Gauss-Seidel on the contact LCP, working on body velocities, with
/// nonsmooth nonlinear conjugate gradient acceleration.

#include <ThyrixLite/ContactSolver.h>

#include <cstdint>
#include <span>
#include <vector>

namespace thyrix {

/// Projected Gauss-Seidel (Preda and Florian 2005): sweeps the contacts in a fixed order,
/// `f_k <- max(0, f_k - (w_k - c_k) / A_kk)`, updating the two bodies' velocities after each
/// contact, so the matrix A is never formed. Starts from the forces already in the rows
/// (warm start): the body velocities given are those without them, and the solver adds
/// theirs.
///
/// With ContactSolverSettings::accelerateGaussSeidel, each sweep is followed by a conjugate
/// step, the nonsmooth nonlinear conjugate gradient method (NNCG) of Silcowitz, Niebe and
/// Erleben ("A nonsmooth nonlinear conjugate gradient method for interactive contact force
/// problems", The Visual Computer 26, 2010): the sweep's change of the forces is taken as the
/// residual, and the forces move further along `p <- change + beta p`, `beta` the
/// Fletcher-Reeves ratio of the squared changes (restarting when it exceeds 1). A load carried
/// through a long chain of contacts (a pile's weight down to its floor) then converges in a few
/// tens of sweeps instead of hundreds.
///
/// The rows are swept in order of their keys (ContactConstraint::order; the Simulator's are
/// heights against gravity), nearly: a counting sort into as many buckets of equal width as
/// rows, ties in island order. Sweeping a pile from its floor up carries the floor's reaction
/// up the whole load path in one sweep, the weight down in the next: measured on piles of
/// 1000 circles, 16 sweeps by height keep the overlaps as small as 20 in detection order (and
/// 14 do not; an odd cap, which ends going up, neither). Such an island has its own cap,
/// ContactSolverSettings::gaussSeidelMaxIterationsInHeightOrder; keys all equal (no gravity),
/// or not all finite, leave the island's order and gaussSeidelMaxIterations.
///
/// The solver copies an island into local arrays (rows with what a sweep needs precomputed,
/// contiguous in sweep order; velocities at the bodies' own indices) before sweeping;
/// the buffers are kept between calls (no allocation once they reached the largest island).
/// Built with GCC or Clang for x86-64, the sweeps and conjugate steps also have a copy
/// compiled for AVX, run where the processor has it: the same operations, the same bits.
class GaussSeidelSolver {
 public:
  /// Solves the rows listed in @p island (forces into the rows, velocities into @p bodies).
  /// @p bodies plus two per row of the island are at most 2^28 (2^29 with float): the local rows
  /// name their velocities by 32-bit byte offsets, which more would wrap (not
  /// checked). @return the number of sweeps done.
  int solve(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
            std::span<SolverBody> bodies, const ContactSolverSettings& settings);

  /// Makes room for islands of up to @p rows rows among @p bodies bodies.
  void reserve(std::size_t bodies, std::size_t rows);

  /// The same method on an LCP given directly: @p matrix (row-major, n x n, symmetric positive
  /// semi-definite, positive diagonal) and @p slack, `b - c` at zero force; @p forces holds the
  /// starting forces and receives the result. No acceleration. @return the number of sweeps.
  static int solveMatrix(std::span<const real> matrix, std::span<const real> slack,
                         std::span<real> forces, const ContactSolverSettings& settings);

 private:
  /// A row in the island's local numbering, with what a sweep needs precomputed: the pushes
  /// and the scaled normal put one multiplication less on a sweep's critical path. In double
  /// a row is one aligned cache line (A_kk, read only for the convergence test, is apart).
  struct alignas(sizeof(real) == 8 ? 64 : alignof(real)) Row {
    Vector2 pushA;         // change of A's velocity per unit force, subtracted: n / m_A
    Vector2 pushB;         // of B's, added: n / m_B
    Vector2 scaledNormal;  // n * relaxation / A_kk
    real scaledTarget;     // c * relaxation / A_kk
    std::uint32_t a;       // local bodies, as byte offsets in velocities_ (see solve())
    std::uint32_t b;
  };
  /// The turning part of a row, kept apart: islands where no contact has a lever arm (circles
  /// and borders) neither read nor write it.
  struct Turning {
    // w = n . (vB - vA) + armB omegaB - armA omegaA: its arms times relaxation / A_kk.
    real scaledArmA;
    real scaledArmB;
    real turnA;  // change of omegaA per unit force: -armA / IA
    real turnB;  // of omegaB: armB / IB
  };

  /// Fills slot_, each island position's local row: the rows nearly in order of their keys
  /// (ContactConstraint::order), which range from @p low to @p high (NaN keys aside),
  /// interleaved. Sets ordered_.
  void sweepOrder(std::span<const std::uint32_t> island, std::span<const ContactConstraint> rows,
                  real low, real high);
  /// Copies the island into the local rows and bodies, the rows interleaved so that
  /// consecutive ones seldom share a body (see interleaved() in the source).
  /// @return the least A_kk of the rows, NaN if one is NaN.
  real gather(std::span<const std::uint32_t> island, std::span<const ContactConstraint> rows,
              std::span<const SolverBody> bodies, real relaxation);
  /// One sweep over the rows, forward or backward; records each row's change in changes_.
  /// Without turning, the rows' lever arms are all zero and are not read. @return the sum of
  /// the squared changes of the forces.
  template <bool backward, bool turning>
  real sweep();
  /// The largest |change of a force| * A_kk of the last sweep: a velocity, the convergence
  /// measure. Only needed when the sweep's squared changes do not already exclude convergence.
  [[nodiscard]] real largestChange() const;
  /// Moves every force by beta * direction (kept non-negative), updates the velocities, and
  /// makes the next direction.
  template <bool turning>
  void conjugateStep(real beta);
  void scatter(std::span<const std::uint32_t> island, std::span<ContactConstraint> rows,
               std::span<SolverBody> bodies);

  std::vector<Row> rows_;
  std::vector<Turning> turning_;  // written and read only when a row of the island turns
  bool turningIsland_ = false;
  /// A row's A_kk and `relaxation / A_kk`, found in gather()'s first pass.
  struct RowResponse {
    real response;
    real inverseScaled;
  };
  std::vector<RowResponse> rowResponses_;  // by island position, for gather()
  std::vector<real> responses_;            // each row's A_kk, for largestChange()
  // The island's bodies at their own indices, then fixed bodies' copies (see gather()).
  std::vector<Vector2> velocities_;
  std::vector<real> omegas_;  // their angular velocities
  std::vector<real> forces_;
  std::vector<real> changes_;               // each force's change in the last sweep
  std::vector<real> direction_;             // the conjugate direction p
  bool ordered_ = false;                    // the island's rows are in order of their keys
  std::vector<std::uint32_t> slot_;         // island position -> local row
  std::vector<std::uint32_t> bucketStart_;  // sweepOrder()'s counting sort
};

}  // namespace thyrix
