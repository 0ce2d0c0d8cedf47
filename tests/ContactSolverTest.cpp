// The two contact solvers on the same LCPs: complementarity, agreement of body velocities, and
// an independent reference that enumerates active sets of small problems.

#include "TestTolerances.h"

#include <Scenes.h>
#include <ThyrixLite/BaraffSolver.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/GaussSeidelSolver.h>
#include <ThyrixLite/Islands.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

namespace thyrix {
namespace {

/// An LCP taken from a simulator's state, built here from the public contacts (independently
/// of the simulator's own assembly).
struct Problem {
  std::vector<SolverBody> bodies;
  std::vector<ContactConstraint> rows;
  std::vector<std::uint32_t> all;
};

/// A random mixed pile jammed into a corner and pushed further in, with u0 from the push.
Problem makeProblem(std::uint32_t seed, int count, Simulator& simulator) {
  const auto bodies = scenes::addMixedPile(simulator, count, seed);
  MTRandom random(seed + 1000);
  for (PhysicalObject* body : bodies) {
    body->externalForce = {static_cast<real>(random.uniform(-3, 0.5)),
                           static_cast<real>(random.uniform(-3, 0.5))};
    body->externalTorque = static_cast<real>(random.uniform(-0.5, 0.5));
  }
  simulator.detectContacts();
  for (PhysicalObject& object : simulator.objects) object.computeDerivativesWithoutContacts();

  Problem problem;
  for (const PhysicalObject& object : simulator.objects)
    problem.bodies.push_back(
        {object.v, object.omega, object.inverseMass(), object.inverseInertia()});
  const real dt = simulator.timestep();
  for (const GlobalContactInfo& c : simulator.contacts) {
    ContactConstraint row;
    row.a = c.bodyA;
    row.b = c.bodyB;
    row.normal = c.normal;
    row.armA = cross(c.point - c.objectA->r, c.normal);
    row.armB = cross(c.point - c.objectB->r, c.normal);
    row.target = c.depth > 0 ? simulator.solverSettings().penetrationCorrection * c.depth / dt
                             : c.depth / dt;
    problem.rows.push_back(row);
  }
  problem.all.resize(problem.rows.size());
  std::iota(problem.all.begin(), problem.all.end(), 0u);
  return problem;
}

/// Scale of the velocities in a problem, for relative tolerances.
real velocityScale(const Problem& p) {
  real scale = 1;
  for (const SolverBody& b : p.bodies) scale = std::max({scale, b.v.length(), std::abs(b.omega)});
  for (const ContactConstraint& r : p.rows) scale = std::max(scale, std::abs(r.target));
  return scale;
}

void expectComplementarity(const Problem& p, real tolerance) {
  for (const ContactConstraint& row : p.rows) {
    const real slack = row.normalVelocity(p.bodies[row.a], p.bodies[row.b]) - row.target;
    EXPECT_GE(row.force, 0);
    EXPECT_GE(slack, -tolerance) << "w >= c";
    // f (w - c) = 0, with f measured as the velocity it causes at its own contact.
    EXPECT_LE(std::abs(row.force * row.selfResponse(p.bodies[row.a], p.bodies[row.b]) * slack),
              tolerance * (tolerance + std::abs(slack) +
                           row.force * row.selfResponse(p.bodies[row.a], p.bodies[row.b])))
        << "complementarity";
    if (row.force > tolerance) {
      EXPECT_NEAR(slack, 0, tolerance);
    }
  }
}

void expectSameVelocities(const Problem& x, const Problem& y, real tolerance) {
  for (std::size_t i = 0; i < x.bodies.size(); ++i) {
    EXPECT_NEAR(x.bodies[i].v.x, y.bodies[i].v.x, tolerance) << "body " << i;
    EXPECT_NEAR(x.bodies[i].v.y, y.bodies[i].v.y, tolerance) << "body " << i;
    EXPECT_NEAR(x.bodies[i].omega, y.bodies[i].omega, tolerance) << "body " << i;
  }
}

ContactSolverSettings convergedSettings() {
  ContactSolverSettings settings;
  settings.gaussSeidelMaxIterations = 200000;
  settings.gaussSeidelTolerance = test::isFloat ? real(1e-6) : real(1e-13);
  return settings;
}

/// Reference: enumerate the active sets S of a small LCP; for each with A_SS invertible solve
/// A_SS f_S = c_S - b_S by Gaussian elimination and keep the first complementary solution.
/// Returns the body velocities it implies.
bool referenceSolve(Problem& p) {
  const std::size_t m = p.rows.size();
  std::vector<std::vector<double>> A(m, std::vector<double>(m));
  std::vector<double> b(m);
  for (std::size_t i = 0; i < m; ++i) {
    // Column i of A: the velocity change at every contact caused by a unit force at i.
    std::vector<SolverBody> unit = p.bodies;
    for (SolverBody& body : unit) body.v = {}, body.omega = 0;
    p.rows[i].applyImpulse(1, unit[p.rows[i].a], unit[p.rows[i].b]);
    for (std::size_t j = 0; j < m; ++j)
      A[j][i] = p.rows[j].normalVelocity(unit[p.rows[j].a], unit[p.rows[j].b]);
    b[i] =
        p.rows[i].normalVelocity(p.bodies[p.rows[i].a], p.bodies[p.rows[i].b]) - p.rows[i].target;
  }
  for (std::uint32_t mask = 0; mask < (1u << m); ++mask) {
    std::vector<std::size_t> set;
    for (std::size_t i = 0; i < m; ++i)
      if (mask & (1u << i)) set.push_back(i);
    const std::size_t n = set.size();
    std::vector<std::vector<double>> M(n, std::vector<double>(n + 1));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) M[i][j] = A[set[i]][set[j]];
      M[i][n] = -b[set[i]];
    }
    bool singular = false;
    for (std::size_t col = 0; col < n && !singular; ++col) {
      std::size_t pivot = col;
      for (std::size_t r = col + 1; r < n; ++r)
        if (std::abs(M[r][col]) > std::abs(M[pivot][col])) pivot = r;
      if (std::abs(M[pivot][col]) < 1e-12) singular = true;
      std::swap(M[col], M[pivot]);
      for (std::size_t r = 0; r < n && !singular; ++r) {
        if (r == col) continue;
        const double factor = M[r][col] / M[col][col];
        for (std::size_t k = col; k <= n; ++k) M[r][k] -= factor * M[col][k];
      }
    }
    if (singular) continue;
    std::vector<double> f(m, 0);
    bool valid = true;
    for (std::size_t i = 0; i < n; ++i) {
      f[set[i]] = M[i][n] / M[i][i];
      if (f[set[i]] < -1e-9) valid = false;
    }
    for (std::size_t i = 0; i < m && valid; ++i) {
      double w = b[i];
      for (std::size_t j = 0; j < m; ++j) w += A[i][j] * f[j];
      if (w < -1e-9) valid = false;
    }
    if (!valid) continue;
    for (std::size_t i = 0; i < m; ++i) {
      p.rows[i].force = static_cast<real>(f[i]);
      p.rows[i].applyImpulse(static_cast<real>(f[i]), p.bodies[p.rows[i].a], p.bodies[p.rows[i].b]);
    }
    return true;
  }
  return false;
}

