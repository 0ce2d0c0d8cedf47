// Tests of the neural networks (Controller/NeuralNetwork.h, Controller/NeuralController.h):
// outputs computed by hand from the documented parameter order, a CTRNN neuron against the
// closed forms of its step response and decay, and bad input.

#include "TestTolerances.h"
#include "support/AllocationCounter.h"

#include <Controller/NeuralController.h>
#include <Controller/NeuralNetwork.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MTRandom.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace thyrix {
namespace {

// Expects InvalidArgument naming @p field.
template <typename Action>
void expectInvalid(Action action, const char* field) {
  try {
    action();
    ADD_FAILURE() << "no exception, expected one naming " << field;
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), field) << error.what();
  }
}

NetworkSpec feedForward(std::vector<std::size_t> layers, Activation activation = Activation::Tanh) {
  return {NetworkKind::FeedForward, std::move(layers), activation};
}

NetworkSpec ctrnn(std::size_t inputs, std::size_t neurons, std::size_t outputs,
                  Activation activation = Activation::Logistic) {
  return {NetworkKind::Ctrnn, {inputs, neurons, outputs}, activation};
}

TEST(NetworkSpecTest, ParameterCount) {
  // Feed-forward: each layer has a bias per unit and a weight per unit and source.
  EXPECT_EQ(feedForward({35, 8, 5}).parameterCount(), std::size_t{(35 + 1) * 8 + (8 + 1) * 5});
  EXPECT_EQ(feedForward({2, 1}).parameterCount(), std::size_t{3});
  EXPECT_EQ(feedForward({2, 3, 4, 1}).parameterCount(),
            std::size_t{(2 + 1) * 3 + (3 + 1) * 4 + (4 + 1) * 1});
  // CTRNN of I inputs, N neurons, O outputs: taus, biases, I*N gains, N*N weights, O output
  // biases, N*O output weights.
  EXPECT_EQ(ctrnn(3, 4, 2).parameterCount(), std::size_t{4 + 4 + 3 * 4 + 4 * 4 + 2 + 4 * 2});
  EXPECT_EQ(ctrnn(35, 8, 5).parameterCount(), std::size_t{8 + 8 + 35 * 8 + 64 + 5 + 40});
  EXPECT_EQ(ctrnn(35, 8, 5).inputCount(), std::size_t{35});
  EXPECT_EQ(ctrnn(35, 8, 5).outputCount(), std::size_t{5});

  NeuralController controller(feedForward({35, 8, 5}));
  EXPECT_EQ(controller.parameterCount(), std::size_t{333});
  EXPECT_EQ(controller.parameters().size(), std::size_t{333});
  for (const real value : controller.parameters()) EXPECT_EQ(value, 0);
}

TEST(NetworkSpecTest, RefusesBadShapes) {
  expectInvalid([] { (void)feedForward({5}).parameterCount(); }, "NetworkSpec.layers");
  expectInvalid([] { (void)feedForward({}).parameterCount(); }, "NetworkSpec.layers");
  expectInvalid([] { (void)feedForward({3, 0, 2}).parameterCount(); }, "NetworkSpec.layers");
  expectInvalid(
      [] {
        (void)feedForward({3, NetworkSpec::maxLayerSize + 1}).parameterCount();
      },
      "NetworkSpec.layers");
  expectInvalid(
      [] {
        (void)feedForward(std::vector<std::size_t>(NetworkSpec::maxLayers + 1, 2)).parameterCount();
      },
      "NetworkSpec.layers");
  expectInvalid(
      [] {
        NetworkSpec spec{NetworkKind::Ctrnn, {3, 4, 2, 1}, Activation::Tanh};
        (void)spec.parameterCount();
      },
      "NetworkSpec.layers");
  expectInvalid(
      [] {
        NetworkSpec spec = feedForward({2, 2});
        spec.activation = static_cast<Activation>(7);
        spec.validate();
      },
      "NetworkSpec.activation");
  expectInvalid(
      [] {
        NetworkSpec spec = feedForward({2, 2});
        spec.kind = static_cast<NetworkKind>(7);
        spec.validate();
      },
      "NetworkSpec.kind");
  expectInvalid([] { NeuralController controller(feedForward({2})); }, "NetworkSpec.layers");
  expectInvalid([] { NeuralController controller(ctrnn(1, 1, 1), 0); },
                "NeuralController.timestep");
  expectInvalid([] { NeuralController controller(ctrnn(1, 1, 1), real(-0.01)); },
                "NeuralController.timestep");
  expectInvalid(
      [] { NeuralController controller(ctrnn(1, 1, 1), std::numeric_limits<real>::infinity()); },
      "NeuralController.timestep");
}

