// The order of Gauss-Seidel's sweeps: an island's rows in order of their keys
// (ContactConstraint::order, the contact's height in a world with gravity), and the cap of
// sweeps that goes with it.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/GaussSeidelSolver.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace thyrix {
namespace {

/// A column of @p count unit disks standing on a fixed floor (body 0), each moving down at 1
/// m/s without contacts (its weight); row i joins body i to body i + 1, from the floor up.
struct Column {
  std::vector<SolverBody> bodies;
  std::vector<ContactConstraint> rows;

  explicit Column(std::uint32_t count) {
    bodies.push_back({});  // the floor
    for (std::uint32_t i = 0; i < count; ++i) bodies.push_back({{0, -1}, 0, 1, 0});
    for (std::uint32_t i = 0; i < count; ++i)
      rows.push_back({i, i + 1, {0, 1}, 0, 0, 0, 0, static_cast<real>(i)});
  }
};

/// The bits of every force and velocity, to compare two solves exactly.
std::vector<std::uint64_t> bitsOf(const Column& column) {
  std::vector<std::uint64_t> bits;
  for (const ContactConstraint& row : column.rows)
    bits.push_back(std::bit_cast<std::uint64_t>(double(row.force)));
  for (const SolverBody& body : column.bodies) {
    bits.push_back(std::bit_cast<std::uint64_t>(double(body.v.x)));
    bits.push_back(std::bit_cast<std::uint64_t>(double(body.v.y)));
  }
  return bits;
}

/// One projected sweep (no acceleration) of @p column over the rows listed in @p island.
void sweepOnce(Column& column, const std::vector<std::uint32_t>& island) {
  ContactSolverSettings settings;
  settings.accelerateGaussSeidel = false;
  settings.gaussSeidelTolerance = 0;
  settings.gaussSeidelMaxIterations = settings.gaussSeidelMaxIterationsInHeightOrder = 1;
  GaussSeidelSolver{}.solve(island, column.rows, column.bodies, settings);
}

TEST(SweepOrder, RowsAreSweptInOrderOfTheirKeys) {
  // The island lists the column from the top down, the keys say from the bottom up: one sweep
  // gives the bits of a sweep over the island listed from the bottom up, keys all equal.
  Column byKeys(10);
  Column byIsland(10);
  for (ContactConstraint& row : byIsland.rows) row.order = 0;
  sweepOnce(byKeys, {9, 8, 7, 6, 5, 4, 3, 2, 1, 0});
  sweepOnce(byIsland, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_EQ(bitsOf(byKeys), bitsOf(byIsland));
  // From the floor up, the floor's reaction reaches the top disk in the one sweep; listed
  // from the top down, keys all equal, it reaches only the lowest disk.
  EXPECT_GT(byKeys.bodies[10].v.y, -1);
  Column topDown(10);
  for (ContactConstraint& row : topDown.rows) row.order = 0;
  sweepOnce(topDown, {9, 8, 7, 6, 5, 4, 3, 2, 1, 0});
  EXPECT_EQ(topDown.bodies[10].v.y, -1);
  EXPECT_EQ(topDown.bodies[1].v.y, 0);
}

TEST(SweepOrder, KeysThatCannotBeOrderedLeaveTheIslandOrder) {
  // An infinite range of keys: island order, as with keys all equal.
  const real inf = std::numeric_limits<real>::infinity();
  Column infinite(6);
  Column equal(6);
  infinite.rows[2].order = inf;
  infinite.rows[4].order = -inf;
  for (ContactConstraint& row : equal.rows) row.order = 0;
  const std::vector<std::uint32_t> island{5, 3, 1, 0, 2, 4};
  sweepOnce(infinite, island);
  sweepOnce(equal, island);
  EXPECT_EQ(bitsOf(infinite), bitsOf(equal));
  // A NaN key is swept first; the others still in order.
  Column withNaN(6);
  Column nanFirst(6);
  withNaN.rows[3].order = std::numeric_limits<real>::quiet_NaN();
  for (ContactConstraint& row : nanFirst.rows) row.order = 0;
  sweepOnce(withNaN, island);
  sweepOnce(nanFirst, {3, 0, 1, 2, 4, 5});
  EXPECT_EQ(bitsOf(withNaN), bitsOf(nanFirst));
}

TEST(SweepOrder, AcceleratedSweepsInKeyOrderConvergeToTheSameForces) {
  // The order changes the path, not the answer: each contact carries the weight above it.
  for (const bool byHeight : {true, false}) {
    Column column(30);
    if (!byHeight)
      for (ContactConstraint& row : column.rows) row.order = 0;
    std::vector<std::uint32_t> island;
    for (std::uint32_t k = 30; k-- > 0;) island.push_back(k);  // from the top down
    ContactSolverSettings settings;
    settings.gaussSeidelTolerance = 0;
    settings.gaussSeidelMaxIterations = settings.gaussSeidelMaxIterationsInHeightOrder = 5000;
    GaussSeidelSolver{}.solve(island, column.rows, column.bodies, settings);
    for (std::size_t k = 0; k < column.rows.size(); ++k)
      EXPECT_NEAR(column.rows[k].force, static_cast<real>(30 - k), 100 * test::loose) << k;
    for (const SolverBody& body : column.bodies) EXPECT_NEAR(body.v.y, 0, test::loose);
  }
}

/// A pile of @p columns x @p layers disks on a floor, pressed down by a gravity field or, with
/// @p byHand, by the same weight added as a force; one step from zero forces, tolerance 0.
/// @return the sweeps of that step.
std::size_t sweepsOfAPile(bool byHand, bool heightOrder) {
  Simulator simulator(real(0.01));
  simulator.setContactSolver(ContactSolverKind::GaussSeidel);
  ContactSolverSettings& settings = simulator.solverSettings();
  settings.gaussSeidelTolerance = 0;
  settings.gaussSeidelHeightOrder = heightOrder;
  const Vector2 g{0, -1};
  if (!byHand) simulator.setGravity(g);
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  std::vector<PhysicalObject*> disks;
  for (int layer = 0; layer < 6; ++layer)
    for (int column = 0; column < 5; ++column) {
      auto& disk = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
      disk.r = {static_cast<real>(column) + (layer % 2 == 0 ? 0 : real(0.5)),
                real(0.5) + real(0.86) * static_cast<real>(layer)};
      disks.push_back(&disk);
    }
  if (byHand)
    for (PhysicalObject* disk : disks) disk->externalForce += g * disk->m;
  simulator.advanceTime();
  EXPECT_EQ(simulator.statistics().solvedIslands, 1u);
  return simulator.statistics().gaussSeidelSweeps;
}

TEST(SweepOrder, AnIslandInHeightOrderHasItsOwnCapOfSweeps) {
  const ContactSolverSettings defaults;
  EXPECT_EQ(sweepsOfAPile(false, true),
            static_cast<std::size_t>(defaults.gaussSeidelMaxIterationsInHeightOrder));
  // Without gravity, or with the order turned off: detection order, the general cap.
  EXPECT_EQ(sweepsOfAPile(true, true), static_cast<std::size_t>(defaults.gaussSeidelMaxIterations));
  EXPECT_EQ(sweepsOfAPile(false, false),
            static_cast<std::size_t>(defaults.gaussSeidelMaxIterations));
}

}  // namespace
}  // namespace thyrix
