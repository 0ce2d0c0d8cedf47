/// @file ArticulatedBodyPasses.cpp
/// @brief The passes of ArticulatedBody's quasistatic articulated-body algorithm: the inward
/// sweep (articulated inertias and bias forces, leaves to root) and the outward pass (joint
/// rates and velocities, root to leaves). The state, kinematics, solve() and respond() are in
/// ArticulatedBody.cpp, with the conventions (frames, world-aligned axes, spatial vectors).
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/SpatialAlgebra.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>

#include <algorithm>
#include <type_traits>

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

void ArticulatedBody::plainChainInwardPass(const Wrenches& wrenches, const real* torques,
                                           SymmetricMatrix3& inertiaCarried, Vector3& biasCarried) {
  {
    using Real = real;
    using Pair = simd::Wide<real, 2>;
    // inwardPass()'s chainStep (with inertias, undamped) in pairs: (xy, xz) and (yy, zz)
    // of the inertia, the force of the bias, beta, A h: held as scalars, the terms of both
    // chains do not fit in the 16 registers.
    //
    // articulateJoint<false>'s algebra, re-associated (so not chainStep's bits: the chain
    // without wrenches runs here too, to keep the bits of zero wrenches). Written plainly, each
    // link waits on two long chains: the division's (d -> 1/d -> h.Ah - g^2/d -> own + that ->
    // next d) and the one through beta, the carried (yy, zz), yz, A h and h.Ah into the next
    // d. Here the child builds the parent's inertia D_p = M_p + D_i - b b^T / d_i with the
    // parent's own terms M_p added first and 1 / d_i multiplied last:
    //   d_p = (own_p + h.Ah) - (g g) / d_i,   (yy, zz)_p = (m_p + (yy, zz)) - (b b) / d_i,
    //   yz_p = yz - (b_x b_y) / d_i,          b_p = (own b_p + A h) - beta g
    // so the next division waits for one product and one difference after this one, and
    // the lower block's chain for one product (not beta's and then its own).
    static_assert(std::is_standard_layout_v<Vector2> && sizeof(Vector2) == 2 * sizeof(Real) &&
                      std::is_standard_layout_v<Vector3> && sizeof(Vector3) == 3 * sizeof(Real),
                  "vectors are read as their coordinates");
    const std::size_t n = links_.size();
    if (n == 0) {
      inertiaCarried = {};
      biasCarried = {};
      return;
    }
    // What a sweep reads and writes (passed on to the copy compiled for AVX).
    struct Sweep {
      const Wrenches* wrenches;
      const Real* torques;
      const LinkMass* links;
      const Vector2* centres;  // link i's at i
      const Vector2* shifts;
      JointTerms* terms;
      Real* jointBias;
      std::size_t n;
      SymmetricMatrix3* inertiaCarried;
      Vector3* biasCarried;
    };
    const Sweep sweepTerms{
        &wrenches,       torques,       linkMasses_.data(), comOffset_.data() + 1,
        shift_.data(),   terms_.data(), jointBias_.data(),  n,
        &inertiaCarried, &biasCarried};
    // In three copies (@p kind): no wrench (0), a wrench per link (1), or the same on every
    // link (2).
    const auto sweep = [](const Sweep& w, auto kind) THYRIX_LAMBDA_ALWAYS_INLINE {
      constexpr int wrenchKind = decltype(kind)::value;
      // In locals: the stores to terms and jointBias might otherwise be taken to change them.
      const LinkMass* const links = w.links;
      const Vector2* const centres = w.centres;
      const Vector2* const shifts = w.shifts;
      JointTerms* const terms = w.terms;
      const Real* const jointTorques = w.torques;
      Real* const jointBias = w.jointBias;
      // Two coordinates from @p first on (a Vector2, or a Vector3's force).
      const auto pairOf = [](const real& first) { return Pair::load(&first); };
      const auto low = [](Pair pair) { return pair.at(0); };
      const auto high = [](Pair pair) { return pair.at(1); };
      // a.x b.y - a.y b.x from (a.x, a.y) and (b.x, b.y)
      const auto crossOf = [&](Pair a, Pair b) {
        const Pair products = a * simd::swapped(b);
        return low(products) - high(products);
      };
      // A h = (yz r.x - yy r.y, zz r.x - yz r.y) from (yy, zz), (yz, yz) and r
      const auto aTimesH = [](Pair yyZz, Pair yz, Real rx, Real ry) {
        return simd::highs(yz, yyZz) * Pair::broadcast(rx) -
               simd::lows(yyZz, yz) * Pair::broadcast(ry);
      };
      const Pair negateLow = simd::pair(real(-0.0), real(0.0));
      const Pair zero = Pair::broadcast(0);
      // (-m c.y, m c.x), the (xy, xz) of link i's own inertia
      const auto ownB = [&](std::size_t i) {
        return flipSigns(Pair::broadcast(links[i].mass), negateLow) *
               simd::swapped(pairOf(centres[i].x));
      };
      const Vector3* const perLink = wrenchKind == 1 ? w.wrenches->perBody + 1 : nullptr;
      // The uniform wrench is read in the loop (from memory, as an operand): kept in
      // registers, it would leave too few for the terms carried.
      const Vector3& uniform = w.wrenches->link;
      // Link i's articulated inertia D_i before its joint, as the child left it: xx, b = (xy,
      // xz), (yy, zz), and yz in both lanes (+0 at the leaf and never -0, as x - y is -0 only for
      // x = -0, so yz is 0 + yz bit for bit without the addition).
      const std::size_t leaf = w.n - 1;
      Real dxx = links[leaf].inertiaAboutJoint;
      Pair b = ownB(leaf);
      Pair yyZz = Pair::broadcast(links[leaf].mass);
      Pair yz = zero;
      Real moment = 0;
      Pair force = zero;
      // Link i >= 1, whose parent is link p = i - 1.
      const auto step = [&](std::size_t i) THYRIX_LAMBDA_ALWAYS_INLINE {
        const std::size_t p = i - 1;
        const Real inverseD = 1 / dxx;
        // What does not wait for the division first, each term used as soon as it is known:
        // GCC allocates registers in about this order, and terms kept longer go to the stack
        // (h.Ah, on the division's chain, and the carried force).
        const Pair r = pairOf(shifts[i].x);
        const Real g = crossOf(r, b);
        const Real gg = g * g;
        const Pair ah = aTimesH(yyZz, yz, shifts[i].x, shifts[i].y);
        const Real hah = crossOf(r, ah);
        // The parent's terms as above, with its own added.
        const Real ownPlusHah = links[p].inertiaAboutJoint + hah;
        const Pair bb = b * b;                   // (xy xy, xz xz)
        const Pair bxBy = b * simd::swapped(b);  // xy xz in both lanes
        const Pair ownYyZz = Pair::broadcast(links[p].mass) + yyZz;
        const Pair ownAh = ownB(p) + ah;
        const Pair inverseDs = Pair::broadcast(inverseD);
        const Pair beta = b * inverseDs;
        const Real alpha = -g * inverseD;
        const Real gamma = (dxx + g) * inverseD;
        const Pair betaG = beta * Pair::broadcast(g);
        dxx = ownPlusHah - gg * inverseD;
        yyZz = ownYyZz - bb * inverseDs;
        yz = yz - bxBy * inverseDs;
        b = ownAh - betaG;
        JointTerms& t = terms[i];
        t.inverseD = inverseD;
        t.alpha = alpha;
        t.gamma = gamma;
        beta.store(&t.beta.x);
        // passBias(i, carried - translateForceBack(w, c), tau); crossOf(centre, wf) written
        // out to use the swapped force. The shift is read again: kept from the start, it would
        // take a register the bias terms need.
        Real pn = moment;
        Pair pf = force;
        if constexpr (wrenchKind != 0) {
          const Vector3& wrench = wrenchKind == 2 ? uniform : perLink[i];
          const Pair wf = pairOf(wrench.y);
          const Pair centreCrossWf = pairOf(centres[i].x) * simd::swapped(wf);
          pn = moment - (wrench.x + (low(centreCrossWf) - high(centreCrossWf)));
          pf = force - wf;
        }
        const Real tau = jointTorques[i];
        const Real u = tau - pn;
        jointBias[i] = u;
        moment = alpha * pn + crossOf(pairOf(shifts[i].x), pf) + gamma * tau;
        force = pf + beta * Pair::broadcast(u);
      };
      for (std::size_t i = leaf; i > 0; --i) step(i);
      // Link 0's articulated inertia and the bias its child passes.
      *w.inertiaCarried = {dxx, low(b), high(b), low(yyZz), low(yz), high(yyZz)};
      *w.biasCarried = {moment, low(force), high(force)};
    };
    // In VEX form with AVX: the same operations (no fused multiply-add), so the same bits,
    // without the register copies of SSE2's two-operand form.
    const auto run = [&](auto kind) {
#if defined(THYRIX_AVX_DISPATCH)
      const auto sweepAvx = [&sweep](const Sweep& w, auto k) __attribute__((target("avx"))) {
        sweep(w, k);
      };
      if (processorHasAvx()) {
        sweepAvx(sweepTerms, kind);
        return;
      }
#endif
      sweep(sweepTerms, kind);
    };
    if (!wrenches.any())
      run(std::integral_constant<int, 0>{});
    else if (wrenches.uniform)
      run(std::integral_constant<int, 2>{});
    else
      run(std::integral_constant<int, 1>{});
    // Link 0, whose parent is the base, as chainStep does it: its step in the loop is the same
    // operations without a parent's own terms to add.
    Vector3 pa = biasCarried;
    if (wrenches.any()) pa = biasCarried - translateForceBack(wrenches.at(1), comOffset_[1]);
    inertiaCarried = articulateJoint<false>(0, inertiaCarried);
    biasCarried = passBias(0, pa, torques[0]);
  }
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
  // (docs/Algorithms.md section 2), and p^A_i starts as -f_ext,i about the frame origin (Table 7.1
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
  // (LinkMass): the same in chainStep and the general loop, so that they give the same bits.
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
  // (In double only: a float build keeps chainStep's association, and so the trajectories of
  // float's tests, one of which compares the kinematics' cos and sin with the library's.)
  if constexpr (withInertias && !damped && std::is_same_v<real, double>) {
    if (plainChain) {
      plainChainInwardPass(wrenches, torques, inertiaCarried, biasCarried);
      done = true;
    }
  }
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
      // chainStep(i, ...) with the test of carriedBias(), written out: calls of chainStep here
      // too make the compiler treat the plain chain's loop above less well.
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
    // an add only (not also a subtraction), and the longest chain left runs through the
    // linear velocities.
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