class RandomPile : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(RandomPile, BothSolversSatisfyComplementarityAndAgreeOnVelocities) {
  Simulator simulator;
  const Problem original = makeProblem(GetParam(), 30, simulator);
  ASSERT_GT(original.rows.size(), 10u) << "the pile should be in contact";

  Problem baraff = original;
  BaraffSolver solver;
  ASSERT_TRUE(solver.solve(baraff.all, baraff.rows, baraff.bodies));
  Problem gaussSeidel = original;
  GaussSeidelSolver{}.solve(gaussSeidel.all, gaussSeidel.rows, gaussSeidel.bodies,
                            convergedSettings());

  const real scale = velocityScale(original);
  const real tolerance = (test::isFloat ? real(2e-3) : real(1e-8)) * scale;
  expectComplementarity(baraff, tolerance);
  expectComplementarity(gaussSeidel, tolerance);
  expectSameVelocities(baraff, gaussSeidel, tolerance);
}

TEST_P(RandomPile, PlainGaussSeidelAgreesWithBaraffToo) {
  Simulator simulator;
  const Problem original = makeProblem(GetParam(), 30, simulator);
  Problem baraff = original;
  BaraffSolver solver;
  ASSERT_TRUE(solver.solve(baraff.all, baraff.rows, baraff.bodies));
  Problem plain = original;
  ContactSolverSettings settings = convergedSettings();
  settings.accelerateGaussSeidel = false;
  GaussSeidelSolver{}.solve(plain.all, plain.rows, plain.bodies, settings);
  const real tolerance = (test::isFloat ? real(2e-3) : real(1e-8)) * velocityScale(original);
  expectComplementarity(plain, tolerance);
  expectSameVelocities(baraff, plain, tolerance);
}

