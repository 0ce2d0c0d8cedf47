// The geometry of the visual sensor, against hand-computed arcs: splitting arcs at +-pi, the
// extents of disks and capsules, and the union of intervals.

#include <ThyrixLite/AngularCoverage.h>
#include <Tools/MathTools.h>
#include <gtest/gtest.h>

#include "TestTolerances.h"

#include <cmath>
#include <vector>

namespace thyrix {
namespace {

using test::tight;
constexpr real kPi = pi<real>;

void expectPieces(const AngularExtent& extent, const std::vector<AngularInterval>& expected) {
  EXPECT_FALSE(extent.wholeCircle);
  ASSERT_EQ(extent.count, static_cast<int>(expected.size()));
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(extent.intervals[i].begin, expected[i].begin, tight) << "piece " << i;
    EXPECT_NEAR(extent.intervals[i].end, expected[i].end, tight) << "piece " << i;
  }
}

void expectWhole(const AngularExtent& extent) {
  EXPECT_TRUE(extent.wholeCircle);
  ASSERT_EQ(extent.count, 1);
  EXPECT_EQ(extent.intervals[0].begin, -kPi);
  EXPECT_EQ(extent.intervals[0].end, kPi);
}

TEST(AngularCoverageTest, SplitAtPi) {
  expectPieces(splitAtPi(-1, 1), {{-1, 1}});
  expectPieces(splitAtPi(real(2.5), real(3.5)), {{real(2.5), kPi}, {-kPi, real(3.5) - 2 * kPi}});
  expectPieces(splitAtPi(real(-3.5), real(-2.5)),
               {{real(-3.5) + 2 * kPi, kPi}, {-kPi, real(-2.5)}});
  // Shifted by 2 pi first: the middle 7.5 lies beyond pi.
  expectPieces(splitAtPi(7, 8), {{7 - 2 * kPi, 8 - 2 * kPi}});
  expectWhole(splitAtPi(-4, 3));
  EXPECT_EQ(splitAtPi(1, -1).count, 0);
}

TEST(AngularCoverageTest, DiskExtent) {
  // R = 1 at d = 2 straight along the reference (pi/2, from (1, 1)): +-pi/6.
  expectPieces(diskExtent({1, 1}, kPi / 2, {1, 3}, 1), {{-kPi / 6, kPi / 6}});
  // The same with the reference as a unit vector, the disk 0.3 rad counter-clockwise of it.
  expectPieces(diskExtent({}, Vector2{1, 0}, {2 * std::cos(real(0.3)), 2 * std::sin(real(0.3))}, 1),
               {{real(0.3) - kPi / 6, real(0.3) + kPi / 6}});
  // Behind: split at +-pi.
  expectPieces(diskExtent({}, real(0), {-2, 0}, 1), {{5 * kPi / 6, kPi}, {-kPi, -5 * kPi / 6}});
  expectWhole(diskExtent({}, real(0), {real(0.5), 0}, 1));  // inside
  expectWhole(diskExtent({}, real(0), {0, 2}, 2));          // touching
}

TEST(AngularCoverageTest, CapsuleExtent) {
  // Broadside, ends (1, -1) and (1, 1), R = sqrt(2)/2: tangents at +-(pi/4 + pi/6).
  const real R = std::sqrt(real(2)) / 2;
  expectPieces(capsuleExtent({}, real(0), {1, -1}, {1, 1}, R), {{-5 * kPi / 12, 5 * kPi / 12}});
  // The ends given the other way round.
  expectPieces(capsuleExtent({}, real(0), {1, 1}, {1, -1}, R), {{-5 * kPi / 12, 5 * kPi / 12}});
  // The same behind the eye: split at +-pi.
  expectPieces(capsuleExtent({}, real(0), {-1, -1}, {-1, 1}, R),
               {{7 * kPi / 12, kPi}, {-kPi, -7 * kPi / 12}});
  // End on: the nearer cap, R = 1 at d = 2.
  expectPieces(capsuleExtent({}, real(0), {2, 0}, {4, 0}, 1), {{-kPi / 6, kPi / 6}});
  // A capsule of zero length is a disk.
  expectPieces(capsuleExtent({}, real(0), {0, 2}, {0, 2}, 1), {{kPi / 3, 2 * kPi / 3}});
  expectWhole(capsuleExtent({}, real(0), {-3, real(0.2)}, {3, real(0.2)}, real(0.5)));  // inside
  expectWhole(capsuleExtent({}, real(0), {1, -1}, {1, 1}, 1));                          // touching
}

TEST(AngularCoverageTest, UnionCountsOverlapsOnce) {
  AngularCoverage coverage;
  coverage.reserve(8);
  coverage.add(AngularInterval{3, 4});
  coverage.add(AngularInterval{real(0.5), 2});
  coverage.add(AngularInterval{0, 1});
  coverage.add(AngularInterval{2, real(2.5)});  // touches [0.5, 2]
  coverage.add(AngularInterval{1, 1});          // empty: ignored
  coverage.add(AngularInterval{2, 1});          // reversed: ignored
  EXPECT_FALSE(coverage.merged());
  coverage.merge();
  EXPECT_TRUE(coverage.merged());
  ASSERT_EQ(coverage.intervals().size(), 2u);
  EXPECT_EQ(coverage.intervals()[0].begin, 0);
  EXPECT_EQ(coverage.intervals()[0].end, real(2.5));
  EXPECT_EQ(coverage.intervals()[1].begin, 3);
  EXPECT_EQ(coverage.intervals()[1].end, 4);
  EXPECT_NEAR(coverage.covered(-1, 5), real(3.5), tight);
  EXPECT_NEAR(coverage.covered(1, real(3.5)), 2, tight);
  EXPECT_EQ(coverage.covered(real(2.6), real(2.9)), 0);
  EXPECT_EQ(coverage.covered(5, 4), 0);
  coverage.clear();
  EXPECT_TRUE(coverage.intervals().empty());
  EXPECT_EQ(coverage.covered(-1, 5), 0);
}

TEST(AngularCoverageTest, CoveredFractionsOfBins) {
  AngularCoverage coverage;
  coverage.add(AngularInterval{real(1.1), real(1.2)});
  coverage.add(AngularInterval{real(0.2), real(0.7)});
  coverage.add(AngularInterval{real(2.5), 7});  // beyond the last bin from 2.5 on
  coverage.merge();
  std::vector<real> fractions(6, real(-1));
  coverage.coveredFractions(0, real(0.5), fractions);
  const std::vector<real> expected{real(0.6), real(0.4), real(0.2), 0, 0, 1};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(fractions[i], expected[i], tight) << "bin " << i;
  EXPECT_EQ(fractions[5], 1);  // a full bin is exactly 1
  // Bins starting before every interval and ending after them.
  std::vector<real> wide(2);
  coverage.coveredFractions(-10, 10, wide);
  EXPECT_EQ(wide[0], 0);
  EXPECT_NEAR(wide[1], (real(0.5) + real(0.1) + real(4.5)) / 10, tight);
}

}  // namespace
}  // namespace thyrix
