// The strategies on the classic test functions (Hansen's tutorial; Beyer and Schwefel), their
// ask/tell contract, and checkpoints that continue bit for bit.

#include <Evolution/CmaEs.h>
#include <Evolution/SelfAdaptiveEs.h>
#include <ThyrixLite/InvalidArgument.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

namespace thyrix {
namespace {

double sphere(const std::vector<double>& x) {
  double sum = 0;
  for (double xi : x) sum += xi * xi;
  return sum;
}

double rosenbrock(const std::vector<double>& x) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i)
    sum += 100 * std::pow(x[i] * x[i] - x[i + 1], 2) + std::pow(x[i] - 1, 2);
  return sum;
}

// Runs @p strategy minimizing @p cost until the best cost of a generation is below @p target
// or @p budget evaluations are spent; returns the evaluations used (or budget + 1).
long minimize(Strategy& strategy, const std::function<double(const std::vector<double>&)>& cost,
              double target, long budget, double* best = nullptr) {
  long evaluations = 0;
  double lowest = INFINITY;
  while (evaluations < budget) {
    const auto population = strategy.ask();
    std::vector<double> fitness;
    for (const std::vector<double>& x : population) {
      const double f = cost(x);
      lowest = std::min(lowest, f);
      fitness.push_back(-f);
    }
    evaluations += static_cast<long>(population.size());
    strategy.tell(fitness);
    if (lowest < target) break;
  }
  if (best) *best = lowest;
  return lowest < target ? evaluations : budget + 1;
}

TEST(CmaEsTest, DefaultSettingsFollowTheTutorial) {
  const CmaEs cma(std::vector<double>(10, 0.0), 1);
  EXPECT_EQ(cma.populationSize(), 10u);  // 4 + floor(3 ln 10)
  EXPECT_EQ(cma.parentCount(), 5u);
  // mu_eff for lambda = 10: (sum w')^2 / sum w'^2 with w'_i = ln(5.5) - ln i, i = 1..5.
  double sum = 0, squares = 0;
  for (int i = 1; i <= 5; ++i) {
    const double w = std::log(5.5) - std::log(i);
    sum += w;
    squares += w * w;
  }
  EXPECT_NEAR(cma.effectiveParents(), sum * sum / squares, 1e-12);
}

TEST(CmaEsTest, ReachesOneInAHundredMillionOnTheSphereInTen) {
  // Hansen's tutorial: about 1,000 to 2,000 evaluations on the 10-D sphere to 1e-8 from sigma 1.
  CmaEs cma(std::vector<double>(10, 1.0), 1.0, 0, 3);
  double best = 0;
  const long used = minimize(cma, sphere, 1e-8, 3000, &best);
  EXPECT_LE(used, 3000) << "best " << best;
  for (double m : cma.mean()) EXPECT_NEAR(m, 0, 1e-3);
}

TEST(CmaEsTest, SolvesRosenbrockInTen) {
  // The tutorial's reference run: about 6,000 evaluations to 1e-8 from the origin.
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    CmaEs cma(std::vector<double>(10, 0.0), 0.5, 0, seed);
    double best = 0;
    const long used = minimize(cma, rosenbrock, 1e-8, 20000, &best);
    EXPECT_LE(used, 20000) << "seed " << seed << ", best " << best;
    for (double m : cma.mean()) EXPECT_NEAR(m, 1, 1e-2) << "seed " << seed;
  }
}

TEST(CmaEsTest, LearnsTheScalesOfAnIllConditionedEllipsoid) {
  // f = sum 10^(6 (i / (n - 1))) x_i^2: C must learn axes 1000 times apart; sigma alone cannot.
  const auto ellipsoid = [](const std::vector<double>& x) {
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      sum += std::pow(10.0, 6.0 * static_cast<double>(i) / static_cast<double>(x.size() - 1)) *
             x[i] * x[i];
    return sum;
  };
  CmaEs cma(std::vector<double>(6, 1.0), 1.0, 0, 5);
  EXPECT_LE(minimize(cma, ellipsoid, 1e-8, 20000), 20000);
  // The covariance's first and last variances differ by about the function's 1e6 ratio.
  const auto c = cma.covariance();
  EXPECT_GT(c[0] / c[35], 1e4);
}

TEST(SelfAdaptiveEsTest, ConvergesOnTheSphere) {
  SelfAdaptiveEs es(std::vector<double>(10, 1.0), 1.0, 12, 3, 4);
  double best = 0;
  EXPECT_LE(minimize(es, sphere, 1e-8, 30000, &best), 30000) << "best " << best;
}

