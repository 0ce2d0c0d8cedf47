#pragma once
/// @file ArticulatedAgentQuasistatic.h
/// @brief An articulated agent under quasistatic dynamics: the O(N) articulated-body algorithm
/// for its free motion, Kokkevis test forces for its contacts and joint limits in the
/// simulator's LCP.

#include <ThyrixLite/MultiBodyObject.h>
#include <ThyrixPro/ArticulatedAgentBase.h>
#include <ThyrixPro/ArticulatedBody.h>

#include <span>
#include <string>
#include <vector>

namespace thyrix {

/// An articulated agent moving by the quasistatic law `(J^T D J) u = J^T F + tau`
/// (ArticulatedBody; docs/Design.md section 4): a base of circles and capsules with limbs of
/// capsule links on revolute joints, registered with a Simulator like any object.
///
/// Build it from ArticulatedBasePart and ArticulatedLimb descriptions, place it (`r`, `alpha`
/// or setPose()), register it, and drive it from control() (override it in a subclass) or
/// between steps with the effectors of ArticulatedAgentBase. In each step:
/// - phase 5, computeDerivativesWithoutContacts(): the free velocities `u0` from the joint
///   torques, the servos (as implicit joint damping `gain dt` plus the torque
///   `gain (target - q)`), `externalForce`/`externalTorque` on the base and the forces of
///   applyLinkForce(), in O(N); the accumulators are reset;
/// - phase 6, in the simulator's contact solve: collectInternalConstraints() adds the joint
///   limits, velocityAlong() and responseMatrix() give the LCP's `b` and `K` block through
///   test forces (Kokkevis 2004; docs/Algorithms.md section 3), O(N) per constraint, and
///   applyConstraintForces() sets the final velocities;
/// - phase 8, integrate(): explicit Euler on the base pose and joint angles, then the shapes
///   are placed.
///
/// A `fixed` agent has a fixed base (infinite mass); its joints still move.
///
/// The per-step work allocates nothing once the largest number of constraints on the agent has
/// been seen (its buffers are members, reused).
class ArticulatedAgentQuasistatic : public ArticulatedAgentBase {
 public:
  /// An agent whose base is made of @p baseParts (at least one) and which carries @p limbs.
  /// @throws InvalidArgument naming "ArticulatedAgentBase.baseParts" when empty, the first bad
  /// field of a part (ArticulatedBasePart::validate()), or of a link (ArticulatedLink)
  ArticulatedAgentQuasistatic(const std::vector<ArticulatedBasePart>& baseParts,
                              const std::vector<ArticulatedLimb>& limbs);

  /// Phase 5: the free velocities (without contacts or limits) from the effectors and the
  /// accumulated forces, which are then reset; `v` and `omega` become the base's. If `r` or
  /// `alpha` were changed by hand since the last step, the agent is first moved there.
  void computeDerivativesWithoutContacts() override;
  /// Phase 8: moves the base and the joints by the final velocities for @p dt, then places the
  /// shapes and copies the base's pose to `r` and `alpha`.
  void integrate(real dt) override;

  /// The velocity @p force reads from the free velocities: a contact point's along its
  /// direction, or `torque * qdot` of a joint.
  [[nodiscard]] real velocityAlong(const UnitForce& force) const override;
  /// `K_ij` by one test force per column (ArticulatedBody::respond()), O(N + n) per column;
  /// symmetrized, `(K_ij + K_ji) / 2`, to remove round-off asymmetry.
  void responseMatrix(std::span<const UnitForce> forces, std::span<real> matrix) override;
  /// Final velocities: the free ones plus the response to all @p forces at once (one O(N)
  /// pass); records the joint-limit torques.
  void applyConstraintForces(std::span<const UnitForce> forces,
                             std::span<const real> magnitudes) override;
  /// For each limited joint at or beyond a limit, or that could reach it this step (turning at
  /// its free rate or at its last step's rate, plus limitMargin): at the lower limit
  /// `qdot >= (qMin - q) / dt` (torque +1), at the upper `-qdot >= (q - qMax) / dt` (torque -1).
  /// The target lets a joint reach its limit within the step, and brings one beyond it back in
  /// one step.
  void collectInternalConstraints(real dt, std::vector<InternalConstraint>& out) override;

  [[nodiscard]] std::string typeName() const override { return "ArticulatedAgentQuasistatic"; }
  /// ArticulatedAgentBase::saveState(), then the last step's rates and free velocities.
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;

 private:
  [[nodiscard]] ArticulatedBody::TestForce toTestForce(const UnitForce& force) const;
  void convert(std::span<const UnitForce> forces);
  /// This step's velocities without contacts (u0): velocities_ until the contact solver
  /// changes them, free_ after.
  [[nodiscard]] const ArticulatedBody::Output& freeVelocities() const;

  ArticulatedBody::Output free_;      ///< u0, once saved (freeSaved_)
  bool freeSaved_ = false;            ///< whether free_ holds this step's u0
  bool limitsActed_ = false;          ///< whether a limit torque is non-zero
  bool servoTorquesSet_ = false;      ///< whether servoTorques_ may hold a non-zero torque
  real dampingTimestep_ = 0;          ///< the time step the joint dampings were set for (s)
  ArticulatedBody::Output response_;  ///< a test force's response
  std::vector<real> torques_;         ///< this step's joint torques with the servos', if any
  std::vector<real> lastRates_;       ///< the last step's final joint rates
  std::vector<ArticulatedBody::TestForce> tests_;  ///< the simulator's unit forces, converted
};

}  // namespace thyrix
