/// @file ArticulatedBodyPasses.cpp
/// @brief The passes of ArticulatedBody's quasistatic articulated-body algorithm: the inward
/// sweep (articulated inertias and bias forces, leaves to root) and the outward pass (joint
/// rates and velocities, root to leaves). The state, kinematics, solve() and respond() are in
/// ArticulatedBody.cpp, with the conventions (frames, world-aligned axes, spatial vectors).
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/SpatialAlgebra.h>

#include <algorithm>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace thyrix {

// --- articulated inertias ---------------------------------------------------------------------
//
// Link i's joint equations, folded with X_i. Let D_i = d_i + c_i (the joint inertia plus its
// damping), U_i = (d_i, b_i) with b_i the linear part, r_i = shift_[i] the joint seen from the
// parent's origin and g_i = r_i x b_i. Writing out X_i^T (...) X_i and X_i^T (...) for the pure
// translation X_i (SpatialAlgebra.h) gives, with A the lower-right 2 x 2 block of D^A_i and
// h_i = (-r_y, r_x):
//
//   inertia passed to the parent:  [ h^T A h + c - k^2 / D      (A h + b k / D)^T ]
//                                  [ A h + b k / D              A - b b^T / D     ],  k = c - g
//   bias passed to the parent:     ( alpha p.n + r x p.f + gamma tau,  p.f + beta u )
//   joint rate:                    qdot = u / D - gamma omega' - beta . v'
//
// with u = tau - p.n, alpha = k / D, gamma = (d + g) / D and beta = b / D, (n, f) the parts of
// p^A_i and (omega', v') the parent's velocity at its own origin. The same algebra as
// Table 7.1, but the coefficients alpha, beta, gamma depend on the configuration only: the
// inertia pass computes them once, and each bias and outward pass, which are chains of
// dependent operations from link to link, does only a few multiply-adds per link.

template <bool damped>
inline SymmetricMatrix3 ArticulatedBody::articulateJoint(std::size_t i,
                                                         const SymmetricMatrix3& da) {
  // Featherstone 2008, section 7.3 and Table 7.1: U_i = I^A_i S_i, d_i = S_i^T U_i, and the
  // parent receives I^a_i = X_i^T (I^A_i - U_i U_i^T / d_i) X_i. A damped joint (torque
  // -c_i qdot_i) has S_i^T f_i = tau_i - c_i qdot_i, so its rate solves
  // (d_i + c_i) qdot_i = u_i - U_i^T v'_i and d_i + c_i replaces d_i in both places; the first
  // row of the bracket is then U_i^T c_i / (d_i + c_i), zero for an undamped joint. S = (1, 0,
  // 0) picks the first column of D^A_i. Written out as in the table above.
  //
  // Without damping (c = 0, every joint of the body: `damped` false) the additions of c are
  // left out: adding zero changes no bit (but a zero's sign), and the division waits for one
  // addition less.
  //
  // With h = (-r_y, r_x) the products with h are written with r's own coordinates:
  // `a (-y) + c` is `c - a y` bit for bit (a product's sign is its factors', and x + (-y) is
  // x - y), so no negation is computed. Likewise k = -g undamped: k k = g g, and b k = -(b g).
  const Vector2 r = shift_[i];
  const Vector2 b{da.xy, da.xz};
  const real g = cross(r, b);
  const Vector2 ah{da.yz * r.x - da.yy * r.y, da.zz * r.x - da.yz * r.y};  // A h
  const real hah = r.x * ah.y - r.y * ah.x;                                // h . A h
  SymmetricMatrix3 passed;
  real inverseD;
  Vector2 beta;
  if constexpr (damped) {
    const real c = jointDamping_[i];
    inverseD = 1 / (da.xx + c);
    const real k = c - g;
    passed.xx = hah + c - k * k * inverseD;
    beta = b * inverseD;
    terms_[i] = {inverseD, k * inverseD, (da.xx + g) * inverseD, beta};
    passed.xy = ah.x + beta.x * k;
    passed.xz = ah.y + beta.y * k;
  } else {
    inverseD = 1 / da.xx;
    passed.xx = hah - g * g * inverseD;
    beta = b * inverseD;
    terms_[i] = {inverseD, -g * inverseD, (da.xx + g) * inverseD, beta};
    passed.xy = ah.x - beta.x * g;
    passed.xz = ah.y - beta.y * g;
  }
  passed.yy = da.yy - beta.x * b.x;
  passed.yz = da.yz - beta.x * b.y;
  passed.zz = da.zz - beta.y * b.y;
  return passed;
}