TEST_P(RandomPile, BaraffMatchesActiveSetEnumerationOnSmallProblems) {
  Simulator simulator;
  Problem original = makeProblem(GetParam(), 7, simulator);
  // Keep the first 12 contacts at most, so 2^m active sets can be enumerated.
  if (original.rows.size() > 12) original.rows.resize(12);
  original.all.resize(original.rows.size());
  if (original.rows.empty()) GTEST_SKIP() << "no contact in this layout";
  Problem reference = original;
  ASSERT_TRUE(referenceSolve(reference));
  Problem baraff = original;
  BaraffSolver solver;
  ASSERT_TRUE(solver.solve(baraff.all, baraff.rows, baraff.bodies));
  const real tolerance = (test::isFloat ? real(1e-3) : real(1e-8)) * velocityScale(original);
  expectSameVelocities(baraff, reference, tolerance);
}

// Gauss-Seidel keeps the bodies' velocities as it goes instead of recomputing them from the
// forces: after thousands of sweeps they must still be u0 + D^-1 J^T f of its own forces (the
// roundings of the two must not add up one way).
TEST_P(RandomPile, GaussSeidelVelocitiesStayThoseOfItsForcesOverManySweeps) {
  Simulator simulator;
  const Problem original = makeProblem(GetParam(), 30, simulator);
  Problem solved = original;
  ContactSolverSettings settings;
  settings.gaussSeidelMaxIterations = 2000;
  settings.gaussSeidelTolerance = 0;  // every sweep is done
  GaussSeidelSolver{}.solve(solved.all, solved.rows, solved.bodies, settings);
  Problem recomputed = original;
  for (const ContactConstraint& row : solved.rows)
    row.applyImpulse(row.force, recomputed.bodies[row.a], recomputed.bodies[row.b]);
  // Measured worst over the seeds: 4e-12 in double, 1.2e-4 in float (velocities following
  // the scaled target instead of the force's change reached 6e-4 there).
  const real tolerance = (test::isFloat ? real(3e-4) : real(1e-11)) * velocityScale(original);
  expectSameVelocities(solved, recomputed, tolerance);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomPile, ::testing::Range(1u, 21u));

/// A column of @p count unit disks on the floor, the top one pushed down by 1 N, solved once
/// from zero forces by Gauss-Seidel with @p sweeps sweeps: the exact answer is every disk at
/// rest (each contact carries 1 N). Returns the largest speed left, the solver's error.
real columnError(int count, int sweeps, bool accelerate) {
  Simulator simulator;
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  ContactSolverSettings& settings = simulator.solverSettings();
  settings.gaussSeidelMaxIterations = sweeps;
  settings.gaussSeidelTolerance = 0;
  settings.accelerateGaussSeidel = accelerate;
  settings.warmStart = false;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  for (int i = 0; i < count; ++i) {
    auto& disk = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    disk.r = {0, real(0.5) + static_cast<real>(i)};
  }
  simulator.objects[static_cast<std::size_t>(count)].externalForce = {0, -1};
  simulator.advanceTime();
  real largest = 0;
  for (const PhysicalObject& object : simulator.objects)
    largest = std::max(largest, object.v.length());
  return largest;
}

TEST(GaussSeidelSolver, AccelerationConvergesFasterAlongAColumn) {
  // Plain Gauss-Seidel moves the load one contact per sweep and diffuses it; the conjugate
  // steps carry it further (measured: about half the error at equal sweeps).
  for (const int sweeps : {20, 50, 100}) {
    const real plain = columnError(30, sweeps, false);
    const real accelerated = columnError(30, sweeps, true);
    EXPECT_GT(plain, real(0.01)) << sweeps << " sweeps: the column is a hard case";
    EXPECT_LT(accelerated, real(0.7) * plain) << sweeps << " sweeps";
  }
  // Both converge to the exact answer given enough sweeps.
  EXPECT_LT(columnError(10, 5000, true), test::isFloat ? real(1e-4) : real(1e-9));
  EXPECT_LT(columnError(10, 5000, false), test::isFloat ? real(1e-4) : real(1e-9));
}

