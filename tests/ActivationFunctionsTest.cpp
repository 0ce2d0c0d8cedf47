// Tests of the portable squashing functions (Controller/ActivationFunctions.h) against the C
// library's exp and tanh, and of the layer functions against the scalar ones.

#include <Controller/ActivationFunctions.h>
#include <Tools/MTRandom.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace thyrix {
namespace {

TEST(ActivationFunctionsTest, BoundedExpIsWithinThreeUnitsInTheLastPlace) {
  EXPECT_EQ(boundedExp(0), 1);
  const int count = 200000;
  double worst = 0;
  for (int i = 0; i <= count; ++i) {
    const double a = -64 + 128.0 * i / count;
    const double expected = std::exp(a);
    worst = std::max(worst, std::abs(boundedExp(a) - expected) / expected);
  }
  EXPECT_LT(worst, 3 * 0x1p-52) << "relative error";
}

TEST(ActivationFunctionsTest, TanhAndLogisticMatchTheCLibrary) {
  const int count = 200000;
  double worstTanh = 0;
  double worstLogistic = 0;
  for (int i = 0; i <= count; ++i) {
    const double x = -60 + 120.0 * i / count;
    worstTanh = std::max(worstTanh, std::abs(portableTanh(x) - std::tanh(x)));
    worstLogistic = std::max(worstLogistic, std::abs(portableLogistic(x) - 1 / (1 + std::exp(-x))));
  }
  EXPECT_LT(worstTanh, 4e-16);
  EXPECT_LT(worstLogistic, 3e-16);
  EXPECT_EQ(portableTanh(0), 0);
  EXPECT_EQ(portableLogistic(0), 0.5);
  // Saturated: exactly the limits, however large the argument.
  EXPECT_EQ(portableTanh(25), 1);
  EXPECT_EQ(portableTanh(-1e300), -1);
  EXPECT_EQ(portableLogistic(1e300), 1);
  EXPECT_LT(portableLogistic(-1e300), 5e-18);
  EXPECT_GE(portableLogistic(-1e300), 0);
}

TEST(ActivationFunctionsTest, LayersApplyTheScalarFunctions) {
  MTRandom random(8);
  std::vector<real> values(37);
  for (real& value : values) value = static_cast<real>(random.normal(0, 30));
  for (const Activation activation : {Activation::Tanh, Activation::Logistic}) {
    std::vector<real> layer = values;
    activateLayer(activation, layer);
    std::vector<real> outputs = values;
    activateOutputs(activation, outputs);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double x = values[i];
      const bool tanh = activation == Activation::Tanh;
      EXPECT_EQ(layer[i], static_cast<real>(tanh ? portableTanh(x) : portableLogistic(x)));
      // An output in [0, 1]: the logistic, or (1 + tanh(x)) / 2, which is the logistic of 2x.
      EXPECT_EQ(outputs[i], static_cast<real>(portableLogistic(tanh ? 2 * x : x)));
      if (tanh) {
        EXPECT_NEAR(outputs[i], 0.5 * (1 + std::tanh(x)), 1e-6);
      }
    }
  }
}

}  // namespace
}  // namespace thyrix
