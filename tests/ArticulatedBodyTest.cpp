// The quasistatic articulated-body algorithm (ThyrixPro/ArticulatedBody) against an independent
// dense reference written here: generalized velocities u = (base vx, vy, omega, qdot_1..N), the
// Jacobian J from u to every body's (centre-of-mass velocity, omega) built from kinematics
// computed here, D = blockdiag(m, m, I), and (J^T D J) u = J^T F + (0, 0, 0, tau) solved by a
// dense Cholesky factorization in long double, whatever `real` is. Also: a two-body case worked by
// hand, zero input giving exactly zero motion, Kokkevis test forces against solve() and the
// constraint matrix K against J_c (J^T D J)^-1 J_c^T, validation, and no allocation.
//
// This executable links support/AllocationCounter.cpp to count allocations around solve() and
// respond().

#include "TestTolerances.h"
#include "support/AllocationCounter.h"
#include "support/SolverCases.h"

#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixPro/ArticulatedBody.h>
#include <ThyrixPro/ArticulatedLink.h>
#include <ThyrixPro/SpatialAlgebra.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <numbers>
#include <string>
#include <vector>

namespace thyrix {
namespace {

using test::isFloat;
using test::tight;

constexpr real kNaN = std::numeric_limits<real>::quiet_NaN();
constexpr real kInf = std::numeric_limits<real>::infinity();

/// Uniform in [low, high) as a real.
real draw(MTRandom& random, double low, double high) {
  return static_cast<real>(random.uniform(low, high));
}

// ---------------------------------------------------------------------------------------------
// Random articulated bodies

enum class Shape { Chain, Tree };

/// Everything that defines one problem: the body, its state and its inputs.
struct Problem {
  real baseMass = 1;
  real baseInertia = 1;
  std::vector<ArticulatedLink> links;
  Vector2 basePosition;
  real baseAngle = 0;
  std::vector<real> q;
  std::vector<real> torques;
  std::vector<Vector3> wrenches;  // (torque about the centre of mass, fx, fy), base first

  [[nodiscard]] ArticulatedBody build() const {
    ArticulatedBody body(baseMass, baseInertia, links);
    body.setBasePose(basePosition, baseAngle);
    body.setJointAngles(q);
    return body;
  }
};

/// A random body of @p count links: a chain (each link on the previous one's tip, the first on
/// the base), or a branching tree (each link on the base or on a random earlier link, mostly at
/// its tip, sometimes elsewhere), with random geometry, centres of mass, masses, angles and
/// inputs.
Problem randomProblem(int count, Shape shape, std::uint32_t seed) {
  MTRandom random(seed);
  Problem p;
  p.baseMass = draw(random, 0.5, 4);
  p.baseInertia = draw(random, 0.1, 2);
  p.basePosition = {draw(random, -5, 5), draw(random, -5, 5)};
  p.baseAngle = draw(random, -4, 4);
  for (int i = 0; i < count; ++i) {
    ArticulatedLink link;
    if (shape == Shape::Chain) {
      link.parent = i - 1;
    } else {
      link.parent = static_cast<int>(random.integer(-1, i - 1));
    }
    link.length = draw(random, 0.2, 2);
    if (link.parent == ArticulatedLink::base) {
      link.jointPosition = {draw(random, -1, 1), draw(random, -1, 1)};
    } else {
      const ArticulatedLink& parent = p.links[static_cast<std::size_t>(link.parent)];
      link.jointPosition = random.bernoulli(0.7) ? parent.tip()
                                                 : Vector2{draw(random, 0, 1) * parent.length,
                                                           draw(random, -0.3, 0.3)};
    }
    link.centerOfMass = random.bernoulli(0.5) ? Vector2{link.length / 2, 0}
                                              : Vector2{draw(random, -0.2, 1.2) * link.length,
                                                        draw(random, -0.3, 0.3)};
    link.mass = draw(random, 0.2, 3);
    link.inertia = draw(random, 0.01, 1);
    p.links.push_back(link);
    p.q.push_back(draw(random, -3.2, 3.2));
    p.torques.push_back(draw(random, -1, 1));
  }
  for (int b = 0; b <= count; ++b)
    p.wrenches.push_back({draw(random, -1, 1), draw(random, -1, 1), draw(random, -1, 1)});
  return p;
}

// ---------------------------------------------------------------------------------------------
// The independent dense reference, in long double

/// The reference's scalar: long double, so that its own round-off is well below the
/// library's even for 50-link chains in double.
using Exact = long double;

struct Point {
  Exact x = 0, y = 0;
};

/// Kinematics from the definition: world angle, frame origin (joint) and centre of mass of
/// every body, base first.
struct ReferenceKinematics {
  std::vector<Exact> angle;
  std::vector<Point> origin;
  std::vector<Point> com;

  explicit ReferenceKinematics(const Problem& p) {
    angle.push_back(p.baseAngle);
    origin.push_back({p.basePosition.x, p.basePosition.y});
    com.push_back(origin.back());
    for (std::size_t i = 0; i < p.links.size(); ++i) {
      const ArticulatedLink& l = p.links[i];
      const int parentSlot = l.parent + 1;
      const auto parent = static_cast<std::size_t>(parentSlot);
      const Exact a = angle[parent];
      const Point j{
          origin[parent].x + std::cos(a) * l.jointPosition.x - std::sin(a) * l.jointPosition.y,
          origin[parent].y + std::sin(a) * l.jointPosition.x + std::cos(a) * l.jointPosition.y};
      const Exact self = a + static_cast<Exact>(p.q[i]);
      angle.push_back(self);
      origin.push_back(j);
      com.push_back({j.x + std::cos(self) * l.centerOfMass.x - std::sin(self) * l.centerOfMass.y,
                     j.y + std::sin(self) * l.centerOfMass.x + std::cos(self) * l.centerOfMass.y});
    }
  }
};

/// A dense row-major matrix.
struct Dense {
  int rows = 0, cols = 0;
  std::vector<Exact> a;
  Dense(int r, int c) : rows(r), cols(c), a(static_cast<std::size_t>(r) * c, 0.0) {}
  Exact& operator()(int i, int j) { return a[static_cast<std::size_t>(i) * cols + j]; }
  Exact operator()(int i, int j) const { return a[static_cast<std::size_t>(i) * cols + j]; }
};

/// Solves S x = b for a symmetric positive definite S by Cholesky factorization.
std::vector<Exact> choleskySolve(Dense s, std::vector<Exact> b) {
  const int n = s.rows;
  for (int j = 0; j < n; ++j) {
    Exact d = s(j, j);
    for (int k = 0; k < j; ++k) d -= s(j, k) * s(j, k);
    EXPECT_GT(d, 0.0) << "the reference matrix is not positive definite";
    s(j, j) = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      Exact v = s(i, j);
      for (int k = 0; k < j; ++k) v -= s(i, k) * s(j, k);
      s(i, j) = v / s(j, j);
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < i; ++k) b[i] -= s(i, k) * b[k];
    b[i] /= s(i, i);
  }
  for (int i = n; i-- > 0;) {
    for (int k = i + 1; k < n; ++k) b[i] -= s(k, i) * b[k];
    b[i] /= s(i, i);
  }
  return b;
}

/// The dense system of a problem: J (rows vx, vy, omega of each body, base first; columns the
/// generalized velocities), D and the solution u.
struct DenseReference {
  bool baseFixed;
  int n;           // links
  int dofs;        // columns of J: 3 + n, or n with a fixed base
  int firstJoint;  // column of qdot_0
  ReferenceKinematics kin;
  Dense J;
  std::vector<Exact> d;  // diagonal of D
  Dense M;               // J^T D J