TEST(GaussSeidelSolver, ConvergenceTestSkipsARowWithANaNResponse) {
  // The sweeps stop when the largest |change| * A_kk is within the tolerance, a NaN product
  // (a body of infinite inverse inertia touched through its centre: 0 * inf) left out. A NaN
  // A_kk must not hide a smaller A_kk from the squared norm's shortcut (convergenceBound):
  // row 0 (A_kk 1e-6) changes its force by 100, a velocity of only 1e-4, and row 2's larger
  // A_kk, after the NaN, must not make that change look like a velocity of 100.
  const real inf = std::numeric_limits<real>::infinity();
  std::vector<SolverBody> bodies{{{}, 0, 0, 0},           // the ground, fixed
                                 {{}, 0, real(1e-6), 0},  // heavy: A_kk 1e-6
                                 {{}, 0, 1, inf},         // A_kk NaN (inf * 0)
                                 {{}, 0, 1, 0}};          // A_kk 1
  std::vector<ContactConstraint> rows{
      {0, 1, {0, 1}, 0, 0, real(1e-4), 0}, {0, 2, {0, 1}, 0, 0, 0, 0}, {0, 3, {0, 1}, 0, 0, 0, 0}};
  ASSERT_TRUE(std::isnan(rows[1].selfResponse(bodies[0], bodies[2])));
  const std::vector<std::uint32_t> island{0, 1, 2};
  ContactSolverSettings settings;
  settings.gaussSeidelTolerance = real(1e-3);
  for (const bool accelerate : {true, false}) {
    settings.accelerateGaussSeidel = accelerate;
    std::vector<ContactConstraint> solved = rows;
    std::vector<SolverBody> moved = bodies;
    // The first sweep's largest change * A_kk is 1e-4: converged at once.
    EXPECT_EQ(GaussSeidelSolver{}.solve(island, solved, moved, settings), 1);
    EXPECT_NEAR(solved[0].force, 100, real(1e-3));
  }
}

TEST(BaraffSolver, RedundantContactsOfAFlatCapsuleGiveTheUniqueVelocity) {
  // A capsule lying flat on a border touches it at both ends; a circle pressed on its middle
  // adds a third, redundant path. Pushed down, nothing may move down.
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.2), real(1)));
  capsule.r = {0, real(0.2)};
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.2), real(1)));
  circle.r = {real(0.3), real(0.6)};
  for (const auto kind : {ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel}) {
    simulator.setContactSolver(kind);
    circle.externalForce = {0, -5};
    capsule.externalForce = {0, -2};
    simulator.advanceTime();
    EXPECT_EQ(simulator.contacts.size(), 3u);
    EXPECT_NEAR(capsule.v.y, 0, test::loose);
    EXPECT_NEAR(capsule.omega, 0, test::loose);
    EXPECT_NEAR(circle.v.y, 0, test::loose);
    // Total contact force from the floor carries the total push.
    real floorForce = 0;
    for (const GlobalContactInfo& c : simulator.contacts)
      if (c.objectA != &circle && c.objectB != &circle) floorForce += c.force;
    EXPECT_NEAR(floorForce, 7, 1e3 * test::loose);
  }
}

/// A random island of @p rows rows between three movable bodies (0, 1, 2) and a fixed one (3),
/// with velocities, arms and targets of both signs: rows that hold, that are driven, that
/// block or release one another.
Problem randomSmallIsland(MTRandom& random, std::size_t rows) {
  Problem p;
  const auto uniform = [&](double a, double b) { return static_cast<real>(random.uniform(a, b)); };
  for (int i = 0; i < 3; ++i)
    p.bodies.push_back(
        {{uniform(-1, 1), uniform(-1, 1)}, uniform(-1, 1), uniform(0.2, 2), uniform(0.2, 5)});
  p.bodies.push_back({});
  for (std::size_t k = 0; k < rows; ++k) {
    ContactConstraint row;
    row.a = static_cast<std::uint32_t>(random.uniform(0, 4)) % 4;
    row.b = (row.a + 1 + static_cast<std::uint32_t>(random.uniform(0, 3)) % 3) % 4;
    const real angle = uniform(0, 6.283);
    row.normal = {std::cos(angle), std::sin(angle)};
    row.armA = uniform(-0.5, 0.5);
    row.armB = uniform(-0.5, 0.5);
    row.target = uniform(-1, 1);
    p.rows.push_back(row);
  }
  p.all.resize(rows);
  std::iota(p.all.begin(), p.all.end(), 0u);
  return p;
}

