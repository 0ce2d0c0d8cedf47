// Tests of the genome file (Controller/Genome.h): the documented text form, an exact round
// trip, and every kind of corrupt or mismatched genome refused with a message saying why.

#include <Controller/Genome.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace thyrix {
namespace {

// Expects read() to refuse @p text with a message containing @p expected.
void expectRefused(const std::string& text, const std::string& expected) {
  std::istringstream in(text);
  try {
    (void)Genome::read(in);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos)
        << "message: " << error.what() << "\nexpected to contain: " << expected;
  }
}

// A genome whose parameters span many exponents, signs, zeros and subnormals.
Genome randomGenome(NetworkSpec spec, std::uint32_t seed) {
  Genome genome;
  genome.spec = std::move(spec);
  MTRandom random(seed);
  genome.parameters.resize(genome.spec.parameterCount());
  for (real& value : genome.parameters) {
    const double mantissa = random.uniform(-1, 1);
    const int exponent = random.integer(-30, 30);
    value = static_cast<real>(std::ldexp(mantissa, exponent));
  }
  genome.parameters[0] = real(-0.0);
  genome.parameters[1] = std::numeric_limits<real>::denorm_min();
  genome.parameters[2] = std::numeric_limits<real>::max();
  genome.parameters[3] = real(0.1);
  return genome;
}

std::string text(const Genome& genome) {
  std::ostringstream out;
  genome.write(out);
  return out.str();
}

TEST(GenomeTest, RoundTripIsExact) {
  for (const NetworkSpec& spec :
       {NetworkSpec{NetworkKind::FeedForward, {35, 8, 5}, Activation::Tanh},
        NetworkSpec{NetworkKind::FeedForward, {3, 4, 4, 2}, Activation::Logistic},
        NetworkSpec{NetworkKind::Ctrnn, {35, 8, 5}, Activation::Logistic},
        NetworkSpec{NetworkKind::Ctrnn, {2, 3, 1}, Activation::Tanh}}) {
    const Genome genome = randomGenome(spec, 17);
    std::istringstream in(text(genome));
    const Genome back = Genome::read(in);
    EXPECT_EQ(back.spec, genome.spec);
    ASSERT_EQ(back.parameters.size(), genome.parameters.size());
    for (std::size_t p = 0; p < genome.parameters.size(); ++p)
      ASSERT_EQ(std::memcmp(&back.parameters[p], &genome.parameters[p], sizeof(real)), 0)
          << "parameter " << p << ": " << back.parameters[p] << " vs " << genome.parameters[p];
    EXPECT_EQ(text(back), text(genome));
  }
}

TEST(GenomeTest, TextFormIsTheDocumentedOne) {
  Genome genome;
  genome.spec = {NetworkKind::Ctrnn, {1, 1, 1}, Activation::Logistic};
  genome.parameters = {real(0.75), real(-2), real(0.5), real(0), real(1), real(-0.125)};
  EXPECT_EQ(text(genome),
            "thyrix-genome 1\n"
            "kind ctrnn\n"
            "activation logistic\n"
            "layers 1 1 1\n"
            "parameters 6\n"
            "0x1.8p-1\n"
            "-0x1p+1\n"
            "0x1p-1\n"
            "0x0p+0\n"
            "0x1p+0\n"
            "-0x1p-3\n");
}

TEST(GenomeTest, ReadsDecimalsWrittenByHand) {
  std::istringstream in(
      "thyrix-genome 1\nkind feed-forward\nactivation tanh\nlayers 2 1\nparameters 3\n"
      "0.5\n-1.25e1\n  3  \n\n");
  const Genome genome = Genome::read(in);
  EXPECT_EQ(genome.spec, (NetworkSpec{NetworkKind::FeedForward, {2, 1}, Activation::Tanh}));
  EXPECT_EQ(genome.parameters, (std::vector<real>{real(0.5), real(-12.5), real(3)}));
}