  DenseReference(const Problem& p, bool fixedBase)
      : baseFixed(fixedBase),
        n(static_cast<int>(p.links.size())),
        dofs(fixedBase ? n : n + 3),
        firstJoint(fixedBase ? 0 : 3),
        kin(p),
        J(3 * (n + 1), dofs),
        d(static_cast<std::size_t>(3 * (n + 1))),
        M(dofs, dofs) {
    for (int b = 0; b <= n; ++b) {
      const int row = 3 * b;
      const Point c = kin.com[b];
      const Exact m = b == 0 ? p.baseMass : p.links[b - 1].mass;
      const Exact inertia = b == 0 ? p.baseInertia : p.links[b - 1].inertia;
      d[row] = d[row + 1] = m;
      d[row + 2] = inertia;
      if (!baseFixed) {
        // The base's motion moves every body rigidly about the base's centre of mass.
        J(row, 0) = 1;
        J(row + 1, 1) = 1;
        J(row, 2) = -(c.y - kin.origin[0].y);
        J(row + 1, 2) = c.x - kin.origin[0].x;
        J(row + 2, 2) = 1;
      }
      // Each joint on the path from body b to the base turns b about that joint.
      for (int link = b - 1; link >= 0; link = p.links[link].parent) {
        const int col = firstJoint + link;
        const Point j = kin.origin[link + 1];
        J(row, col) = -(c.y - j.y);
        J(row + 1, col) = c.x - j.x;
        J(row + 2, col) = 1;
      }
    }
    for (int i = 0; i < dofs; ++i)
      for (int j = 0; j < dofs; ++j) {
        Exact sum = 0;
        for (int r = 0; r < J.rows; ++r) sum += J(r, i) * d[r] * J(r, j);
        M(i, j) = sum;
      }
  }

  /// u from torques and wrenches (torque about the centre of mass, fx, fy) per body.
  [[nodiscard]] std::vector<Exact> solve(const std::vector<real>& torques,
                                         const std::vector<Vector3>& wrenches) const {
    std::vector<Exact> rhs(static_cast<std::size_t>(dofs), 0.0);
    for (int i = 0; i < dofs; ++i) {
      Exact sum = 0;
      for (int b = 0; b <= n; ++b) {
        const Vector3& w = wrenches[b];
        sum += J(3 * b, i) * w.y + J(3 * b + 1, i) * w.z + J(3 * b + 2, i) * w.x;
      }
      rhs[i] = sum;
    }
    for (int i = 0; i < n; ++i) rhs[firstJoint + i] += torques[i];
    return choleskySolve(M, rhs);
  }

  /// The body velocities J u: (vx, vy, omega) per body, base first.
  [[nodiscard]] std::vector<Exact> bodyVelocities(const std::vector<Exact>& u) const {
    std::vector<Exact> v(static_cast<std::size_t>(J.rows), 0.0);
    for (int r = 0; r < J.rows; ++r)
      for (int i = 0; i < dofs; ++i) v[r] += J(r, i) * u[i];
    return v;
  }

  /// The Jacobian row of a constraint (the same description as the library's TestForce).
  [[nodiscard]] std::vector<Exact> constraintRow(const ArticulatedBody::TestForce& c) const {
    std::vector<Exact> row(static_cast<std::size_t>(dofs), 0.0);
    if (c.kind == ArticulatedBody::TestForce::Kind::JointTorque) {
      row[firstJoint + c.index] = c.torque;
      return row;
    }
    const int b = c.index + 1;
    const Point com = kin.com[b];
    // n . (v_com + omega x (p - com)) = n_x vx + n_y vy + (n . perp(p - com)) omega
    const Exact nx = c.direction.x, ny = c.direction.y;
    const Exact lever = nx * -(c.point.y - com.y) + ny * (c.point.x - com.x);
    for (int i = 0; i < dofs; ++i)
      row[i] = nx * J(3 * b, i) + ny * J(3 * b + 1, i) + lever * J(3 * b + 2, i);
    return row;
  }
};

/// The largest difference between the library's output and the reference, and the largest
/// reference value, over the base velocity, the joint rates and every link's velocity.
struct Comparison {
  Exact error = 0;
  Exact scale = 0;
  [[nodiscard]] Exact relative() const { return scale > 0 ? error / scale : error; }
};

Comparison compare(const ArticulatedBody::Output& out, const DenseReference& ref,
                   const std::vector<Exact>& u) {
  Comparison c;
  auto add = [&](real actual, Exact expected) {
    c.error = std::max(c.error, std::abs(static_cast<Exact>(actual) - expected));
    c.scale = std::max(c.scale, std::abs(expected));
  };
  const std::vector<Exact> v = ref.bodyVelocities(u);
  for (int b = 0; b <= ref.n; ++b) {
    const Vector3& w = out.velocities[static_cast<std::size_t>(b)];
    const std::size_t row = 3 * static_cast<std::size_t>(b);
    add(w.y, v[row]);
    add(w.z, v[row + 1]);
    add(w.x, v[row + 2]);
  }
  for (int i = 0; i < ref.n; ++i) add(out.jointRates[i], u[ref.firstJoint + i]);
  return c;
}

/// The relative tolerance of an O(N) result against the dense reference: round-off grows
/// with the depth of the tree (each level adds a few operations and the spread of lever arms
/// grows the condition of J^T D J), so it is scaled by the link count.
Exact relativeTolerance(int links) { return (isFloat ? 5e-7 : 2e-14) * (10 + links); }

// ---------------------------------------------------------------------------------------------
// Against the dense reference

struct Case {
  int links;
  Shape shape;
};

const Case kCases[] = {{1, Shape::Chain}, {2, Shape::Chain},  {2, Shape::Tree},
                       {5, Shape::Chain}, {5, Shape::Tree},   {20, Shape::Chain},
                       {20, Shape::Tree}, {50, Shape::Chain}, {50, Shape::Tree}};

TEST(ArticulatedBodyTest, KinematicsMatchTheDefinition) {
  for (const Case& k : kCases) {
    const Problem p = randomProblem(k.links, k.shape, 7u + static_cast<std::uint32_t>(k.links));
    const ArticulatedBody body = p.build();
    const ReferenceKinematics ref(p);
    const real tol = (isFloat ? real(2e-5) : real(1e-12)) * real(10 + k.links);
    for (int b = -1; b < k.links; ++b) {
      const int slot = b + 1;
      const auto s = static_cast<std::size_t>(slot);
      EXPECT_NEAR(body.origin(b).x, static_cast<double>(ref.origin[s].x), tol) << "body " << b;
      EXPECT_NEAR(body.origin(b).y, static_cast<double>(ref.origin[s].y), tol) << "body " << b;
      EXPECT_NEAR(body.centerOfMass(b).x, static_cast<double>(ref.com[s].x), tol) << "body " << b;
      EXPECT_NEAR(body.centerOfMass(b).y, static_cast<double>(ref.com[s].y), tol) << "body " << b;
      EXPECT_NEAR(
          static_cast<double>(std::remainder(body.angle(b) - ref.angle[s], 2 * std::numbers::pi)),
          0, tol);
    }
  }
}

TEST(ArticulatedBodyTest, SolveMatchesDenseReferenceOnRandomTrees) {
  for (const Case& k : kCases) {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      SCOPED_TRACE(::testing::Message()
                   << k.links << " links, " << (k.shape == Shape::Chain ? "chain" : "tree")
                   << ", seed " << seed);
      const Problem p =
          randomProblem(k.links, k.shape, seed * 1000u + static_cast<std::uint32_t>(k.links));
      ArticulatedBody body = p.build();
      ArticulatedBody::Output out = body.makeOutput();
      body.solve(p.torques, p.wrenches, out);
      const DenseReference ref(p, false);
      const Comparison c = compare(out, ref, ref.solve(p.torques, p.wrenches));
      EXPECT_LE(c.relative(), relativeTolerance(k.links)) << "scale " << c.scale;
      EXPECT_GT(c.scale, 0.0);
    }
  }
}

