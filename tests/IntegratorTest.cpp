// The simulator's integrator is a strategy it calls in phase 8 of every step: a replacement is
// called for every object (under either solver), a higher-order one changes the motion as its
// order says, and the default stays explicit Euler.

#include "TestTolerances.h"
#include "support/SolverCases.h"

#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Integrator.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

using test::bitsOf;
using test::solverName;

/// Explicit Euler that notes each object it moves, and the step it was given.
class RecordingIntegrator : public Integrator {
 public:
  struct Call {
    const PhysicalObject* object;
    real dt;
  };
  std::vector<Call> calls;

  void integrateObject(PhysicalObject& object, real dt) override {
    calls.push_back({&object, dt});
    Integrator::integrateObject(object, dt);
  }
};

/// The explicit midpoint method: the velocities are evaluated again half a step ahead (with
/// the simulator's own phases, contacts and solver included), and the step is taken from the
/// start with them. Second order: exact while the velocity is linear in time.
class MidpointIntegrator : public Integrator {
 public:
  void integrate(Simulator& simulator, real dt) override {
    start_.clear();
    for (PhysicalObject& object : simulator.objects) {
      start_.push_back({object.r, object.alpha});
      object.integrate(dt / 2);
    }
    simulator.eraseContacts();
    simulator.detectContacts();
    simulator.indexContacts();
    simulator.computeDerivativesWithoutContacts();
    simulator.solveContacts();
    std::size_t i = 0;
    for (PhysicalObject& object : simulator.objects) {
      object.r = start_[i].r;
      object.alpha = start_[i].alpha;
      ++i;
      object.integrate(dt);
    }
  }

 private:
  struct Pose {
    Vector2 r;
    real alpha;
  };
  std::vector<Pose> start_;
};

/// A circle that spins at the constant rate `spin` (rad/s) and is driven along x at `k * alpha`
/// (m/s), its velocity depending on its pose, while pressed at `press` (m/s) onto the floor.
/// Along x: alpha = spin t, so x = x0 + k spin t^2 / 2.
class SpinDrivenCircle : public Circle {
 public:
  static constexpr real k = 1;
  static constexpr real spin = 2;
  static constexpr real press = 1;
  SpinDrivenCircle() : Circle(real(0.5), 1) {}
  void computeDerivativesWithoutContacts() override {
    externalForce += Vector2{k * alpha, -press} * m;
    externalTorque += spin * I;
    Circle::computeDerivativesWithoutContacts();
  }
};

class IntegratorTest : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(IntegratorTest, ReplacementIsCalledForEveryObjectOnceAStep) {
  // A pile pushed into walls (contacts that need forces) and a custom object: the replaced
  // integrator moves each of them once per step, in registration order, by the time step.
  Simulator simulator(real(0.02));
  Simulator reference(real(0.02));
  for (Simulator* s : {&simulator, &reference}) {
    s->setContactSolver(GetParam());
    scenes::addMixedPile(*s, 30, 5);
    s->registerObject(std::make_unique<SpinDrivenCircle>()).r = {3, 3};
  }
  auto recorder = std::make_unique<RecordingIntegrator>();
  RecordingIntegrator& recorded = *recorder;
  simulator.setIntegrator(std::move(recorder));
  EXPECT_EQ(&simulator.integrator(), &recorded);

  const std::size_t count = simulator.objects.size();
  for (int step = 0; step < 50; ++step) {
    for (Simulator* s : {&simulator, &reference})
      for (PhysicalObject& object : s->objects)
        if (!object.fixed) object.externalForce = {-2, -1};
    recorded.calls.clear();
    simulator.advanceTime();
    reference.advanceTime();
    ASSERT_EQ(recorded.calls.size(), count) << "step " << step;
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_EQ(recorded.calls[i].object, &simulator.objects[i]) << "step " << step;
      EXPECT_EQ(recorded.calls[i].dt, simulator.timestep());
    }
  }
  EXPECT_GT(simulator.statistics().solvedIslands, 0u);
  // It delegates to Euler: the same motion, bit for bit, as the default's own loop.
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_EQ(bitsOf(simulator.objects[i].r.x), bitsOf(reference.objects[i].r.x)) << i;
    EXPECT_EQ(bitsOf(simulator.objects[i].r.y), bitsOf(reference.objects[i].r.y)) << i;
    EXPECT_EQ(bitsOf(simulator.objects[i].alpha), bitsOf(reference.objects[i].alpha)) << i;
  }
}

TEST_P(IntegratorTest, MidpointFollowsAPoseDependentVelocityExactly) {
  // A circle on the floor y = 0, spinning at a constant rate and driven along x in proportion
  // to its angle: x(T) = k spin T^2 / 2. The midpoint method is exact for it; Euler lags by
  // k spin T dt / 2, its sum k spin dt^2 N (N - 1) / 2 over the N steps.
  const real dt = real(0.01);
  const int steps = 100;
  const real T = dt * steps;
  const real k = SpinDrivenCircle::k;
  const real spin = SpinDrivenCircle::spin;
  real x[2];
  for (const bool midpoint : {true, false}) {
    Simulator simulator(dt);
    simulator.setContactSolver(GetParam());
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    auto& circle = simulator.registerObject(std::make_unique<SpinDrivenCircle>());
    circle.r = {0, circle.radius()};
    if (midpoint) simulator.setIntegrator(std::make_unique<MidpointIntegrator>());
    for (int step = 0; step < steps; ++step) simulator.advanceTime();
    // The floor held it up, the contact solved in every step.
    EXPECT_EQ(simulator.contacts.size(), 1u);
    EXPECT_NEAR(circle.r.y, circle.radius(), test::loose);
    EXPECT_NEAR(circle.alpha, spin * T, test::loose);
    x[midpoint ? 0 : 1] = circle.r.x;
  }
  EXPECT_NEAR(x[0], k * spin * T * T / 2, test::loose);
  const auto n = static_cast<real>(steps);
  EXPECT_NEAR(x[1], k * spin * dt * dt * n * (n - 1) / 2, test::loose);
  EXPECT_GT(std::abs(x[0] - x[1]), real(0.005));
}

INSTANTIATE_TEST_SUITE_P(Solvers, IntegratorTest,
                         ::testing::Values(ContactSolverKind::Baraff,
                                           ContactSolverKind::GaussSeidel),
                         solverName);

TEST(IntegratorSetting, NullIsRefusedAndTheIntegratorKept) {
  Simulator simulator;
  Integrator& before = simulator.integrator();
  try {
    simulator.setIntegrator(nullptr);
    FAIL() << "no exception";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "Simulator.setIntegrator.integrator");
  }
  EXPECT_EQ(&simulator.integrator(), &before);
}

TEST(IntegratorSetting, DefaultIsEulerThroughEitherPath) {
  // The default's fast loop and its virtual integrate() move objects alike: one Euler step.
  Simulator simulator(real(0.5));
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), 2));
  circle.externalForce = {2, -4};
  circle.externalTorque = 1;
  simulator.advanceTime();
  EXPECT_NEAR(circle.r.x, real(0.5) * 2 / 2, test::tight);
  EXPECT_NEAR(circle.r.y, real(0.5) * -4 / 2, test::tight);
  EXPECT_NEAR(circle.alpha, real(0.5) / circle.I, test::tight);
  simulator.integrator().integrate(simulator, real(0.5));
  EXPECT_NEAR(circle.r.x, 2 * real(0.5), test::tight);
  EXPECT_NEAR(circle.alpha, 2 * real(0.5) / circle.I, test::tight);
}

}  // namespace
}  // namespace thyrix