TEST(BaraffSolver, IslandsOfOneAndTwoRowsGiveThePivotingsBitsAndTheReference) {
  // solve() takes islands of one or two rows in closed form: the same operations as the
  // pivoting, the same bits, which solveMatrix() runs on the same matrix and slacks (built as
  // solve() builds them). The active-set enumeration is the independent reference. The last
  // trials give a row a target of NaN or an infinity: the bits must still agree.
  const auto sameBits = [](real x, real y) {
    return std::memcmp(&x, &y, sizeof(real)) == 0;  // NaN included
  };
  const real nonFinite[] = {std::numeric_limits<real>::quiet_NaN(),
                            std::numeric_limits<real>::infinity(),
                            -std::numeric_limits<real>::infinity()};
  MTRandom random(7);
  int solved = 0;
  for (int trial = 0; trial < 4600; ++trial) {
    const std::size_t rows = 1 + static_cast<std::size_t>(trial % 2);
    Problem closed = randomSmallIsland(random, rows);
    const bool finite = trial < 4000;
    if (!finite)
      closed.rows[static_cast<std::size_t>(trial / 2) % rows].target = nonFinite[trial % 3];
    Problem start = closed;

    BaraffSolver baraff;
    const bool closedSolved = baraff.solve(closed.all, closed.rows, closed.bodies);
    const int closedPivots = baraff.lastPivotCount();
    std::vector<real> matrix(rows * rows);
    std::vector<real> slack(rows);
    std::vector<real> forces(rows);
    for (std::size_t i = 0; i < rows; ++i) {
      const ContactConstraint& row = start.rows[i];
      for (std::size_t j = i; j < rows; ++j)  // the upper triangle, mirrored (buildMatrix())
        matrix[i * rows + j] = matrix[j * rows + i] =
            rigidCoupling(row, start.rows[j], start.bodies);
      slack[i] = row.normalVelocity(start.bodies[row.a], start.bodies[row.b]) - row.target;
    }
    const bool pivotSolved = baraff.solveMatrix(matrix, slack, forces);
    ASSERT_EQ(closedSolved, pivotSolved) << "trial " << trial;
    EXPECT_EQ(closedPivots, baraff.lastPivotCount()) << "trial " << trial;
    if (!closedSolved) continue;
    solved += finite ? 1 : 0;
    Problem pivoted = start;
    for (std::size_t k = 0; k < rows; ++k) {
      ContactConstraint& row = pivoted.rows[k];
      row.force = forces[k];
      row.applyImpulse(row.force, pivoted.bodies[row.a], pivoted.bodies[row.b]);
      EXPECT_TRUE(sameBits(closed.rows[k].force, row.force)) << "trial " << trial << " row " << k;
    }
    for (std::size_t i = 0; i < closed.bodies.size(); ++i) {
      const SolverBody& x = closed.bodies[i];
      const SolverBody& y = pivoted.bodies[i];
      EXPECT_TRUE(sameBits(x.v.x, y.v.x) && sameBits(x.v.y, y.v.y) && sameBits(x.omega, y.omega))
          << "trial " << trial << " body " << i;
    }
    if (!finite) continue;
    ASSERT_TRUE(referenceSolve(start)) << "trial " << trial;
    expectSameVelocities(closed, start, test::isFloat ? real(1e-4) : real(1e-9));
  }
  EXPECT_GT(solved, 3000);
}

TEST(BaraffSolver, ContradictoryTargetsFallBackWithoutExplosion) {
  // A circle squeezed between two borders closer than its diameter: both contacts demand
  // separation, which no velocity can give. The step must stay finite and bounded.
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, real(0.9)}, Vector2{0, -1}));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {0, real(0.45)};
  for (int step = 0; step < 100; ++step) simulator.advanceTime();
  EXPECT_TRUE(std::isfinite(circle.r.y));
  // Bounded: the overlap is shared somehow, but the circle is never pushed further than to
  // rest on one border (y = 0.5 on the floor, 0.4 under the ceiling).
  const real tolerance = test::isFloat ? real(1e-5) : real(1e-9);
  EXPECT_GE(circle.r.y, real(0.4) - tolerance);
  EXPECT_LE(circle.r.y, real(0.5) + tolerance);
}

TEST(Islands, SeparateGroupsAreSeparateIslands) {
  // Two rows of touching circles far apart, plus a border under both: the border, being
  // fixed, does not join them.
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  for (const real x0 : {real(0), real(10)})
    for (int i = 0; i < 3; ++i) {
      auto& c = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
      c.r = {x0 + static_cast<real>(i), real(0.5)};
      c.externalForce = {0, -1};
    }
  simulator.advanceTime();
  EXPECT_EQ(simulator.statistics().islands, 2u);
}

}  // namespace
}  // namespace thyrix