TEST(ArticulatedBodyTest, FixedBaseMatchesDenseReference) {
  for (const Case& k : kCases) {
    SCOPED_TRACE(::testing::Message() << k.links << " links");
    const Problem p = randomProblem(k.links, k.shape, 99u + static_cast<std::uint32_t>(k.links));
    ArticulatedBody body = p.build();
    body.setBaseFixed(true);
    ArticulatedBody::Output out = body.makeOutput();
    body.solve(p.torques, p.wrenches, out);
    EXPECT_EQ(out.velocity(ArticulatedBody::base), Vector3{});
    const DenseReference ref(p, true);
    const Comparison c = compare(out, ref, ref.solve(p.torques, p.wrenches));
    EXPECT_LE(c.relative(), relativeTolerance(k.links)) << "scale " << c.scale;
  }
}

TEST(ArticulatedBodyTest, TorquesAloneAndWrenchesAloneMatchDenseReference) {
  // Empty spans mean "none": each input is checked on its own.
  const Problem p = randomProblem(20, Shape::Tree, 4242);
  ArticulatedBody body = p.build();
  ArticulatedBody::Output out = body.makeOutput();
  const DenseReference ref(p, false);
  const std::vector<real> noTorques(p.torques.size(), 0);
  const std::vector<Vector3> noWrenches(p.wrenches.size());

  body.solve(p.torques, {}, out);
  Comparison c = compare(out, ref, ref.solve(p.torques, noWrenches));
  EXPECT_LE(c.relative(), relativeTolerance(20));

  body.solve({}, p.wrenches, out);
  c = compare(out, ref, ref.solve(noTorques, p.wrenches));
  EXPECT_LE(c.relative(), relativeTolerance(20));
}

// ---------------------------------------------------------------------------------------------
// Closed-form cases

TEST(ArticulatedBodyTest, NoTorqueAndNoForceGiveExactlyZeroMotion) {
  for (const Case& k : kCases) {
    const Problem p = randomProblem(k.links, k.shape, 5u);
    ArticulatedBody body = p.build();
    ArticulatedBody::Output out = body.makeOutput();
    body.solve({}, {}, out);
    for (const Vector3& v : out.velocities) EXPECT_EQ(v, Vector3{});
    for (const real rate : out.jointRates) EXPECT_EQ(rate, 0);
    const std::vector<real> zeroTorques(p.torques.size(), 0);
    const std::vector<Vector3> zeroWrenches(p.wrenches.size());
    body.solve(zeroTorques, zeroWrenches, out);
    for (const Vector3& v : out.velocities) EXPECT_EQ(v, Vector3{});
    for (const real rate : out.jointRates) EXPECT_EQ(rate, 0);
  }
}

TEST(ArticulatedBodyTest, TwoBodiesWithAJointTorqueByHand) {
  // Base m0 = 2, I0 = 1; one link jointed at the base's centre of mass, along the base's x
  // axis (q = 0), centre of mass at (l, 0) with l = 1.5, m1 = 1, I1 = 0.5; joint torque
  // tau = 1. Base frame along world x at the origin first, then turned by 0.7 rad and moved.
  //
  // Forces: the link gets +tau and the joint reaction R at the joint, whose torque about the
  // link's centre of mass is cross((-l, 0), R) = -l R_y; the base gets -tau and -R at its
  // centre of mass (no torque). With v0 the base velocity, the link's centre of mass moves at
  // v1 = v0 + omega1 x (l, 0) since the joint point moves with the base:
  //   m0 v0 = -R,   I0 omega0 = -tau,   m1 (v0 + (0, l omega1)) = R,   I1 omega1 = tau - l R_y.
  // Along x: (m0 + m1) v0x = 0. Along y: v0y = -m1 l omega1 / (m0 + m1), so
  // R_y = mu l omega1 with mu = m0 m1 / (m0 + m1) = 2/3, and omega1 = tau / (I1 + mu l^2)
  // = 1 / (0.5 + 1.5) = 0.5. Hence omega0 = -1, qdot = omega1 - omega0 = 1.5,
  // v0 = (0, -1 * 1.5 * 0.5 / 3) = (0, -0.25), v1 = (0, 1.5 * 0.5 * 2 / 3) = (0, 0.5).
  ArticulatedLink link;
  link.parent = ArticulatedLink::base;
  link.jointPosition = {0, 0};
  link.length = 3;
  link.centerOfMass = {real(1.5), 0};
  link.mass = 1;
  link.inertia = real(0.5);
  for (const real turn : {real(0), real(0.7)}) {
    SCOPED_TRACE(turn);
    ArticulatedBody body(2, 1, {link});
    body.setBasePose({real(3) * turn, -turn}, turn);
    ArticulatedBody::Output out = body.makeOutput();
    const real torque[] = {1};
    body.solve(torque, {}, out);
    const Vector2 v0 = Vector2{0, real(-0.25)}.rotated(turn);
    const Vector2 v1 = Vector2{0, real(0.5)}.rotated(turn);
    EXPECT_NEAR(out.angularVelocity(ArticulatedBody::base), -1, tight);
    EXPECT_NEAR(out.linearVelocity(ArticulatedBody::base).x, v0.x, tight);
    EXPECT_NEAR(out.linearVelocity(ArticulatedBody::base).y, v0.y, tight);
    EXPECT_NEAR(out.jointRate(0), real(1.5), tight);
    EXPECT_NEAR(out.angularVelocity(0), real(0.5), tight);
    EXPECT_NEAR(out.linearVelocity(0).x, v1.x, tight);
    EXPECT_NEAR(out.linearVelocity(0).y, v1.y, tight);
    // Momentum balance: nothing outside pushes, so the total "momentum" m v sums to zero.
    const Vector2 total = out.linearVelocity(ArticulatedBody::base) * 2 + out.linearVelocity(0);
    EXPECT_NEAR(total.x, 0, tight);
    EXPECT_NEAR(total.y, 0, tight);
  }
}