inline Vector3 ArticulatedBody::passBias(std::size_t i, const Vector3& pa, real tau) {
  // Table 7.1, second loop: u_i = tau_i - S_i^T p^A_i, and the parent receives
  // p^a_i = X_i^T (p^A_i + U_i u_i / (d_i + c_i)), written out as in the table above.
  const JointTerms& t = terms_[i];
  const real ui = tau - pa.x;
  jointBias_[i] = ui;
  const Vector2 f = linearPart(pa);
  return forceVector(t.alpha * pa.x + cross(shift_[i], f) + t.gamma * tau, f + t.beta * ui);
}

template <class Real>
bool ArticulatedBody::plainChainInwardPass(const Wrenches& wrenches, const Real* torques,
                                           SymmetricMatrix3& inertiaCarried, Vector3& biasCarried) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<Real, double>) {
    // The operations of inwardPass()'s chainStep (with inertias, undamped, with wrenches) on
    // the same values in the same order, so the same bits, with the pairs that go together in
    // one SSE2 register: (xy, xz) and (yy, zz) of the inertia, the force of the bias, beta, A h.
    // Held as scalars, the terms of both chains did not fit in the 16 registers: GCC kept some
    // on the stack, the carried xx among them (measured: the pass 20% slower than in pairs).
    static_assert(std::is_standard_layout_v<Vector2> && sizeof(Vector2) == 2 * sizeof(Real) &&
                      std::is_standard_layout_v<Vector3> && sizeof(Vector3) == 3 * sizeof(Real),
                  "vectors are read as their coordinates");
    // Two coordinates from @p first on (a Vector2, or a Vector3's force).
    const auto pairOf = [](const real& first) {
      return _mm_loadu_pd(reinterpret_cast<const Real*>(&first));
    };
    const auto low = [](__m128d pair) { return _mm_cvtsd_f64(pair); };
    const auto high = [](__m128d pair) { return _mm_cvtsd_f64(_mm_unpackhi_pd(pair, pair)); };
    const auto swapped = [](__m128d pair) { return _mm_shuffle_pd(pair, pair, 1); };
    // a.x b.y - a.y b.x from (a.x, a.y) and (b.x, b.y)
    const auto crossOf = [&](__m128d a, __m128d b) {
      const __m128d products = _mm_mul_pd(a, swapped(b));
      return low(products) - high(products);
    };
    const __m128d negateLow = _mm_set_pd(0.0, -0.0);
    const __m128d zero = _mm_setzero_pd();
    const LinkMass* const links = linkMasses_.data();
    const Vector2* const centres = comOffset_.data() + 1;  // link i's at i
    const Vector2* const shifts = shift_.data();
    JointTerms* const terms = terms_.data();
    Real* const jointBias = jointBias_.data();
    // In two copies: a wrench per link, or the same on every link (@p uniform true), whose
    // force and its swapped pair are then read once, before the loop.
    const auto sweep = [&](auto uniform) {
      constexpr bool sameWrench = decltype(uniform)::value;
      // Link i's at i (unless sameWrench: perBody is then null).
      const Vector3* const perLink = sameWrench ? nullptr : wrenches.perBody + 1;
      const Real uniformMoment = wrenches.link.x;
      const __m128d uniformForce = pairOf(wrenches.link.y);
      const __m128d uniformForceSwapped = swapped(uniformForce);
      // The carried inertia and bias.
      Real xx = 0;
      __m128d xyXz = zero;
      __m128d yyZz = zero;
      // In the low lane. It starts at +0 and is never -0 (x - y is -0 only for x = -0), so
      // yz is 0 + yz (SymmetricMatrix3's sum of the own inertia's yz = 0 and the carried one)
      // bit for bit, without the addition.
      __m128d yz = zero;
      Real moment = 0;
      __m128d force = zero;
      for (std::size_t i = links_.size(); i-- > 0;) {
        // da = ownInertia(i) + carried
        const Real m = links[i].mass;
        const __m128d centre = pairOf(centres[i].x);
        const __m128d mm = _mm_set1_pd(m);
        const Real dxx = links[i].inertiaAboutJoint + xx;
        // (-m c.y, m c.x) + (xy, xz)
        const __m128d b = _mm_add_pd(_mm_mul_pd(_mm_xor_pd(mm, negateLow), swapped(centre)), xyXz);
        const __m128d dyyZz = _mm_add_pd(mm, yyZz);
        // articulateJoint<false>(i, da)
        const __m128d r = pairOf(shifts[i].x);
        const Real g = crossOf(r, b);
        // A h = (yz r.x - yy r.y, zz r.x - yz r.y)
        const __m128d ah =
            _mm_sub_pd(_mm_mul_pd(_mm_move_sd(dyyZz, yz), _mm_set1_pd(shifts[i].x)),
                       _mm_mul_pd(_mm_unpacklo_pd(dyyZz, yz), _mm_set1_pd(shifts[i].y)));
        const Real hah = crossOf(r, ah);
        const Real inverseD = 1 / dxx;
        xx = hah - g * g * inverseD;
        const __m128d beta = _mm_mul_pd(b, _mm_set1_pd(inverseD));
        const Real alpha = -g * inverseD;
        const Real gamma = (dxx + g) * inverseD;
        JointTerms& t = terms[i];
        t.inverseD = inverseD;
        t.alpha = alpha;
        t.gamma = gamma;
        _mm_storeu_pd(reinterpret_cast<Real*>(&t.beta), beta);
        xyXz = _mm_sub_pd(ah, _mm_mul_pd(beta, _mm_set1_pd(g)));
        yyZz = _mm_sub_pd(dyyZz, _mm_mul_pd(beta, b));
        yz = _mm_sub_sd(yz, _mm_mul_sd(beta, _mm_unpackhi_pd(b, b)));
        // passBias(i, carried - translateForceBack(w, c), tau); crossOf(centre, wf) written
        // out to use the swapped force kept
        Real wn;
        __m128d wf;
        __m128d wfSwapped;
        if constexpr (sameWrench) {
          wn = uniformMoment;
          wf = uniformForce;
          wfSwapped = uniformForceSwapped;
        } else {
          wn = perLink[i].x;
          wf = pairOf(perLink[i].y);
          wfSwapped = swapped(wf);
        }
        const __m128d centreCrossWf = _mm_mul_pd(centre, wfSwapped);
        const Real pn = moment - (wn + (low(centreCrossWf) - high(centreCrossWf)));
        const __m128d pf = _mm_sub_pd(force, wf);
        const Real tau = torques[i];
        const Real u = tau - pn;
        jointBias[i] = u;
        moment = alpha * pn + crossOf(r, pf) + gamma * tau;
        force = _mm_add_pd(pf, _mm_mul_pd(beta, _mm_set1_pd(u)));
      }
      inertiaCarried = {xx, low(xyXz), high(xyXz), low(yyZz), low(yz), high(yyZz)};
      biasCarried = {moment, low(force), high(force)};
    };
    if (wrenches.uniform)
      sweep(std::true_type{});
    else
      sweep(std::false_type{});
    return true;
  }