TEST(NeuralControllerTest, FeedForwardTanhByHand) {
  // 2 inputs, 2 hidden tanh units, 1 output. Order: hidden biases, then the weights source by
  // source (x0 -> h0, x0 -> h1, x1 -> h0, x1 -> h1), then the output bias and weights.
  NeuralController controller(feedForward({2, 2, 1}, Activation::Tanh));
  const std::vector<real> parameters = {real(0.1), real(-0.2), real(1.0), real(-1.0), real(2.0),
                                        real(0.5), real(0.3),  real(0.7), real(-1.2)};
  controller.setParameters(parameters);
  const std::vector<real> sensors = {real(0.5), real(0.25)};
  std::vector<real> effectors(1);
  controller.control(sensors, effectors);

  const double h0 = std::tanh(0.1 + 0.5 * 1.0 + 0.25 * 2.0);
  const double h1 = std::tanh(-0.2 + 0.5 * -1.0 + 0.25 * 0.5);
  const double out = 0.5 * (1 + std::tanh(0.3 + 0.7 * h0 - 1.2 * h1));
  EXPECT_NEAR(effectors[0], out, test::tight);
  // A feed-forward network has no state: the same sensors give the same output.
  std::vector<real> again(1);
  controller.control(sensors, again);
  EXPECT_EQ(again[0], effectors[0]);
  EXPECT_TRUE(controller.state().empty());
}

TEST(NeuralControllerTest, FeedForwardLogisticByHand) {
  // 3 inputs straight to 2 logistic outputs, then one more layer of 2: two layers of weights.
  NeuralController controller(feedForward({3, 2, 2}, Activation::Logistic));
  std::vector<real> p = {real(0.5), real(-0.5),  // hidden biases
                         real(1),   real(2),     real(-3),  real(1),
                         real(0.5), real(-0.25),  // x0->h0,h1; x1->..; x2->..
                         real(-1),  real(1),      // output biases
                         real(2),   real(-2),    real(0.5), real(1.5)};  // h0->o0,o1; h1->o0,o1
  controller.setParameters(p);
  const std::vector<real> x = {real(0.2), real(0.4), real(0.8)};
  std::vector<real> y(2);
  controller.control(x, y);
  const double h0 = 1 / (1 + std::exp(-(0.5 + 0.2 * 1 + 0.4 * -3 + 0.8 * 0.5)));
  const double h1 = 1 / (1 + std::exp(-(-0.5 + 0.2 * 2 + 0.4 * 1 + 0.8 * -0.25)));
  EXPECT_NEAR(y[0], 1 / (1 + std::exp(-(-1 + 2 * h0 + 0.5 * h1))), test::tight);
  EXPECT_NEAR(y[1], 1 / (1 + std::exp(-(1 - 2 * h0 + 1.5 * h1))), test::tight);
}

TEST(NeuralControllerTest, OutputsStayInUnitIntervalAndFinite) {
  for (const Activation activation : {Activation::Tanh, Activation::Logistic}) {
    for (const NetworkSpec& spec :
         {feedForward({35, 8, 5}, activation), ctrnn(35, 8, 5, activation)}) {
      NeuralController controller(spec);
      MTRandom random(3);
      std::vector<real> p(controller.parameterCount());
      for (real& value : p) value = static_cast<real>(random.uniform(-1e6, 1e6));
      controller.setParameters(p);
      std::vector<real> sensors(35);
      std::vector<real> effectors(5);
      for (int step = 0; step < 50; ++step) {
        for (real& s : sensors) s = static_cast<real>(random.uniform());
        controller.control(sensors, effectors);
        for (const real e : effectors) {
          ASSERT_GE(e, 0);
          ASSERT_LE(e, 1);
        }
        for (const real y : controller.state()) ASSERT_TRUE(std::isfinite(y));
      }
    }
  }
}