TEST(ArticulatedBodyTest, ForcesProportionalToMassTranslateEveryBodyAlike) {
  // A straight chain (all q = 0) along x, each body pushed along x at its centre of mass by
  // 3 times its mass: a common translation at 3 m/s balances every body's force by itself
  // (D u = F body by body, with no joint force), and it is in the span of u, so it is the
  // solution: no body turns and no joint moves.
  ArticulatedLink link;
  link.length = 2;
  link.centerOfMass = {1, 0};
  link.mass = 1;
  link.inertia = real(0.25);
  std::vector<ArticulatedLink> links;
  for (int i = 0; i < 4; ++i) {
    link.parent = i - 1;
    link.jointPosition = i == 0 ? Vector2{real(0.5), 0} : Vector2{2, 0};
    links.push_back(link);
  }
  ArticulatedBody body(2, 1, links);
  std::vector<Vector3> wrenches;
  wrenches.push_back(forceVector(0, {2 * real(3), 0}));
  for (int i = 0; i < 4; ++i) wrenches.push_back(forceVector(0, {3, 0}));
  ArticulatedBody::Output out = body.makeOutput();
  body.solve({}, wrenches, out);
  for (int b = -1; b < 4; ++b) {
    EXPECT_NEAR(out.linearVelocity(b).x, 3, tight) << "body " << b;
    EXPECT_NEAR(out.linearVelocity(b).y, 0, tight) << "body " << b;
    EXPECT_NEAR(out.angularVelocity(b), 0, tight) << "body " << b;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out.jointRate(i), 0, tight);
}

// ---------------------------------------------------------------------------------------------
// Test forces (Kokkevis) and the constraint matrix K

/// Random constraints on a problem: contacts at random points of random bodies with random
/// unit normals, and joint-limit torques of either sign.
std::vector<ArticulatedBody::TestForce> randomConstraints(const ArticulatedBody& body, int count,
                                                          std::uint32_t seed) {
  MTRandom random(seed);
  std::vector<ArticulatedBody::TestForce> constraints;
  for (int k = 0; k < count; ++k) {
    if (random.bernoulli(0.3)) {
      constraints.push_back(ArticulatedBody::TestForce::onJoint(
          static_cast<int>(random.integer(0, body.linkCount() - 1)),
          random.bernoulli(0.5) ? real(1) : real(-1)));
    } else {
      const int b = static_cast<int>(random.integer(-1, body.linkCount() - 1));
      const Vector2 point =
          body.centerOfMass(b) + Vector2{draw(random, -1, 1), draw(random, -1, 1)};
      const real a = draw(random, -4, 4);
      constraints.push_back(
          ArticulatedBody::TestForce::atPoint(b, point, {std::cos(a), std::sin(a)}));
    }
  }
  return constraints;
}

TEST(ArticulatedBodyTest, RespondEqualsSolveWithTheSameForce) {
  for (const Case& k : kCases) {
    SCOPED_TRACE(::testing::Message() << k.links << " links");
    const Problem p = randomProblem(k.links, k.shape, 31u + static_cast<std::uint32_t>(k.links));
    ArticulatedBody body = p.build();
    ArticulatedBody::Output fromRespond = body.makeOutput();
    ArticulatedBody::Output fromSolve = body.makeOutput();
    for (const ArticulatedBody::TestForce& t : randomConstraints(body, 10, 17)) {
      body.respond(t, fromRespond);
      std::vector<real> torques(p.torques.size(), 0);
      std::vector<Vector3> wrenches(p.wrenches.size());
      if (t.kind == ArticulatedBody::TestForce::Kind::JointTorque) {
        torques[static_cast<std::size_t>(t.index)] = t.torque;
      } else {
        const int slot = t.index + 1;
        wrenches[static_cast<std::size_t>(slot)] =
            spatialForceAt(t.direction, t.point, body.centerOfMass(t.index));
      }
      body.solve(torques, wrenches, fromSolve);
      double error = 0, scale = 0;
      for (std::size_t s = 0; s < fromSolve.velocities.size(); ++s) {
        const Vector3 d = fromRespond.velocities[s] - fromSolve.velocities[s];
        error =
            std::max({error, std::abs(double(d.x)), std::abs(double(d.y)), std::abs(double(d.z))});
        scale = std::max({scale, std::abs(double(fromSolve.velocities[s].x)),
                          std::abs(double(fromSolve.velocities[s].y)),
                          std::abs(double(fromSolve.velocities[s].z))});
      }
      for (std::size_t i = 0; i < fromSolve.jointRates.size(); ++i) {
        error =
            std::max(error, std::abs(double(fromRespond.jointRates[i] - fromSolve.jointRates[i])));
        scale = std::max(scale, std::abs(double(fromSolve.jointRates[i])));
      }
      // The same passes in a different order of summation: equal up to a few roundings.
      EXPECT_LE(error, (isFloat ? 1e-5 : 1e-13) * std::max(scale, 1.0));
    }
  }
}

TEST(ArticulatedBodyTest, RespondToASetIsTheSumOfTheResponses) {
  const Problem p = randomProblem(20, Shape::Tree, 77);
  ArticulatedBody body = p.build();
  const auto forces = randomConstraints(body, 6, 3);
  const std::vector<real> magnitudes{real(0.5), real(-2), real(1.25), real(3), real(0), real(-1)};
  ArticulatedBody::Output together = body.makeOutput();
  body.respond(forces, magnitudes, together);
  ArticulatedBody::Output sum = body.makeOutput();
  ArticulatedBody::Output one = body.makeOutput();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    body.respond(forces[k], one);
    sum.addScaled(one, magnitudes[k]);
  }
  const real tol = isFloat ? real(1e-4) : real(1e-12);
  for (std::size_t s = 0; s < sum.velocities.size(); ++s) {
    EXPECT_NEAR(together.velocities[s].x, sum.velocities[s].x, tol);
    EXPECT_NEAR(together.velocities[s].y, sum.velocities[s].y, tol);
    EXPECT_NEAR(together.velocities[s].z, sum.velocities[s].z, tol);
  }
  for (std::size_t i = 0; i < sum.jointRates.size(); ++i)
    EXPECT_NEAR(together.jointRates[i], sum.jointRates[i], tol);
}