#endif
  static_cast<void>(wrenches);
  static_cast<void>(torques);
  static_cast<void>(inertiaCarried);
  static_cast<void>(biasCarried);
  return false;
}

template <bool withInertias, bool damped, bool general>
void ArticulatedBody::inwardPass(const Wrenches& wrenches, const real* torques) {
  // Leaves to root: reverse index order visits children before parents. A link's terms go to
  // its parent's slot, except when the parent is the next link visited (slot i: within a
  // limb, the usual case): they are then carried to it in registers. Each link waits for its
  // children, and a round trip through memory would lengthen every link's step. So a body's
  // slot holds only what its other children have passed (and, in bias_, respond()'s test
  // forces), and is read only if it can hold something (gathers_): a chain's links touch no
  // slot. A body's own terms are added when it is visited: its inertia about its frame origin
  // (ALGORITHMS.md section 2), and p^A_i starts as -f_ext,i about the frame origin (Table 7.1
  // without the v x* I v term), the wrench being given about the centre of mass: it is
  // subtracted from the children's terms when the slot is empty, which gives the same bits as
  // adding its negation. Only the base's articulated inertia is needed afterwards: the links'
  // are stored when `general` (for articulatedInertia()).
  const bool anyWrench = wrenches.any();
  const auto ownBias = [&](std::size_t slot) {
    return !anyWrench ? Vector3{} : -translateForceBack(wrenches.at(slot), comOffset_[slot]);
  };
  const auto carriedBias = [&](std::size_t slot, const Vector3& carried) {
    return !anyWrench ? carried : carried - translateForceBack(wrenches.at(slot), comOffset_[slot]);
  };
  // Link i's spatialInertia() about its joint, with the xx that does not change as it turns
  // (LinkMass): the same in every path, so that they all give the same bits.
  const auto ownInertia = [&](std::size_t i) {
    const LinkMass& link = linkMasses_[i];
    const Vector2 c = comOffset_[i + 1];
    return SymmetricMatrix3{
        link.inertiaAboutJoint, -link.mass * c.y, link.mass * c.x, link.mass, 0, link.mass};
  };
  SymmetricMatrix3 inertiaCarried;
  Vector3 biasCarried;
  // Link i within a chain (the parent is the next link visited, no other child): the terms
  // come in registers and go out in registers, with no slot to look at. In two copies, with
  // and without wrenches (carriedBias() without its test).
  const auto chainStep = [&](std::size_t i, auto withWrenches) {
    const std::size_t self = i + 1;
    if constexpr (withInertias) {
      inertiaCarried = articulateJoint<damped>(i, ownInertia(i) + inertiaCarried);
    }
    Vector3 pa = biasCarried;
    if constexpr (decltype(withWrenches)::value)
      pa = biasCarried - translateForceBack(wrenches.at(self), comOffset_[self]);
    biasCarried = passBias(i, pa, torques[i]);
  };
  // A plain chain (every link in a chain): a loop without a test per link.
  const bool plainChain = !general && allInChain_;
  bool done = false;  // by plainChainInwardPass()
  if constexpr (withInertias && !damped)
    done = plainChain && anyWrench &&
           plainChainInwardPass<real>(wrenches, torques, inertiaCarried, biasCarried);
  if (plainChain && !done) {
    if (anyWrench) {
      for (std::size_t i = links_.size(); i-- > 0;) chainStep(i, std::true_type{});
    } else {
      for (std::size_t i = links_.size(); i-- > 0;) chainStep(i, std::false_type{});
    }
  }
  for (std::size_t i = plainChain ? 0 : links_.size(); i-- > 0;) {
    const std::size_t self = i + 1;
    if (!general && inChain_[i] != 0) {
      // chainStep(i, ...) with the test of carriedBias() (measured: in this loop, calls of
      // chainStep cost the plain chain's loop above 2 instructions a link).
      if constexpr (withInertias) {
        inertiaCarried = articulateJoint<damped>(i, ownInertia(i) + inertiaCarried);
      }
      biasCarried = passBias(i, carriedBias(self, biasCarried), torques[i]);
      continue;
    }
    const std::size_t parent = parentSlot_[i];
    const bool carry = parent == i;
    const bool gathers = gathers_[self] != 0;
    if constexpr (withInertias) {
      SymmetricMatrix3 da = ownInertia(i);
      if (gathers) da = da + articulatedInertia_[self];
      da = da + inertiaCarried;
      if constexpr (general) articulatedInertia_[self] = da;
      const SymmetricMatrix3 passed = articulateJoint<damped>(i, da);
      if (carry) {
        inertiaCarried = passed;
      } else {
        articulatedInertia_[parent] = articulatedInertia_[parent] + passed;
        inertiaCarried = {};
      }
    }
    const Vector3 pa = general || gathers ? ownBias(self) + bias_[self] + biasCarried
                                          : carriedBias(self, biasCarried);
    const Vector3 passed = passBias(i, pa, torques[i]);
    if (carry) {
      biasCarried = passed;
    } else {
      bias_[parent] += passed;
      biasCarried = {};
    }
  }
  // The first link is always carried (slot 0 is the base): the base gets its last terms here.
  const bool baseGathers = gathers_[0] != 0;
  if constexpr (withInertias) {
    SymmetricMatrix3 da = SymmetricMatrix3::diagonal(baseInertia_, baseMass_, baseMass_);
    if (baseGathers) da = da + articulatedInertia_[0];
    articulatedInertia_[0] = da + inertiaCarried;
  }
  bias_[0] =
      general || baseGathers ? ownBias(0) + bias_[0] + biasCarried : carriedBias(0, biasCarried);
}

