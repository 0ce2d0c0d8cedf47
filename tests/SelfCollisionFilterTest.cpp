// Self-collision filter: the table a multi-body object declares its rules in must answer as
// they were declared, in either order, with nothing declared meaning "every pair may touch".

#include <ThyrixLite/SelfCollisionFilter.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace thyrix {
namespace {

using Apart = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

TEST(SelfCollisionFilter, WithoutRulesEveryPairOfDifferentPrimitivesMayTouch) {
  const SelfCollisionFilter filter;
  EXPECT_TRUE(filter.mayTouch(0, 1));
  EXPECT_TRUE(filter.mayTouch(7, 3));
  EXPECT_FALSE(filter.mayTouch(2, 2));
  EXPECT_EQ(filter.partOf(5), 5u);
}

TEST(SelfCollisionFilter, PartsAndPairsDeclaredApart) {
  // Primitives 0 and 1 form part 0 (a base of two shapes); 2, 3, 4 are parts 1, 2, 3 (a chain
  // 1 -> 2 -> 3 on the base); 5 is part 4, on the base too. Apart: each link and its parent,
  // one pair given twice and in both orders.
  SelfCollisionFilter filter;
  const std::vector<std::uint32_t> parts{0, 0, 1, 2, 3, 4};
  const Apart apart{{1, 0}, {2, 1}, {3, 2}, {0, 4}, {2, 3}};
  filter.assign(parts, apart);
  EXPECT_FALSE(filter.mayTouch(0, 1));  // one part
  EXPECT_FALSE(filter.mayTouch(0, 2));  // declared apart
  EXPECT_FALSE(filter.mayTouch(1, 2));
  EXPECT_FALSE(filter.mayTouch(3, 2));
  EXPECT_FALSE(filter.mayTouch(4, 3));
  EXPECT_FALSE(filter.mayTouch(5, 0));
  EXPECT_TRUE(filter.mayTouch(0, 3));  // not declared
  EXPECT_TRUE(filter.mayTouch(2, 4));
  EXPECT_TRUE(filter.mayTouch(5, 4));
  for (std::size_t a = 0; a < parts.size(); ++a)
    for (std::size_t b = 0; b < parts.size(); ++b)
      EXPECT_EQ(filter.mayTouch(a, b), filter.mayTouch(b, a)) << a << ", " << b;
  EXPECT_EQ(filter.partOf(1), 0u);
  EXPECT_EQ(filter.partOf(5), 4u);

  // Assigning again replaces the rules.
  filter.assign(parts, Apart{});
  EXPECT_TRUE(filter.mayTouch(0, 2));
  EXPECT_FALSE(filter.mayTouch(0, 1));
}

TEST(SelfCollisionFilter, NearAndFarPrimitivesAgreeWithTheParts) {
  // A chain of 150 parts, one primitive each after a base of three (part 0), each link apart
  // from its parent, plus links 10 and 120 declared apart (far apart in the order, past the
  // near bits) and 5 and 70 (just past them). Every pair, near or far, in both orders, agrees
  // with partsMayTouch() on their parts.
  std::vector<std::uint32_t> parts{0, 0, 0};
  Apart apart;
  for (std::uint32_t p = 1; p <= 150; ++p) {
    parts.push_back(p);
    apart.emplace_back(p, p - 1);
  }
  apart.emplace_back(11, 121);
  apart.emplace_back(6, 71);
  SelfCollisionFilter filter;
  filter.assign(parts, apart);
  for (std::size_t a = 0; a < parts.size(); ++a)
    for (std::size_t b = 0; b < parts.size(); ++b)
      ASSERT_EQ(filter.mayTouch(a, b), filter.partsMayTouch(parts[a], parts[b])) << a << ", " << b;
  EXPECT_FALSE(filter.mayTouch(13, 123));  // links 10 and 120: primitives 13 and 123
  EXPECT_FALSE(filter.mayTouch(73, 8));
  EXPECT_TRUE(filter.mayTouch(13, 124));
  EXPECT_FALSE(filter.mayTouch(40, 41));
  EXPECT_TRUE(filter.mayTouch(40, 42));
  EXPECT_FALSE(filter.mayTouch(1, 2));  // the base's own
  EXPECT_FALSE(filter.mayTouch(2, 3));  // the base and link 0
}

}  // namespace
}  // namespace thyrix