/// Succeeds when the symmetric @p k plus @p shift times the identity has a Cholesky factor,
/// i.e. when every eigenvalue of @p k is above -shift.
bool choleskySucceeds(Dense k, Exact shift) {
  for (int i = 0; i < k.rows; ++i) k(i, i) += shift;
  for (int j = 0; j < k.rows; ++j) {
    Exact d = k(j, j);
    for (int m = 0; m < j; ++m) d -= k(j, m) * k(j, m);
    if (!(d > 0)) return false;
    k(j, j) = std::sqrt(d);
    for (int i = j + 1; i < k.rows; ++i) {
      Exact v = k(i, j);
      for (int m = 0; m < j; ++m) v -= k(i, m) * k(j, m);
      k(i, j) = v / k(j, j);
    }
  }
  return true;
}

TEST(ArticulatedBodyTest, ConstraintMatrixColumnByColumnIsSymmetricPsdAndMatchesDense) {
  for (const Case& k : kCases) {
    for (const bool fixed : {false, true}) {
      SCOPED_TRACE(::testing::Message() << k.links << " links, fixed base " << fixed);
      const Problem p = randomProblem(k.links, k.shape, 555u + static_cast<std::uint32_t>(k.links));
      ArticulatedBody body = p.build();
      body.setBaseFixed(fixed);
      auto constraints = randomConstraints(body, 12, 9u + static_cast<std::uint32_t>(k.links));
      // A repeated constraint makes K singular: it must stay positive semi-definite.
      constraints.push_back(constraints.front());
      const int m = static_cast<int>(constraints.size());

      Dense K(m, m);
      ArticulatedBody::Output out = body.makeOutput();
      for (int j = 0; j < m; ++j) {
        body.respond(constraints[j], out);
        for (int i = 0; i < m; ++i) K(i, j) = body.velocityAlong(out, constraints[i]);
      }

      // Dense: K = J_c M^-1 J_c^T, one solve per column.
      const DenseReference ref(p, fixed);
      std::vector<std::vector<Exact>> rows;
      rows.reserve(constraints.size());
      for (const auto& c : constraints) rows.push_back(ref.constraintRow(c));
      Exact scale = 0, error = 0, asymmetry = 0, trace = 0;
      for (int j = 0; j < m; ++j) {
        const std::vector<Exact> x = choleskySolve(ref.M, rows[j]);
        for (int i = 0; i < m; ++i) {
          Exact expected = 0;
          for (int c = 0; c < ref.dofs; ++c) expected += rows[i][c] * x[c];
          scale = std::max(scale, std::abs(expected));
          error = std::max(error, std::abs(K(i, j) - expected));
          asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
        }
        trace += K(j, j);
      }
      const Exact tol = relativeTolerance(k.links) * scale;
      EXPECT_LE(error, tol) << "scale " << scale;
      EXPECT_LE(asymmetry, tol);
      for (int i = 0; i < m; ++i) EXPECT_GE(K(i, i), 0);
      EXPECT_TRUE(choleskySucceeds(K, relativeTolerance(k.links) * trace))
          << "K has a negative eigenvalue";
      EXPECT_FALSE(choleskySucceeds(K, -1e-3 * trace)) << "the repeated row should make K singular";
    }
  }
}

TEST(ArticulatedBodyTest, VelocityAlongReadsPointVelocitiesAndJointRates) {
  const Problem p = randomProblem(5, Shape::Tree, 8);
  ArticulatedBody body = p.build();
  ArticulatedBody::Output out = body.makeOutput();
  body.solve(p.torques, p.wrenches, out);
  const int b = 3;
  const Vector2 point = body.tip(b);
  // The tip moves with the link: v_com + omega x (tip - com).
  const Vector2 expected =
      out.linearVelocity(b) + cross(out.angularVelocity(b), point - body.centerOfMass(b));
  EXPECT_EQ(body.pointVelocity(out, b, point), expected);
  EXPECT_NEAR(body.velocityAlong(out, ArticulatedBody::TestForce::atPoint(b, point, {0, 1})),
              expected.y, tight);
  EXPECT_EQ(body.velocityAlong(out, ArticulatedBody::TestForce::onJoint(2, -1)), -out.jointRate(2));
  EXPECT_EQ(ArticulatedBody::jointRate(out, 2), out.jointRates[2]);
}

// ---------------------------------------------------------------------------------------------
// Joint damping: (J^T D J + C) u = J^T F + tau with C = diag(0, 0, 0, c), the implicit servo term

/// Random damping per joint, a third of them zero (undamped joints mixed with damped ones).
std::vector<real> randomDamping(int count, std::uint32_t seed) {
  MTRandom random(seed);
  std::vector<real> c;
  for (int i = 0; i < count; ++i) c.push_back(random.bernoulli(0.3) ? real(0) : draw(random, 0, 5));
  return c;
}

/// The dense reference with the joint damping added to the diagonal of J^T D J.
DenseReference dampedReference(const Problem& p, bool fixedBase, const std::vector<real>& c) {
  DenseReference ref(p, fixedBase);
  for (int i = 0; i < ref.n; ++i) ref.M(ref.firstJoint + i, ref.firstJoint + i) += c[i];
  return ref;
}

TEST(ArticulatedBodyTest, DampedJointsMatchDenseReference) {
  for (const Case& k : kCases) {
    for (const bool fixed : {false, true}) {
      SCOPED_TRACE(::testing::Message() << k.links << " links, fixed base " << fixed);
      const Problem p = randomProblem(k.links, k.shape, 77u + static_cast<std::uint32_t>(k.links));
      ArticulatedBody body = p.build();
      body.setBaseFixed(fixed);
      const std::vector<real> c = randomDamping(k.links, 3u + static_cast<std::uint32_t>(k.links));
      for (int i = 0; i < k.links; ++i) body.setJointDamping(i, c[i]);
      ArticulatedBody::Output out = body.makeOutput();
      body.solve(p.torques, p.wrenches, out);
      const DenseReference ref = dampedReference(p, fixed, c);
      const Comparison cmp = compare(out, ref, ref.solve(p.torques, p.wrenches));
      EXPECT_LE(cmp.relative(), relativeTolerance(k.links)) << "scale " << cmp.scale;

      // Test forces see the damped joints too: K = J_c (J^T D J + C)^-1 J_c^T.
      const auto constraints =
          randomConstraints(body, 6, 21u + static_cast<std::uint32_t>(k.links));
      Exact scale = 0, error = 0;
      for (const auto& cj : constraints) {
        body.respond(cj, out);
        const std::vector<Exact> x = choleskySolve(ref.M, ref.constraintRow(cj));
        for (const auto& ci : constraints) {
          const std::vector<Exact> row = ref.constraintRow(ci);
          Exact expected = 0;
          for (int col = 0; col < ref.dofs; ++col) expected += row[col] * x[col];
          scale = std::max(scale, std::abs(expected));
          error = std::max(error, std::abs(body.velocityAlong(out, ci) - expected));
        }
      }
      EXPECT_LE(error, relativeTolerance(k.links) * scale) << "scale " << scale;
    }
  }
}