// One neuron fed by one constant input with gain g: tau dy/dt = -y + g s, y(0) = 0, so
// y(t) = g s (1 - exp(-t / tau)); forward Euler gives y_n = g s (1 - (1 - dt / tau)^n).
TEST(NeuralControllerTest, CtrnnNeuronStepResponseAndDecay) {
  const real dt = real(0.01);
  const double tauParameter = std::log(0.5);  // tau = dt + exp(p) = 0.51 s
  const double tau = 0.01 + 0.5;
  const double gain = 2;
  const double sensor = 0.75;
  const double theta = 0.3;
  NeuralController controller(ctrnn(1, 1, 1, Activation::Logistic), dt);
  // Order: tau parameter, bias, input gain, recurrent weight, output bias, output weight.
  controller.setParameters(std::vector<real>{static_cast<real>(tauParameter), real(theta),
                                             real(gain), 0, real(-0.4), real(1.5)});
  const std::vector<real> sensors = {real(sensor)};
  std::vector<real> effectors(1);
  const double target = gain * sensor;
  const double factor = 1 - 0.01 / tau;
  const int steps = 200;
  // Rounding over hundreds of steps (float keeps about 7 digits).
  const double euler = test::isFloat ? 1e-4 : 1e-12;
  for (int n = 1; n <= steps; ++n) {
    controller.control(sensors, effectors);
    const double y = controller.state()[0];
    ASSERT_NEAR(y, target * (1 - std::pow(factor, n)), euler) << "step " << n;
    // Euler's own error on this decay is below (dt / tau) / 2 of the jump.
    ASSERT_NEAR(y, target * (1 - std::exp(-n * 0.01 / tau)), target * 0.01 / tau / 2)
        << "step " << n;
    // The output reads the neuron's firing rate after the step.
    const double firing = 1 / (1 + std::exp(-(y + theta)));
    ASSERT_NEAR(effectors[0], 1 / (1 + std::exp(-(-0.4 + 1.5 * firing))), euler);
  }
  // Then the input stops: y decays from y_200 as exp(-t / tau).
  const double start = controller.state()[0];
  const std::vector<real> silent = {0};
  for (int m = 1; m <= steps; ++m) {
    controller.control(silent, effectors);
    const double y = controller.state()[0];
    ASSERT_NEAR(y, start * std::pow(factor, m), euler) << "step " << m;
    ASSERT_NEAR(y, start * std::exp(-m * 0.01 / tau), start * 0.01 / tau / 2) << "step " << m;
  }
  // reset() starts the neuron from 0 again.
  controller.reset();
  EXPECT_EQ(controller.state()[0], 0);
  controller.control(sensors, effectors);
  EXPECT_NEAR(controller.state()[0], target * (1 - factor), test::tight);
}

