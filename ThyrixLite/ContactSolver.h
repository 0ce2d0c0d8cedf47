#pragma once
/// @file ContactSolver.h
/// @brief The contact LCP as the solvers see it: bodies, constraint rows, settings.
///
/// For contact k between bodies a and b with unit normal n (a to b) at point p, the row of
/// the Jacobian is `J_k = [-n, -ka | n, kb]` with `ka = (p - c_a) x n`, `kb = (p - c_b) x n`.
/// The solvers find forces f >= 0 with `w = J u >= c` and `f (w - c) = 0`, where
/// `u = u0 + D^-1 J^T f` and `D = diag(m, m, I)` per body (docs/Design.md section 4).

#include <ThyrixLite/Renamed.h>
#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <cstdint>
#include <span>
#include <type_traits>

namespace thyrix {

/// Which method solves the contact LCP.
enum class ContactSolverKind : std::uint8_t {
  Baraff,       ///< Baraff's (1994) pivoting method: exact up to round-off
  GaussSeidel,  ///< projected Gauss-Seidel (Preda and Florian 2005): iterative
};

/// Tuning of the contact solvers.
struct ContactSolverSettings {
  /// Gauss-Seidel stops when no force changes the velocity of its contact by more than this (m/s).
  real gaussSeidelTolerance = std::is_same_v<real, float> ? real(1e-5) : real(1e-7);
  /// Gauss-Seidel stops after this many sweeps even if not converged (an island swept in
  /// height order: gaussSeidelMaxIterationsInHeightOrder). With acceleration, 20 sweeps keep a
  /// 30-body-high pile's overlaps under 1% of the radius (bench/README.md); raise it for more
  /// exact forces.
  int gaussSeidelMaxIterations = 20;
  /// In a world with gravity (Simulator::setGravity()), Gauss-Seidel sweeps each island's
  /// contacts in order of height against gravity, the first sweep from the lowest up, the next
  /// from the highest down, and so on: a sweep then carries the floor's reaction up the whole
  /// load path, the next the weight down, and a pile converges in fewer sweeps than in
  /// detection order. Off, or without gravity, in detection order.
  bool gaussSeidelHeightOrder = true;
  /// The cap of sweeps for an island swept in height order (its contacts not all at one
  /// height), in place of gaussSeidelMaxIterations. 16 sweeps in height order keep a
  /// 30-body-high pile's overlaps as small as 20 in detection order do (measured over 32
  /// seeds); an even cap ends with a sweep from the top down, which keeps them smaller than an
  /// odd one.
  int gaussSeidelMaxIterationsInHeightOrder = 16;
  /// Gauss-Seidel follows each sweep with a nonsmooth nonlinear conjugate gradient step
  /// (GaussSeidelSolver): far fewer sweeps for loads carried through many contacts.
  bool accelerateGaussSeidel = true;
  /// Gauss-Seidel starts from the last step's force of each contact that persists (matched by
  /// its shapes and feature); this makes piles converge in a few sweeps.
  bool warmStart = true;
  /// Over-relaxation factor of Gauss-Seidel, in (0, 2); 1 is plain Gauss-Seidel.
  real relaxation = 1;
  /// Islands of rigid bodies with more contacts than this are solved by Gauss-Seidel even when
  /// Baraff is chosen, and counted in StepStatistics::baraffOversizedIslands. Baraff's method
  /// works on a dense matrix of the island's contacts and pivots once or more per contact, so
  /// its cost grows with the cube of the contacts (measured on settled piles: 4x Gauss-Seidel's
  /// 20 sweeps at 22 contacts, 40x at 92): the exact solve is for the small islands agents
  /// make, piles go to Gauss-Seidel. `std::numeric_limits<int>::max()` asks for exact solves
  /// everywhere. (Islands with an articulated agent are solved by the chosen method whatever
  /// their size.)
  int baraffMaxIslandContacts = 32;
  /// The former name of baraffMaxIslandContacts: any use fails to compile, naming it.
  static renamed::baraffMaxContacts_is_now_baraffMaxIslandContacts baraffMaxContacts;
  /// Fraction of an overlap corrected per step (the elastic push apart), in (0, 1]. At 1 an
  /// overlap's target asks for the whole overlap to go in one step, as a gap's target allows the
  /// whole gap to close: the constraint is then "no overlap at the end of the step". A solver
  /// error e (m/s) left in a contact then gives a steady overlap of e dt / penetrationCorrection,
  /// the least for 1; smaller values push apart more softly.
  real penetrationCorrection = 1;
  /// Contacts are created while the gap is below a margin: this fraction of the smaller shape
  /// radius, plus what the two shapes travelled in the last step (times speculativeTravel).
  real speculativeFraction = real(0.1);
  /// How many times its last step's travel (the largest displacement of a point of its axis,
  /// as |dx| + |dy|, at most its radius) a shape's margin grows by: a shape that keeps its
  /// speed then sees every contact it can reach in the step, whatever the speed, while a
  /// crowd at rest keeps only the narrow margin of speculativeFraction (fewer contacts).
  real speculativeTravel = 1;
};

/// A body as the solvers see it: the velocity being solved for and the inverse quasistatic mass.
/// Fixed bodies have zero inverse mass and inertia, so contacts never move them.
struct SolverBody {
  Vector2 v;                ///< linear velocity
  real omega = 0;           ///< angular velocity
  real inverseMass = 0;     ///< 1 / m, 0 when fixed
  real inverseInertia = 0;  ///< 1 / I, 0 when fixed
};

/// One row of the LCP.
struct ContactConstraint {
  std::uint32_t a = 0;  ///< index of body A in the solver's bodies
  std::uint32_t b = 0;  ///< index of body B
  Vector2 normal;       ///< unit normal from A to B
  real armA = 0;        ///< (p - c_a) x n
  real armB = 0;        ///< (p - c_b) x n
  real target = 0;      ///< c: the least allowed normal velocity
  real force = 0;       ///< f: the normal force, the unknown (Gauss-Seidel starts from it)
  /// Where Gauss-Seidel sweeps the row: an island's rows go in increasing order of this key
  /// (nearly: see GaussSeidelSolver), ties in island order; all equal, in island order. The
  /// Simulator gives a contact's height against gravity (its point . -gravity), 0 without it
  /// or without ContactSolverSettings::gaussSeidelHeightOrder.
  real order = 0;