TEST(ArticulatedBodyTest, ZeroDampingChangesNothing) {
  // Setting every damping to zero (explicitly) must give bit-identical results to never setting
  // it: the undamped passes are exactly the original algorithm.
  const Problem p = randomProblem(20, Shape::Tree, 808);
  ArticulatedBody plain = p.build();
  ArticulatedBody zeroed = p.build();
  for (int i = 0; i < 20; ++i) zeroed.setJointDamping(i, 0);
  ArticulatedBody::Output a = plain.makeOutput();
  ArticulatedBody::Output b = zeroed.makeOutput();
  plain.solve(p.torques, p.wrenches, a);
  zeroed.solve(p.torques, p.wrenches, b);
  EXPECT_EQ(a.velocities, b.velocities);
  EXPECT_EQ(a.jointRates, b.jointRates);
}

TEST(ArticulatedBodyTest, SingleDampedJointByHand) {
  // A fixed base and one link jointed at its centre of mass: the joint's effective inertia is
  // d = I + m l^2 about the joint, so (d + c) qdot = tau, whatever the joint's direction.
  const real m = 2, inertia = real(0.3), l = real(0.8), c = real(1.7), tau = real(0.9);
  ArticulatedLink link;
  link.parent = ArticulatedLink::base;
  link.jointPosition = {real(0.4), real(-0.2)};
  link.length = 2 * l;
  link.centerOfMass = {l, 0};
  link.mass = m;
  link.inertia = inertia;
  ArticulatedBody body(1, 1, {link});
  body.setBaseFixed(true);
  body.setBasePose({1, 2}, real(0.3));
  body.setJointAngle(0, real(-1.1));
  body.setJointDamping(0, c);
  EXPECT_EQ(body.jointDamping(0), c);
  ArticulatedBody::Output out = body.makeOutput();
  const real torque[] = {tau};
  body.solve(torque, {}, out);
  EXPECT_NEAR(out.jointRate(0), tau / (inertia + m * l * l + c), tight);
  // A unit joint test force: K = 1 / (d + c).
  body.respond(ArticulatedBody::TestForce::onJoint(0), out);
  EXPECT_NEAR(out.jointRate(0), 1 / (inertia + m * l * l + c), tight);
}

TEST(ArticulatedBodyTest, StiffImplicitServoConvergesMonotonically) {
  // The servo tau = k (q* - q - dt qdot) as damping c = k dt plus the torque k (q* - q): one
  // joint with effective inertia d (fixed base) gives (d + k dt) qdot = k (q* - q), so the error
  // shrinks by d / (d + k dt) per step, never changing sign, however large k. Here
  // k dt / d = 1000: the explicit servo (c = 0) would overshoot by a factor ~1000 and diverge.
  const real m = 1, inertia = real(0.25), l = real(0.5);
  const real d = inertia + m * l * l;
  const real dt = real(0.01);
  const real k = 1000 * d / dt;
  const real target = real(1.2);
  ArticulatedLink link;
  link.parent = ArticulatedLink::base;
  link.length = 2 * l;
  link.centerOfMass = {l, 0};
  link.mass = m;
  link.inertia = inertia;
  ArticulatedBody body(1, 1, {link});
  body.setBaseFixed(true);
  body.setJointDamping(0, k * dt);
  ArticulatedBody::Output out = body.makeOutput();
  real error = target - body.jointAngle(0);
  for (int step = 0; step < 5; ++step) {
    const real torque[] = {k * (target - body.jointAngle(0))};
    body.solve(torque, {}, out);
    body.integrate(out, dt);
    const real next = target - body.jointAngle(0);
    EXPECT_GE(next, 0) << "overshoot at step " << step;
    EXPECT_NEAR(next, error * d / (d + k * dt), tight) << "step " << step;
    EXPECT_LE(next, error) << "step " << step;  // equal only once both are round-off
    error = next;
  }

  // A floating 10-link chain with every joint servoed at k dt = 1000 d. The joints are coupled:
  // the error map is about the joint-space M / (k dt), symmetric positive definite and small,
  // not diagonal, so a joint may cross its target by a fraction of the others' errors; but the
  // largest error shrinks by more than a factor 10 every step, down to round-off (the slowest
  // mode contracts by lambda / (lambda + k dt), lambda the largest eigenvalue of the chain's
  // joint-space inertia, about 70 d here; an explicit servo would grow it by about 1000).
  std::vector<ArticulatedLink> chain;
  for (int i = 0; i < 10; ++i) {
    link.parent = i - 1;
    link.jointPosition = i == 0 ? Vector2{real(0.5), 0} : link.tip();
    chain.push_back(link);
  }
  ArticulatedBody floating(2, 1, chain);
  std::vector<real> targets, torques(10);
  for (int i = 0; i < 10; ++i) {
    targets.push_back(real(0.3) * std::sin(real(i) + 1));
    floating.setJointDamping(i, k * dt);
  }
  ArticulatedBody::Output fout = floating.makeOutput();
  real largest = 1;
  for (int step = 0; step < 20; ++step) {
    for (int i = 0; i < 10; ++i) torques[i] = k * (targets[i] - floating.jointAngle(i));
    floating.solve(torques, {}, fout);
    floating.integrate(fout, dt);
    real now = 0;
    for (int i = 0; i < 10; ++i) {
      const real e = targets[i] - floating.jointAngle(i);
      now = std::max(now, std::abs(e));
    }
    EXPECT_LE(now, std::max(real(0.1) * largest, real(isFloat ? 1e-5 : 1e-12))) << "step " << step;
    largest = now;
  }
  EXPECT_LT(largest, isFloat ? real(1e-4) : real(1e-9));
}

TEST(ArticulatedBodyTest, JointDampingValidation) {
  ArticulatedLink link;
  ArticulatedBody body(1, 1, {link});
  for (const real bad : {real(-1), kNaN, kInf}) {
    try {
      body.setJointDamping(0, bad);
      ADD_FAILURE() << "no exception for " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), "ArticulatedBody.jointDamping");
    }
  }
  try {
    body.setJointDamping(1, 1);
    ADD_FAILURE() << "no exception for a bad index";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "ArticulatedBody.jointDamping");
  }
  EXPECT_EQ(body.jointDamping(0), 0);
}

// ---------------------------------------------------------------------------------------------
// State, determinism, allocation