void ArticulatedBody::computeArticulatedInertias() {
  // The bias pass comes along (its result is not used): one sweep, and no second copy of it.
  std::fill(bias_.begin(), bias_.end(), Vector3{});
  clearGatheringSlots(articulatedInertia_);
  std::fill(jointTorque_.begin(), jointTorque_.end(), real(0));
  if (dampedJoints_ > 0)
    inwardPass<true, true, true>({}, jointTorque_.data());
  else
    inwardPass<true, false, true>({}, jointTorque_.data());
  inertiasStale_ = false;
}

// --- the passes of solve() and respond() ------------------------------------------------------

template <bool general>
void ArticulatedBody::biasAndOutwardPasses(const Wrenches& wrenches, const real* torques,
                                           Output& out) {
  // Leaves to root. The articulated inertias and the bias forces are both built from the
  // leaves, and link i's bias needs only its own terms: when the configuration has changed,
  // one sweep does both, so the two dependency chains run side by side.
  if (inertiasStale_) {
    clearGatheringSlots(articulatedInertia_);
    if (dampedJoints_ > 0)
      inwardPass<true, true, general>(wrenches, torques);
    else
      inwardPass<true, false, general>(wrenches, torques);
    inertiasStale_ = false;
  } else {
    inwardPass<false, false, general>(wrenches, torques);
  }

  // The free-floating base: nothing acts on it from outside the tree, so 0 = D^A_0 v_0 + p^A_0
  // (Featherstone 2008, chapter 9, free-floating bases, with v for a). D^A_0 is symmetric
  // positive definite: the base's own inertia is, and every child adds a positive
  // semi-definite term.
  Vector3 v0{};
  if (!baseFixed_) v0 = articulatedInertia_[0].solve(-bias_[0]);
  originVelocity_[0] = v0;
  out.velocities[0] = v0;  // the base frame's origin is its centre of mass

  // Outward pass, root to leaves (Table 7.1, third loop): v'_i = X_i v_parent,
  // qdot_i = (u_i - U_i^T v'_i) / (d_i + c_i), v_i = v'_i + S_i qdot_i, with qdot_i as in the
  // table above. The parent's velocity is carried in registers when it is the body just
  // visited (slot i), as in the inward pass.
  // Link i's step from its parent's velocity @p vp at the parent's origin: its own there.
  const auto outwardStep = [&](std::size_t i, const Vector3& vp) {
    const std::size_t self = i + 1;
    const JointTerms& t = terms_[i];
    const real omega = angularPart(vp);
    const real rate = jointBias_[i] * t.inverseD;
    const real betaV = t.beta.dot(linearPart(vp));
    const real qdot = rate - t.gamma * omega - betaV;
    Vector3 v = translateMotion(vp, shift_[i]);
    // The link's angular velocity omega' + qdot_i, written as alpha_i omega' + u_i / D_i -
    // beta_i . v' (1 - gamma = alpha): the next link then waits three operations on omega'
    // (not four) and one after beta . v' (not two).
    v.x = t.alpha * omega + rate - betaV;
    out.jointRates[i] = qdot;
    // The centre of mass moves with the body point there: v_O + omega x c.
    out.velocities[self] = translateMotion(v, comOffset_[self]);
    return v;
  };
  Vector3 previous = v0;
  if (allInChain_) {  // a plain chain: every parent is the link just visited, none gathers
    if (links_.empty()) return;
    // outwardStep() with beta_i . v'_i written out by one link: v'_i's linear part is the
    // grandparent's plus omega'' x r_{i-1}, so beta_i . v'_i = beta_i . (grandparent's) +
    // omega'' (r_{i-1} x beta_i). Link i then waits on its parent's omega' for a multiply and
    // an add only (not also a subtraction); the longest chain left, through the linear
    // velocities, takes about 7 cycles a link instead of 9 (measured: chain1000 3% faster).
    // The joint rate is the same sum less gamma omega'. The results differ in the last bits.
    Vector3 grandparent = v0;
    previous = outwardStep(0, v0);
    for (std::size_t i = 1; i < links_.size(); ++i) {
      const std::size_t self = i + 1;
      const JointTerms& t = terms_[i];
      const real omega = angularPart(previous);
      const real rate = jointBias_[i] * t.inverseD;
      const real partial = (rate - t.beta.dot(linearPart(grandparent))) -
                           cross(shift_[i - 1], t.beta) * angularPart(grandparent);
      Vector3 v = translateMotion(previous, shift_[i]);
      v.x = t.alpha * omega + partial;
      out.jointRates[i] = partial - t.gamma * omega;
      out.velocities[self] = translateMotion(v, comOffset_[self]);
      grandparent = previous;
      previous = v;
    }
    return;
  }
  for (std::size_t i = 0; i < links_.size(); ++i) {
    const std::size_t parent = parentSlot_[i];
    Vector3 vp = previous;
    if (parent != i) vp = originVelocity_[parent];
    previous = outwardStep(i, vp);
    if (gathers_[i + 1] != 0) originVelocity_[i + 1] = previous;  // read by a child not carried
  }
}

template void ArticulatedBody::biasAndOutwardPasses<false>(const Wrenches&, const real*, Output&);
template void ArticulatedBody::biasAndOutwardPasses<true>(const Wrenches&, const real*, Output&);

}  // namespace thyrix