// Runs 2 g generations straight, and g generations, a save, a restore into a fresh strategy
// and g more: the same population at every step, bit for bit. The save is taken between ask()
// and tell() when @p midGeneration.
template <class S, class Make>
void expectCheckpointContinues(Make make, bool midGeneration) {
  const auto step = [](Strategy& s) {
    const auto population = s.ask();
    std::vector<double> fitness;
    for (const auto& x : population) fitness.push_back(-rosenbrock(x));
    s.tell(fitness);
  };
  S straight = make(1);
  S first = make(1);
  for (int g = 0; g < 30; ++g) {
    step(straight);
    step(first);
  }
  if (midGeneration) {
    (void)straight.ask();
    (void)first.ask();
  }
  std::stringstream saved;
  first.save(saved);
  S resumed = make(99);  // another seed: the restore must bring the stream too
  resumed.restore(saved);
  EXPECT_EQ(resumed.generation(), first.generation());
  for (int g = 0; g < 30; ++g) {
    const auto a = straight.ask();
    const auto b = resumed.ask();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], b[k]) << g << " " << k;
    step(straight);
    step(resumed);
  }
  std::stringstream x, y;
  straight.save(x);
  resumed.save(y);
  EXPECT_EQ(x.str(), y.str());
}

TEST(CmaEsTest, CheckpointContinuesBitForBit) {
  const auto make = [](std::uint32_t seed) {
    return CmaEs(std::vector<double>(5, 0.0), 0.5, 0, seed);
  };
  expectCheckpointContinues<CmaEs>(make, false);
  expectCheckpointContinues<CmaEs>(make, true);
}

TEST(SelfAdaptiveEsTest, CheckpointContinuesBitForBit) {
  const auto make = [](std::uint32_t seed) {
    return SelfAdaptiveEs(std::vector<double>(5, 0.0), 0.5, 8, 2, seed);
  };
  expectCheckpointContinues<SelfAdaptiveEs>(make, false);
  expectCheckpointContinues<SelfAdaptiveEs>(make, true);
}

TEST(CmaEsTest, RestoreRefusesCorruptOrMismatchedStatesAndKeepsItsOwn) {
  CmaEs cma(std::vector<double>(3, 0.0), 0.5);
  (void)cma.ask();
  std::stringstream good;
  cma.save(good);
  const std::string text = good.str();
  std::stringstream before;
  cma.save(before);

  const auto refuses = [&](const std::string& state, const std::string& message, Strategy& s) {
    std::stringstream in(state);
    try {
      s.restore(in);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
  };
  std::size_t fifthLine = 0;
  for (int i = 0; i < 5; ++i) fifthLine = text.find('\n', fifthLine) + 1;
  refuses(text.substr(0, fifthLine), "ends early", cma);
  refuses(text.substr(0, text.size() - 100), "random stream", cma);
  const std::size_t sigma = text.find("sigma 1 ");
  ASSERT_NE(sigma, std::string::npos);
  std::string nan = text.substr(0, sigma + 8);
  nan += "x";
  nan += text.substr(sigma + 9);
  refuses(nan, "not a finite number", cma);
  CmaEs other(std::vector<double>(4, 0.0), 0.5);
  refuses(text, "dimension 3, this CMA-ES 4", other);
  CmaEs wider(std::vector<double>(3, 0.0), 0.5, 20);
  refuses(text, "population", wider);
  SelfAdaptiveEs es(std::vector<double>(3, 0.0), 0.5, 8);
  refuses(text, "not of the self-adaptive ES", es);

  std::stringstream after;
  cma.save(after);
  EXPECT_EQ(after.str(), before.str());
}

TEST(CmaEsTest, RefusesBadSettingsAndFitnesses) {
  const auto field = [](auto make) {
    try {
      make();
    } catch (const InvalidArgument& error) {
      return error.field();
    }
    return std::string("none");
  };
  EXPECT_EQ(field([] { CmaEs({}, 1); }), "CmaEs.mean");
  EXPECT_EQ(field([] { CmaEs({NAN}, 1); }), "CmaEs.mean");
  EXPECT_EQ(field([] { CmaEs({0}, 0); }), "CmaEs.sigma");
  EXPECT_EQ(field([] { CmaEs({0}, 1, 1); }), "CmaEs.population");
  EXPECT_EQ(field([] { SelfAdaptiveEs({0}, 1, 4, 4); }), "SelfAdaptiveEs.parents");

  CmaEs cma({0, 0}, 1, 4);
  EXPECT_EQ(field([&] { cma.tell(std::vector<double>(4, 0.0)); }), "CmaEs.fitnesses");
  (void)cma.ask();
  EXPECT_EQ(field([&] { cma.tell(std::vector<double>(3, 0.0)); }), "CmaEs.fitnesses");
  EXPECT_EQ(field([&] { cma.tell(std::vector<double>{0, 0, NAN, 0}); }), "CmaEs.fitnesses");
  EXPECT_EQ(cma.generation(), 0u);
  cma.tell(std::vector<double>(4, 0.0));
  EXPECT_EQ(cma.generation(), 1u);
}

}  // namespace
}  // namespace thyrix