TEST(ArticulatedBodyTest, IntegrateMovesTheStateByTheVelocities) {
  const Problem p = randomProblem(5, Shape::Chain, 12);
  ArticulatedBody body = p.build();
  ArticulatedBody::Output out = body.makeOutput();
  body.solve(p.torques, p.wrenches, out);
  const real dt = real(0.01);
  body.integrate(out, dt);
  EXPECT_EQ(body.basePosition(), p.basePosition + out.linearVelocity(ArticulatedBody::base) * dt);
  EXPECT_EQ(body.baseAngle(), p.baseAngle + out.angularVelocity(ArticulatedBody::base) * dt);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(body.jointAngle(i), p.q[i] + out.jointRate(i) * dt);
  // The next solve sees the new configuration: it matches a body built there from scratch.
  Problem moved = p;
  moved.basePosition = body.basePosition();
  moved.baseAngle = body.baseAngle();
  moved.q.assign(body.jointAngles().begin(), body.jointAngles().end());
  ArticulatedBody fresh = moved.build();
  ArticulatedBody::Output a = body.makeOutput();
  ArticulatedBody::Output b = fresh.makeOutput();
  body.solve(p.torques, p.wrenches, a);
  fresh.solve(p.torques, p.wrenches, b);
  EXPECT_EQ(a.velocities, b.velocities);
  EXPECT_EQ(a.jointRates, b.jointRates);
}

TEST(ArticulatedBodyTest, IntegrateCallsEachLinkWithItsPoseInOrder) {
  // A chain and a tree (the calls come from within the kinematics' loop in both): each link
  // once, in index order, with the pose the accessors give, the same state as integrate()
  // without the calls, and link i's pose already there when it is called.
  for (const Shape shape : {Shape::Chain, Shape::Tree}) {
    const Problem p = randomProblem(12, shape, 31);
    ArticulatedBody body = p.build();
    ArticulatedBody plain = p.build();
    ArticulatedBody::Output out = body.makeOutput();
    body.solve(p.torques, p.wrenches, out);
    const real dt = real(0.01);
    std::vector<int> seen;
    body.integrate(out, dt, [&](std::size_t i, Vector2 centre, real angle, Vector2 axis) {
      const int link = static_cast<int>(i);
      seen.push_back(link);
      EXPECT_EQ(centre, body.centerOfMass(link)) << link;
      EXPECT_EQ(angle, body.angle(link)) << link;
      EXPECT_EQ(axis, body.axis(link)) << link;
    });
    plain.integrate(out, dt);
    std::vector<int> expected(12);
    for (int i = 0; i < 12; ++i) expected[static_cast<std::size_t>(i)] = i;
    EXPECT_EQ(seen, expected);
    EXPECT_EQ(body.basePosition(), plain.basePosition());
    EXPECT_EQ(body.baseAngle(), plain.baseAngle());
    for (int b = ArticulatedBody::base; b < 12; ++b) {
      EXPECT_EQ(body.origin(b), plain.origin(b)) << b;
      EXPECT_EQ(body.angle(b), plain.angle(b)) << b;
      EXPECT_EQ(body.axis(b), plain.axis(b)) << b;
      EXPECT_EQ(body.centerOfMass(b), plain.centerOfMass(b)) << b;
    }
  }
}

TEST(ArticulatedBodyTest, SameInputGivesBitIdenticalOutput) {
  const Problem p = randomProblem(50, Shape::Tree, 2024);
  ArticulatedBody first = p.build();
  ArticulatedBody second = p.build();
  ArticulatedBody::Output a = first.makeOutput();
  ArticulatedBody::Output b = second.makeOutput();
  first.solve(p.torques, p.wrenches, a);
  second.solve(p.torques, p.wrenches, b);
  EXPECT_EQ(a.velocities, b.velocities);
  EXPECT_EQ(a.jointRates, b.jointRates);
}

TEST(ArticulatedBodyTest, ZeroWrenchesGiveTheBitsOfNoWrenches) {
  // Subtracting zero wrenches changes no bit, so the two must agree bit for bit. A tree's
  // inward pass takes both through one loop; a plain chain's (in double with SSE2) takes them
  // through copies of its pairs' loop, with and without the wrenches' terms, which must then
  // do the same operations (and the compiler must fuse none into multiply-adds of its own).
  for (const Shape shape : {Shape::Chain, Shape::Tree}) {
    const Problem p = randomProblem(30, shape, 77);
    ArticulatedBody withZeros = p.build();
    ArticulatedBody without = p.build();
    ArticulatedBody::Output a = withZeros.makeOutput();
    ArticulatedBody::Output b = without.makeOutput();
    const std::vector<Vector3> zeros(p.wrenches.size());
    withZeros.solve(p.torques, zeros, a);
    without.solve(p.torques, {}, b);
    for (std::size_t k = 0; k < a.velocities.size(); ++k) {
      const Vector3& va = a.velocities[k];
      const Vector3& vb = b.velocities[k];
      EXPECT_EQ(test::bitsOf(va.x), test::bitsOf(vb.x)) << k;
      EXPECT_EQ(test::bitsOf(va.y), test::bitsOf(vb.y)) << k;
      EXPECT_EQ(test::bitsOf(va.z), test::bitsOf(vb.z)) << k;
    }
    for (std::size_t i = 0; i < a.jointRates.size(); ++i)
      EXPECT_EQ(test::bitsOf(a.jointRates[i]), test::bitsOf(b.jointRates[i])) << i;
  }
}

