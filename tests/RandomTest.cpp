// Tests of the seeded random stream (Tools/MTRandom.h, Tools/Random.h).

#include <Tools/MTRandom.h>
#include <Tools/Random.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace thyrix {
namespace {

TEST(MTRandomTest, StandardCheckValue) {
  // C++ standard [rand.predef]: the 10000th consecutive invocation of a default-constructed
  // mt19937 (seed 5489) produces 4123659995.
  MTRandom random;
  std::uint32_t value = 0;
  for (int i = 0; i < 10000; ++i) value = random.nextUint32();
  EXPECT_EQ(value, 4123659995u);

  MTRandom seeded(5489u);
  for (int i = 0; i < 10000; ++i) value = seeded.nextUint32();
  EXPECT_EQ(value, 4123659995u);
}

TEST(MTRandomTest, FirstOutputsOfReferenceSeed) {
  // The first outputs of MT19937 with seed 5489 (Matsumoto & Nishimura's reference
  // implementation, init_genrand(5489)).
  MTRandom random;
  EXPECT_EQ(random.nextUint32(), 3499211612u);
  EXPECT_EQ(random.nextUint32(), 581869302u);
  EXPECT_EQ(random.nextUint32(), 3890346734u);
  EXPECT_EQ(random.nextUint32(), 3586334585u);
  EXPECT_EQ(random.nextUint32(), 545404204u);
}

TEST(MTRandomTest, MatchesStdMt19937) {
  for (const std::uint32_t seed : {5489u, 0u, 1u, 42u, 4294967295u}) {
    SCOPED_TRACE(seed);
    MTRandom random(seed);
    std::mt19937 reference(seed);
    for (int i = 0; i < 2000; ++i) ASSERT_EQ(random.nextUint32(), reference()) << "draw " << i;
  }
}

TEST(MTRandomTest, SameSeedSameStream) {
  MTRandom a(12345);
  MTRandom b(12345);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.nextUint32(), b.nextUint32());
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.uniform(), b.uniform());
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.integer(-7, 13), b.integer(-7, 13));
}

TEST(MTRandomTest, SeedRestartsTheStream) {
  MTRandom random(777);
  std::vector<std::uint32_t> first;
  for (int i = 0; i < 100; ++i) first.push_back(random.nextUint32());
  random.seed(777);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(random.nextUint32(), first[i]);

  // seed() with another value gives that seed's stream, as a fresh object would.
  random.seed(5489u);
  MTRandom fresh;
  for (int i = 0; i < 100; ++i) ASSERT_EQ(random.nextUint32(), fresh.nextUint32());
}

TEST(MTRandomTest, DifferentSeedsDiffer) {
  MTRandom a(1);
  MTRandom b(2);
  int equal = 0;
  for (int i = 0; i < 1000; ++i) equal += a.nextUint32() == b.nextUint32() ? 1 : 0;
  // Two independent 32-bit streams agree on a draw with probability 2^-32.
  EXPECT_EQ(equal, 0);
}

TEST(MTRandomTest, UsableThroughTheInterface) {
  MTRandom concrete(31);
  std::mt19937 reference(31);
  Random& random = concrete;
  for (int i = 0; i < 10; ++i) EXPECT_EQ(random.nextUint32(), reference());
}

TEST(RandomTest, UniformIsInUnitIntervalWith53Bits) {
  MTRandom random(2024);
  std::mt19937 reference(2024);
  double sum = 0;
  const int draws = 100000;
  for (int i = 0; i < draws; ++i) {
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    // The documented construction (as genrand_res53 of the MT reference code): the top 27 bits
    // of one draw then the top 26 bits of the next, as a 53-bit fraction.
    const std::uint64_t high = reference() >> 5;
    const std::uint64_t low = reference() >> 6;
    ASSERT_EQ(u, static_cast<double>(high * 67108864u + low) / 9007199254740992.0);
  }
  // Mean 1/2 with standard deviation sqrt(1/12 / 100000) ~ 0.0009: 0.01 is > 10 sigma.
  EXPECT_NEAR(sum / draws, 0.5, 0.01);
}

TEST(RandomTest, UniformBoundsReachable) {
  // uniform() is 0 exactly when both draws have their used bits all zero, and its largest value
  // is 1 - 2^-53: check the extremes of the mapping through a scripted stream.
  class Scripted final : public Random {
   public:
    explicit Scripted(std::uint32_t value) : value_(value) {}
    std::uint32_t nextUint32() override { return value_; }

   private:
    std::uint32_t value_;
  };
  Scripted zeros(0);
  EXPECT_EQ(zeros.uniform(), 0.0);
  Scripted ones(0xFFFFFFFFu);
  EXPECT_EQ(ones.uniform(), 1.0 - 0x1.0p-53);
  EXPECT_LT(ones.uniform(), 1.0);
  EXPECT_FALSE(ones.bernoulli(1.0 - 0x1.0p-53));
  EXPECT_TRUE(ones.bernoulli(1.0));
  EXPECT_FALSE(zeros.bernoulli(0.0));
  EXPECT_TRUE(zeros.bernoulli(0x1.0p-60));
}