TEST(NeuralControllerTest, CtrnnTwoNeuronsByHand) {
  // 2 inputs, 2 tanh neurons, 1 output, two Euler steps written out.
  const double dt = 0.1;
  NeuralController controller(ctrnn(2, 2, 1, Activation::Tanh), real(dt));
  const double p0 = 0, p1 = std::log(0.2);  // tau0 = 1.1, tau1 = 0.3
  const double th0 = 0.2, th1 = -0.1;
  // gains source by source: s0->y0, s0->y1, s1->y0, s1->y1
  const double g00 = 1, g01 = -0.5, g10 = 0.25, g11 = 2;
  // weights source by source: y0->y0, y0->y1, y1->y0, y1->y1
  const double w00 = 0.5, w01 = -1, w10 = 1.5, w11 = 0.2;
  const double c = 0.1, v0 = 1, v1 = -2;
  controller.setParameters(std::vector<real>{real(p0), real(p1), real(th0), real(th1), real(g00),
                                             real(g01), real(g10), real(g11), real(w00), real(w01),
                                             real(w10), real(w11), real(c), real(v0), real(v1)});
  const double tau0 = dt + 1, tau1 = dt + 0.2;
  const double s0 = 0.6, s1 = 0.9;
  const std::vector<real> sensors = {real(s0), real(s1)};
  std::vector<real> effectors(1);

  double y0 = 0, y1 = 0;
  for (int step = 0; step < 2; ++step) {
    const double f0 = std::tanh(y0 + th0), f1 = std::tanh(y1 + th1);
    const double net0 = g00 * s0 + g10 * s1 + w00 * f0 + w10 * f1;
    const double net1 = g01 * s0 + g11 * s1 + w01 * f0 + w11 * f1;
    y0 += dt / tau0 * (net0 - y0);
    y1 += dt / tau1 * (net1 - y1);
    controller.control(sensors, effectors);
    EXPECT_NEAR(controller.state()[0], y0, test::tight) << "step " << step;
    EXPECT_NEAR(controller.state()[1], y1, test::tight) << "step " << step;
    const double out =
        0.5 * (1 + std::tanh(c + v0 * std::tanh(y0 + th0) + v1 * std::tanh(y1 + th1)));
    EXPECT_NEAR(effectors[0], out, test::tight) << "step " << step;
  }
}

TEST(NeuralControllerTest, CtrnnFastNeuronStaysStable) {
  // A very negative tau parameter makes tau barely above dt: the Euler step lands on the input
  // instead of overshooting it, and nothing grows.
  NeuralController controller(ctrnn(1, 1, 1), real(0.01));
  controller.setParameters(std::vector<real>{-80, 0, 3, 0, 0, 1});
  const std::vector<real> sensors = {1};
  std::vector<real> effectors(1);
  for (int step = 0; step < 100; ++step) {
    controller.control(sensors, effectors);
    ASSERT_NEAR(controller.state()[0], 3, test::loose);
  }
}

TEST(NeuralControllerTest, SetParametersRefusesBadInputAndKeepsTheOld) {
  NeuralController controller(feedForward({2, 2, 1}));
  std::vector<real> good(controller.parameterCount(), real(0.5));
  controller.setParameters(good);
  expectInvalid([&] { controller.setParameters(std::vector<real>(8, 0)); },
                "NeuralController.parameters");
  expectInvalid([&] { controller.setParameters(std::vector<real>(10, 0)); },
                "NeuralController.parameters");
  std::vector<real> bad = good;
  bad[4] = std::numeric_limits<real>::quiet_NaN();
  expectInvalid([&] { controller.setParameters(bad); }, "NeuralController.parameters");
  bad[4] = -std::numeric_limits<real>::infinity();
  expectInvalid([&] { controller.setParameters(bad); }, "NeuralController.parameters");
  EXPECT_EQ(std::vector<real>(controller.parameters().begin(), controller.parameters().end()),
            good);
  // Its own parameters passed back are accepted.
  controller.setParameters(controller.parameters());
  EXPECT_EQ(controller.parameters()[0], real(0.5));
}

TEST(NeuralControllerTest, ControlRefusesWrongCounts) {
  NeuralController controller(feedForward({3, 2}));
  std::vector<real> sensors(3);
  std::vector<real> effectors(2);
  std::vector<real> fewSensors(2);
  std::vector<real> manyEffectors(3);
  expectInvalid([&] { controller.control(fewSensors, effectors); }, "NeuralController.sensors");
  expectInvalid([&] { controller.control(sensors, manyEffectors); }, "NeuralController.effectors");
}

TEST(NeuralControllerTest, StepsAllocateNothing) {
  for (const NetworkSpec& spec : {feedForward({35, 8, 8, 5}), ctrnn(35, 8, 5)}) {
    NeuralController controller(spec);
    controller.setParameters(std::vector<real>(controller.parameterCount(), real(0.1)));
    std::vector<real> sensors(35, real(0.5));
    std::vector<real> effectors(5);
    const long before = test::allocationCount();
    for (int step = 0; step < 100; ++step) controller.control(sensors, effectors);
    controller.reset();
    EXPECT_EQ(test::allocationCount(), before);
  }
}

}  // namespace
}  // namespace thyrix