  /// The normal relative velocity `w = J u` for the current body velocities.
  [[nodiscard]] real normalVelocity(const SolverBody& bodyA, const SolverBody& bodyB) const {
    return dot(normal, bodyB.v - bodyA.v) + armB * bodyB.omega - armA * bodyA.omega;
  }
  /// The diagonal entry `A_kk = J_k D^-1 J_k^T`.
  [[nodiscard]] real selfResponse(const SolverBody& bodyA, const SolverBody& bodyB) const {
    return bodyA.inverseMass + bodyA.inverseInertia * armA * armA + bodyB.inverseMass +
           bodyB.inverseInertia * armB * armB;
  }
  /// Adds the body velocities caused by a change @p deltaForce of this contact's force.
  void applyImpulse(real deltaForce, SolverBody& bodyA, SolverBody& bodyB) const {
    bodyA.v -= normal * (deltaForce * bodyA.inverseMass);
    bodyA.omega -= armA * deltaForce * bodyA.inverseInertia;
    bodyB.v += normal * (deltaForce * bodyB.inverseMass);
    bodyB.omega += armB * deltaForce * bodyB.inverseInertia;
  }
};

/// `A_ij = J_i D^-1 J_j^T` between two rows through the rigid bodies they share (fixed bodies
/// and bodies with zero inverse mass contribute nothing).
inline real rigidCoupling(const ContactConstraint& i, const ContactConstraint& j,
                          std::span<const SolverBody> bodies) {
  // The body-X part of J_i D^-1 J_j^T, with signs sI, sJ (A: -1, B: +1).
  const auto part = [&](real signI, real armI, real signJ, real armJ, const SolverBody& body) {
    return signI * signJ *
           (body.inverseMass * dot(i.normal, j.normal) + body.inverseInertia * armI * armJ);
  };
  real value = 0;
  if (i.a == j.a) value += part(-1, i.armA, -1, j.armA, bodies[i.a]);
  if (i.a == j.b) value += part(-1, i.armA, 1, j.armB, bodies[i.a]);
  if (i.b == j.a) value += part(1, i.armB, -1, j.armA, bodies[i.b]);
  if (i.b == j.b) value += part(1, i.armB, 1, j.armB, bodies[i.b]);
  return value;
}

}  // namespace thyrix