TEST(RandomTest, UniformInRange) {
  MTRandom random(3);
  for (int i = 0; i < 100000; ++i) {
    const double u = random.uniform(-2.5, 7.0);
    ASSERT_GE(u, -2.5);
    ASSERT_LT(u, 7.0);
  }
  for (int i = 0; i < 1000; ++i) {
    const double u = random.uniform(10.0, 10.5);
    ASSERT_GE(u, 10.0);
    ASSERT_LE(u, 10.5);
  }
}

TEST(RandomTest, IntegerBelowN) {
  MTRandom random(11);
  for (const std::uint32_t n : {1u, 2u, 3u, 7u, 1000u, 0x80000001u, 0xFFFFFFFFu}) {
    for (int i = 0; i < 10000; ++i) ASSERT_LT(random.integer(n), n) << "n = " << n;
  }
  for (int i = 0; i < 100; ++i) EXPECT_EQ(random.integer(1u), 0u);
}

TEST(RandomTest, IntegerBucketsAreUniform) {
  // 100000 draws in 10 buckets: each count is Binomial(100000, 0.1), mean 10000 and standard
  // deviation ~95, so +-5% (500) is over 5 sigma. The seed is fixed: the test is deterministic.
  MTRandom random(42);
  std::array<int, 10> counts{};
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t k = random.integer(10u);
    ASSERT_LT(k, 10u);
    ++counts[k];
  }
  for (int k = 0; k < 10; ++k) {
    EXPECT_GE(counts[k], 9500) << "bucket " << k;
    EXPECT_LE(counts[k], 10500) << "bucket " << k;
  }
}

TEST(RandomTest, IntegerRangeIsInclusive) {
  MTRandom random(5);
  struct Range {
    std::int32_t low;
    std::int32_t high;
  };
  for (const Range range : {Range{0, 5}, Range{-3, 2}, Range{-10, -4}, Range{-1, 1}, Range{7, 8}}) {
    SCOPED_TRACE(::testing::Message() << "[" << range.low << ", " << range.high << "]");
    bool sawLow = false;
    bool sawHigh = false;
    for (int i = 0; i < 10000; ++i) {
      const std::int32_t k = random.integer(range.low, range.high);
      ASSERT_GE(k, range.low);
      ASSERT_LE(k, range.high);
      sawLow = sawLow || k == range.low;
      sawHigh = sawHigh || k == range.high;
    }
    EXPECT_TRUE(sawLow);
    EXPECT_TRUE(sawHigh);
  }
  // A single value.
  for (int i = 0; i < 100; ++i) EXPECT_EQ(random.integer(-6, -6), -6);
  // Ranges wider than half of int32 (the span does not fit in int32).
  const std::int32_t lowest = std::numeric_limits<std::int32_t>::min();
  const std::int32_t highest = std::numeric_limits<std::int32_t>::max();
  for (int i = 0; i < 1000; ++i) {
    const std::int32_t k = random.integer(lowest, 10);
    ASSERT_GE(k, lowest);
    ASSERT_LE(k, 10);
    const std::int32_t j = random.integer(-10, highest);
    ASSERT_GE(j, -10);
  }
  // The full int32 range, [min, max], is a valid request (low <= high).
  bool sawNegative = false;
  bool sawPositive = false;
  for (int i = 0; i < 1000; ++i) {
    const std::int32_t k = random.integer(lowest, highest);
    sawNegative = sawNegative || k < 0;
    sawPositive = sawPositive || k > 0;
  }
  EXPECT_TRUE(sawNegative);
  EXPECT_TRUE(sawPositive);
}

TEST(RandomTest, IntegerRangeBucketsAreUniform) {
  // [-5, 4] has 10 values: same bounds as IntegerBucketsAreUniform.
  MTRandom random(43);
  std::array<int, 10> counts{};
  for (int i = 0; i < 100000; ++i) ++counts[static_cast<std::size_t>(random.integer(-5, 4) + 5)];
  for (int k = 0; k < 10; ++k) {
    EXPECT_GE(counts[k], 9500) << "value " << k - 5;
    EXPECT_LE(counts[k], 10500) << "value " << k - 5;
  }
}