TEST(GenomeTest, MakeControllerRunsTheGenome) {
  const Genome genome = randomGenome({NetworkKind::Ctrnn, {3, 2, 2}, Activation::Tanh}, 5);
  const auto controller = genome.makeController(real(0.02));
  EXPECT_EQ(controller->spec(), genome.spec);
  EXPECT_EQ(controller->timestep(), real(0.02));
  EXPECT_EQ(std::vector<real>(controller->parameters().begin(), controller->parameters().end()),
            genome.parameters);
  genome.requireShape(3, 2);
  try {
    genome.requireShape(35, 5);
    ADD_FAILURE() << "a 3-input genome accepted for 35 sensors";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(),
                 "the genome's network has 3 inputs and 2 outputs, but the agent has 35 sensors "
                 "and 5 effectors");
  }
}

TEST(GenomeTest, WriteRefusesAnInconsistentGenome) {
  Genome genome;
  genome.spec = {NetworkKind::FeedForward, {2, 1}, Activation::Tanh};
  genome.parameters = {1, 2};
  std::ostringstream out;
  try {
    genome.write(out);
    ADD_FAILURE() << "wrote 2 parameters for 3";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "Genome.parameters");
  }
  genome.parameters = {1, 2, std::numeric_limits<real>::quiet_NaN()};
  EXPECT_THROW(genome.write(out), InvalidArgument);
  genome.parameters = {1, 2, 3};
  genome.spec.layers = {2};
  EXPECT_THROW(genome.write(out), InvalidArgument);
  EXPECT_TRUE(out.str().empty()) << "nothing is written before the checks";
}

TEST(GenomeTest, RefusesCorruptGenomes) {
  const std::string head = "thyrix-genome 1\nkind feed-forward\nactivation tanh\n";
  const std::string good = head + "layers 2 1\nparameters 3\n1\n2\n3\n";
  {
    std::istringstream in(good);
    EXPECT_NO_THROW((void)Genome::read(in));
  }
  expectRefused("", "genome line 1: missing");
  expectRefused("hello world\n", "line 1: not a Thyrix genome");
  expectRefused("thyrix-genome 2\n", "line 1: version 2 is not supported");
  expectRefused("thyrix-genome 1\nkind lstm\n", "line 2: unknown kind");
  expectRefused("thyrix-genome 1\nactivation tanh\n", "line 2: expected 'kind");
  expectRefused("thyrix-genome 1\nkind ctrnn\nactivation relu\n", "line 3: unknown activation");
  expectRefused(head + "layers 2 x\n", "line 4: layer size 'x' is not a count");
  expectRefused(head + "layers 2 -1\n", "line 4: layer size '-1' is not a count");
  expectRefused(head + "layers 2 0\n", "line 4: NetworkSpec.layers");
  expectRefused(head + "layers 2\n", "line 4: NetworkSpec.layers");
  expectRefused(head + "layers 99999999999999999999 1\n", "is not a count");
  expectRefused("thyrix-genome 1\nkind ctrnn\nactivation tanh\nlayers 2 1\n",
                "line 4: NetworkSpec.layers of a Ctrnn");
  expectRefused(head + "layers 2 1\nparameters 4\n",
                "line 5: declares 4 parameters, but a feed-forward network of these layers has 3");
  expectRefused(head + "layers 2 1\nparameters\n", "line 5: expected 'parameters COUNT'");
  expectRefused(head + "layers 2 1\nparameters 3\n1\n2\n", "line 8: missing: expected parameter 2");
  expectRefused(head + "layers 2 1\nparameters 3\n1\nabc\n3\n", "line 7: parameter 1 is not");
  expectRefused(head + "layers 2 1\nparameters 3\n1\n2 3\n", "line 7: parameter 1 is not");
  expectRefused(head + "layers 2 1\nparameters 3\n1\n2x\n3\n", "line 7: parameter 1 is not");
  expectRefused(head + "layers 2 1\nparameters 3\n1\nnan\n3\n", "line 7: parameter 1 is not");
  expectRefused(head + "layers 2 1\nparameters 3\n1\ninf\n3\n", "line 7: parameter 1 is not");
  expectRefused(head + "layers 2 1\nparameters 3\n1\n1e999\n3\n", "line 7: parameter 1 is not");
  expectRefused(good + "4\n", "line 9: unexpected text after the last parameter");
}

TEST(GenomeTest, LoadNamesTheFile) {
  try {
    (void)Genome::load("/nonexistent/dir/best.genome");
    ADD_FAILURE() << "loaded a missing file";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "/nonexistent/dir/best.genome: cannot be opened");
  }
}

}  // namespace
}  // namespace thyrix