TEST(ArticulatedBodyTest, SolveAndRespondDoNotAllocate) {
  const Problem p = randomProblem(50, Shape::Tree, 6);
  ArticulatedBody body = p.build();
  ArticulatedBody::Output out = body.makeOutput();
  const auto forces = randomConstraints(body, 8, 1);
  const long before = test::allocationCount();
  for (int step = 0; step < 10; ++step) {
    body.setJointAngle(step % 50, real(0.1) * real(step));
    body.setBasePose({real(step), 0}, real(0.01) * real(step));
    body.solve(p.torques, p.wrenches, out);
    for (const auto& f : forces) {
      body.respond(f, out);
      (void)body.velocityAlong(out, f);
    }
    body.respond(forces, {}, out);
    body.integrate(out, real(0.01));
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

// ---------------------------------------------------------------------------------------------
// Validation: bad input throws InvalidArgument naming the field

template <class Action>
std::string thrownField(Action&& action) {
  try {
    action();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos)
        << "message \"" << e.what() << "\" does not name the field " << e.field();
    return e.field();
  } catch (...) {
    return "<other exception>";
  }
  return "<no exception>";
}

std::vector<ArticulatedLink> threeLinkChain() {
  std::vector<ArticulatedLink> links(3);
  for (int i = 0; i < 3; ++i) {
    links[i].parent = i - 1;
    links[i].jointPosition = i == 0 ? Vector2{} : links[i - 1].tip();
  }
  return links;
}

TEST(ArticulatedBodyTest, GettersCheckTheirIndex) {
  const ArticulatedBody body(1, 1, threeLinkChain());
  for (const int i : {-1, 3, 99}) {
    SCOPED_TRACE(i);
    EXPECT_EQ(thrownField([&] { (void)body.jointAngle(i); }), "ArticulatedBody.link");
    EXPECT_EQ(thrownField([&] { (void)body.jointDamping(i); }), "ArticulatedBody.link");
    EXPECT_EQ(thrownField([&] { (void)body.link(i); }), "ArticulatedBody.link");
    EXPECT_EQ(thrownField([&] { (void)body.tip(i); }), "ArticulatedBody.link");
  }
  EXPECT_EQ(thrownField([&] { (void)body.jointAngle(2); }), "<no exception>");
  EXPECT_EQ(thrownField([&] { (void)body.tip(0); }), "<no exception>");
}

TEST(ArticulatedBodyTest, ValidationNamesTheField) {
  auto build = [](const std::vector<ArticulatedLink>& links) {
    return [links] { ArticulatedBody body(1, 1, links); };
  };
  EXPECT_EQ(thrownField(build(threeLinkChain())), "<no exception>");

  // Parents: a loop (a link on itself or on a later link) and out-of-range indices.
  for (const int parent : {2, 3, 7, -2}) {
    SCOPED_TRACE(parent);
    auto links = threeLinkChain();
    links[2].parent = parent;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.parent");
  }
  {
    auto links = threeLinkChain();
    links[0].parent = 0;  // the first link on itself
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.parent");
  }
  for (const real bad : {real(0), real(-1), kNaN, kInf}) {
    SCOPED_TRACE(bad);
    auto links = threeLinkChain();
    links[1].length = bad;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.length");
    links = threeLinkChain();
    links[1].mass = bad;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.mass");
    links = threeLinkChain();
    links[1].inertia = bad;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.inertia");
    EXPECT_EQ(thrownField([bad] { ArticulatedBody body(bad, 1, {}); }), "ArticulatedBody.baseMass");
    EXPECT_EQ(thrownField([bad] { ArticulatedBody body(1, bad, {}); }),
              "ArticulatedBody.baseInertia");
  }
  {
    auto links = threeLinkChain();
    links[0].jointPosition = {kNaN, 0};
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.jointPosition");
    links = threeLinkChain();
    links[2].centerOfMass = {0, kInf};
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.centerOfMass");
    links = threeLinkChain();
    links[1].hasLimits = true;
    links[1].qMin = 1;
    links[1].qMax = -1;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.qMax");
    links[1].qMin = kNaN;
    EXPECT_EQ(thrownField(build(links)), "ArticulatedLink.qMin");
    links[1].qMin = -1;
    links[1].qMax = 1;
    EXPECT_EQ(thrownField(build(links)), "<no exception>");
  }
  EXPECT_EQ(thrownField([] { (void)ArticulatedLink::capsule(-1, {}, 0, 1, 1); }),
            "ArticulatedLink.length");
  EXPECT_EQ(thrownField([] { (void)ArticulatedLink::capsule(-1, {}, 1, -1, 1); }),
            "ArticulatedLink.radius");
  EXPECT_EQ(thrownField([] { (void)ArticulatedLink::capsule(-1, {}, 1, 1, -2); }),
            "ArticulatedLink.mass");
}

TEST(ArticulatedBodyTest, BadStateAndInputsNameTheFieldAndLeaveTheStateUnchanged) {
  ArticulatedBody body(1, 1, threeLinkChain());
  body.setJointAngle(1, real(0.5));
  ArticulatedBody::Output out = body.makeOutput();
  const std::vector<real> wrongQ{1, 2};
  EXPECT_EQ(thrownField([&] { body.setJointAngles(wrongQ); }), "ArticulatedBody.q");
  const std::vector<real> nanQ{1, kNaN, 2};
  EXPECT_EQ(thrownField([&] { body.setJointAngles(nanQ); }), "ArticulatedBody.q");
  EXPECT_EQ(thrownField([&] { body.setJointAngle(3, 0); }), "ArticulatedBody.q");
  EXPECT_EQ(body.jointAngle(0), 0);
  EXPECT_EQ(body.jointAngle(1), real(0.5));
  EXPECT_EQ(thrownField([&] { body.setBasePose({kNaN, 0}, 0); }), "ArticulatedBody.basePosition");
  EXPECT_EQ(thrownField([&] { body.setBasePose({}, kInf); }), "ArticulatedBody.baseAngle");
  EXPECT_EQ(body.basePosition(), Vector2{});

  const std::vector<real> twoTorques{1, 2};
  EXPECT_EQ(thrownField([&] { body.solve(twoTorques, {}, out); }), "ArticulatedBody.jointTorques");
  const std::vector<Vector3> threeWrenches(3);
  EXPECT_EQ(thrownField([&] { body.solve({}, threeWrenches, out); }),
            "ArticulatedBody.externalWrenches");
  EXPECT_EQ(thrownField([&] {
              body.respond(ArticulatedBody::TestForce::atPoint(3, {}, {1, 0}), out);
            }),
            "ArticulatedBody.TestForce.index");
  EXPECT_EQ(thrownField([&] {
              body.respond(ArticulatedBody::TestForce::atPoint(-2, {}, {1, 0}), out);
            }),
            "ArticulatedBody.TestForce.index");
  EXPECT_EQ(thrownField([&] { body.respond(ArticulatedBody::TestForce::onJoint(-1), out); }),
            "ArticulatedBody.TestForce.index");
  const ArticulatedBody::TestForce forces[] = {ArticulatedBody::TestForce::onJoint(0)};
  const std::vector<real> twoMagnitudes{1, 2};
  EXPECT_EQ(thrownField([&] { body.respond(forces, twoMagnitudes, out); }),
            "ArticulatedBody.magnitudes");
  EXPECT_EQ(thrownField([&] {
              body.respond(ArticulatedBody::TestForce::atPoint(-1, {}, {1, 0}), out);
            }),
            "<no exception>");
}

TEST(ArticulatedBodyTest, CapsuleLinkHasTheCapsuleGeometry) {
  const ArticulatedLink link = ArticulatedLink::capsule(-1, {1, 2}, real(0.75), real(0.25), 3);
  EXPECT_EQ(link.parent, -1);
  EXPECT_EQ(link.jointPosition, (Vector2{1, 2}));
  EXPECT_EQ(link.length, real(1.5));
  EXPECT_EQ(link.centerOfMass, (Vector2{real(0.75), 0}));
  EXPECT_EQ(link.tip(), (Vector2{real(1.5), 0}));
  EXPECT_EQ(link.mass, 3);
  // Between a thin rod of length 2(l + R) and one of length 2l about the centre: m L^2 / 12.
  EXPECT_GT(link.inertia, 3 * real(1.5) * real(1.5) / 12);
  EXPECT_LT(link.inertia, 3 * real(2) * real(2) / 12 + 3 * real(0.25) * real(0.25));
}

}  // namespace
}  // namespace thyrix