TEST(RandomTest, Bernoulli) {
  MTRandom random(8);
  for (int i = 0; i < 10000; ++i) ASSERT_FALSE(random.bernoulli(0.0));
  for (int i = 0; i < 10000; ++i) ASSERT_TRUE(random.bernoulli(1.0));
  // p = 0.3 over 100000 draws: standard deviation of the count ~145, so +-1500 is > 10 sigma.
  int hits = 0;
  for (int i = 0; i < 100000; ++i) hits += random.bernoulli(0.3) ? 1 : 0;
  EXPECT_NEAR(hits, 30000, 1500);
}

// Marsaglia's polar method written out independently, on the uniform draws of @p stream, with
// the C library's log: MTRandom::normal() must give these numbers.
class PolarReference {
 public:
  explicit PolarReference(std::uint32_t seed) : stream_(seed) {}
  double next() {
    if (kept_) {
      kept_ = false;
      return second_;
    }
    for (;;) {
      const double u = 2 * stream_.uniform() - 1;
      const double v = 2 * stream_.uniform() - 1;
      const double s = u * u + v * v;
      if (s >= 1 || s == 0) continue;
      const double f = std::sqrt(-2 * std::log(s) / s);
      second_ = v * f;
      kept_ = true;
      return u * f;
    }
  }
  MTRandom& stream() { return stream_; }

 private:
  MTRandom stream_;
  bool kept_ = false;
  double second_ = 0;
};

TEST(MTRandomNormalTest, MatchesThePolarMethodOnTheUniformStream) {
  for (const std::uint32_t seed : {1u, 5489u, 123456789u}) {
    SCOPED_TRACE(seed);
    MTRandom random(seed);
    PolarReference reference(seed);
    for (int i = 0; i < 20000; ++i) {
      const double expected = reference.next();
      // Only the last bit of the log may differ from the C library's.
      ASSERT_NEAR(random.normal(), expected, 4e-16 * std::max(1.0, std::abs(expected)))
          << "draw " << i;
    }
    // The same uniform draws were used: the raw streams are at the same place.
    ASSERT_EQ(random.nextUint32(), reference.stream().nextUint32());
  }
}

TEST(MTRandomNormalTest, MeanVarianceAndSpread) {
  MTRandom random(2024);
  const int n = 1000000;
  double sum = 0;
  double squares = 0;
  double fourth = 0;
  int withinOne = 0;
  for (int i = 0; i < n; ++i) {
    const double x = random.normal();
    sum += x;
    squares += x * x;
    fourth += x * x * x * x;
    if (std::abs(x) < 1) ++withinOne;
  }
  // Five standard errors: mean 1/sqrt(n), variance sqrt(2/n), P(|x| < 1) sqrt(p(1-p)/n).
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0, 5 / std::sqrt(n));
  EXPECT_NEAR(squares / n - mean * mean, 1, 5 * std::sqrt(2.0 / n));
  EXPECT_NEAR(fourth / n, 3, 5 * std::sqrt(96.0 / n));  // E x^4 = 3, Var x^4 = 105 - 9
  EXPECT_NEAR(static_cast<double>(withinOne) / n, 0.682689492137, 5 * std::sqrt(0.2167 / n));

  MTRandom shifted(7);
  double shiftedSum = 0;
  double shiftedSquares = 0;
  const int m = 200000;
  for (int i = 0; i < m; ++i) {
    const double x = shifted.normal(3, 2);
    shiftedSum += x;
    shiftedSquares += x * x;
  }
  const double shiftedMean = shiftedSum / m;
  EXPECT_NEAR(shiftedMean, 3, 5 * 2 / std::sqrt(m));
  EXPECT_NEAR(shiftedSquares / m - shiftedMean * shiftedMean, 4, 5 * 4 * std::sqrt(2.0 / m));
}

TEST(MTRandomNormalTest, ScaledDrawIsMeanPlusSdTimesStandard) {
  MTRandom a(99);
  MTRandom b(99);
  for (int i = 0; i < 101; ++i) ASSERT_EQ(a.normal(-1.5, 0.25), -1.5 + 0.25 * b.normal());
  EXPECT_EQ(a.normal(4, 0), 4);
  EXPECT_THROW((void)a.normal(0, -1), std::invalid_argument);
  EXPECT_THROW((void)a.normal(0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW((void)a.normal(0, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(MTRandomNormalTest, SeedForgetsTheKeptDraw) {
  MTRandom random(11);
  (void)random.normal();  // keeps the pair's second draw
  random.seed(11);
  MTRandom fresh(11);
  for (int i = 0; i < 10; ++i) ASSERT_EQ(random.normal(), fresh.normal());
}

// Draws a mix of everything the stream offers.
std::vector<double> drawMix(MTRandom& random, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) {
    values.push_back(random.normal());
    values.push_back(random.uniform());
    values.push_back(random.integer(-5, 5));
    values.push_back(random.normal(1, 3));
    values.push_back(random.normal());
  }
  return values;
}

TEST(MTRandomStateTest, RestoreContinuesIdentically) {
  for (const int before : {0, 1, 2, 7}) {  // odd counts leave a kept normal draw in the state
    SCOPED_TRACE(before);
    MTRandom random(31337);
    for (int i = 0; i < before; ++i) (void)random.normal();
    const MTRandom::State saved = random.saveState();
    EXPECT_EQ(saved.hasSpare, before % 2 == 1);
    const std::vector<double> first = drawMix(random, 500);

    random.restoreState(saved);
    EXPECT_EQ(random.saveState(), saved);
    EXPECT_EQ(drawMix(random, 500), first);

    MTRandom other(1);  // another stream takes the state over
    other.restoreState(saved);
    EXPECT_EQ(drawMix(other, 500), first);

    std::stringstream text;
    saved.write(text);
    text << "after\n";
    const MTRandom::State read = MTRandom::State::read(text);
    EXPECT_EQ(read, saved);
    std::string rest;
    text >> rest;
    EXPECT_EQ(rest, "after") << "read() stops after the state";
    MTRandom third(2);
    third.restoreState(read);
    EXPECT_EQ(drawMix(third, 500), first);
  }
}

TEST(MTRandomStateTest, TextFormIsTheDocumentedOne) {
  // A fresh stream holds MT19937's seeding recurrence (init_genrand) and twists at its first draw.
  std::ostringstream expected;
  expected << "mt19937-state 1\n624";
  std::uint32_t word = 42;
  for (std::uint32_t i = 0; i < 624; ++i) {
    if (i > 0) word = 1812433253u * (word ^ (word >> 30)) + i;
    expected << ' ' << word;
  }
  expected << "\nspare 0 0x0p+0\n";
  std::ostringstream text;
  MTRandom(42).saveState().write(text);
  EXPECT_EQ(text.str(), expected.str());

  MTRandom random(42);
  (void)random.normal();
  const MTRandom::State state = random.saveState();
  EXPECT_TRUE(state.hasSpare);
  EXPECT_EQ(state.index, 4u) << "two uniform draws of two words each";
  std::ostringstream withSpare;
  state.write(withSpare);
  char spare[64];
  std::snprintf(spare, sizeof spare, "%a", state.spare);
  std::ostringstream line;
  line << "\nspare 1 " << spare << '\n';
  EXPECT_NE(withSpare.str().find(line.str()), std::string::npos);
}

TEST(MTRandomStateTest, RestoreRefusesAnImpossibleState) {
  MTRandom random(3);
  const MTRandom::State before = random.saveState();
  MTRandom::State bad = before;
  bad.index = 625;
  EXPECT_THROW(random.restoreState(bad), std::invalid_argument);
  bad = before;
  bad.hasSpare = true;
  bad.spare = std::numeric_limits<double>::infinity();
  EXPECT_THROW(random.restoreState(bad), std::invalid_argument);
  EXPECT_EQ(random.saveState(), before);
}

TEST(MTRandomStateTest, ReadRefusesCorruptStates) {
  MTRandom random(5);
  (void)random.normal();
  std::ostringstream good;
  random.saveState().write(good);
  const std::string text = good.str();
  const auto refused = [](const std::string& input, const std::string& expected) {
    std::istringstream in(input);
    try {
      (void)MTRandom::State::read(in);
      ADD_FAILURE() << "accepted: " << input.substr(0, 60);
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  };
  refused("", "expected 'mt19937-state'");
  refused("genome 1\n", "expected 'mt19937-state'");
  refused("mt19937-state 2\n", "version '2' is not supported");
  refused(text.substr(0, text.size() / 2), "missing word");
  const std::size_t index = text.find('\n') + 1;  // the index, then the words
  refused(text.substr(0, index) + "625 ", "index '625' is not a number from 0 to 624");
  refused(text.substr(0, index) + "-1 ", "index '-1'");
  const std::size_t firstWord = text.find(' ', index) + 1;
  std::string big = text;
  big.replace(firstWord, 0, "4294967296 ");  // one word too large, the rest shifted
  refused(big, "word 0 ('4294967296') is not a 32-bit unsigned number");
  std::string negative = text;
  negative.replace(firstWord, 0, "-1 ");
  refused(negative, "word 0 ('-1')");
  const std::size_t spare = text.find("spare");
  refused(text.substr(0, spare), "expected 'spare 0|1 VALUE'");
  refused(text.substr(0, spare) + "spare 2 0x1p+0\n", "expected 'spare 0|1 VALUE'");
  refused(text.substr(0, spare) + "spare 1 nan\n", "the spare 'nan' is not a finite number");
  refused(text.substr(0, spare) + "spare 1 1.5x\n", "the spare '1.5x'");
  std::istringstream in(text);
  EXPECT_EQ(MTRandom::State::read(in), random.saveState());
}

}  // namespace
}  // namespace thyrix
