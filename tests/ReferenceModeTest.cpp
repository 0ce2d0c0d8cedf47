// The reference mode (Simulator::referenceMode) turns every cache and shortcut off and runs the
// plain algorithm: a world in it must go through the same states, bit for bit and step by
// step, as the same world with every cache on. The reference is that plain run, not a number:
// a shortcut that changes any bit of any step (a pose, a velocity, a contact's place or force,
// the order of the contacts) fails here at the first step it does.

#include <Scenes.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/WorldState.h>
#include <Tools/MTRandom.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <tuple>

#include "support/StateScenes.h"

namespace thyrix {
namespace {

using namespace state_scenes;

/// Spherus and its circles in a small arena, so that they meet the walls and each other.
std::unique_ptr<Simulator> spherusCrowded() {
  SpherusSimulator::Options options;
  options.objects = 30;
  options.size = 5;
  return std::make_unique<SpherusSimulator>(options, std::make_unique<RandomController>(7, 5, 30));
}

struct ReferenceScene {
  const char* name;
  Factory make;
  /// Bodies pushed at random before each step (none for the agents, which move themselves).
  bool pushed;
  /// Steps compared: the agents' scenes run until their agents have met walls and objects.
  int steps;
};

const ReferenceScene referenceScenes[] = {
    {"Pile", pile, false, 400},
    {"MixedPile", mixedPile, false, 400},
    {"Chain", chain, false, 400},
    {"LongChain", longChain, false, 300},
    {"Crowd", crowd, true, 400},
    {"Spherus", spherusCrowded, false, 1000},
    {"PacEating", pacEating, false, 1000},
    {"Iunctus", iunctus, false, 1000},
    {"IunctusGrasping", iunctusGrasping, false, 1000},
};

/// Pushes a few of @p simulator's movable objects, chosen by @p random, before a step.
void pushSome(Simulator& simulator, MTRandom& random) {
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(random.uniform(0, 1) *
                                            static_cast<double>(simulator.objects.size()));
    PhysicalObject& object = simulator.objects[std::min(i, simulator.objects.size() - 1)];
    if (object.fixed) continue;
    object.externalForce +=
        {static_cast<real>(random.uniform(-3, 3)), static_cast<real>(random.uniform(-3, 3))};
  }
}

using Parameters = std::tuple<int, ContactSolverKind>;  // scene, solver

class ReferenceModeTest : public ::testing::TestWithParam<Parameters> {
 protected:
  [[nodiscard]] const ReferenceScene& scene() const {
    return referenceScenes[std::get<0>(GetParam())];
  }
  [[nodiscard]] std::unique_ptr<Simulator> make(bool reference) const {
    auto simulator = scene().make();
    simulator->setContactSolver(std::get<1>(GetParam()));
    simulator->referenceMode = reference;
    return simulator;
  }
};

TEST_P(ReferenceModeTest, EveryStepIsBitIdenticalToTheDefaultMode) {
  auto fast = make(false);
  auto plain = make(true);
  MTRandom pushFast(17);
  MTRandom pushPlain(17);
  ASSERT_EQ(fast->saveState(), plain->saveState());
  std::size_t contacts = 0;
  for (int step = 0; step < scene().steps; ++step) {
    if (scene().pushed) {
      pushSome(*fast, pushFast);
      pushSome(*plain, pushPlain);
    }
    fast->advanceTime();
    plain->advanceTime();
    ASSERT_EQ(scenes::stateHash(*fast), scenes::stateHash(*plain)) << "step " << step;
    // (The whole state: the contacts too, in their order, with their forces.)
    ASSERT_EQ(fast->saveState(), plain->saveState()) << "step " << step;
    ASSERT_EQ(fast->statistics().contacts, plain->statistics().contacts) << "step " << step;
    contacts += fast->contacts.size();
  }
  EXPECT_GT(contacts, 0u) << "the scene should have contacts to compare";
}

TEST_P(ReferenceModeTest, SwitchingModesBetweenStepsChangesNothing) {
  // The caches are rebuilt after steps in reference mode: a world switched back and forth
  // goes on as one that never switched.
  auto fast = make(false);
  auto mixed = make(false);
  MTRandom pushFast(23);
  MTRandom pushMixed(23);
  for (int step = 0; step < scene().steps; ++step) {
    mixed->referenceMode = step % 10 >= 7;
    if (scene().pushed) {
      pushSome(*fast, pushFast);
      pushSome(*mixed, pushMixed);
    }
    fast->advanceTime();
    mixed->advanceTime();
    ASSERT_EQ(fast->saveState(), mixed->saveState()) << "step " << step;
  }
}

std::string parameterName(const ::testing::TestParamInfo<Parameters>& info) {
  return std::string(referenceScenes[std::get<0>(info.param)].name) +
         (std::get<1>(info.param) == ContactSolverKind::Baraff ? "Baraff" : "GaussSeidel");
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ReferenceModeTest,
    ::testing::Combine(::testing::Range(0, static_cast<int>(std::size(referenceScenes))),
                       ::testing::Values(ContactSolverKind::Baraff,
                                         ContactSolverKind::GaussSeidel)),
    parameterName);

TEST(ReferenceMode, RestingPileWithFewPushesIsBitIdentical) {
  // A settled pile of 200 circles, a few bodies pushed now and then: rest skipping reuses most
  // contacts, and the broad phase (above its all-pairs limit) keeps most pairs of its last call.
  for (const ContactSolverKind solver :
       {ContactSolverKind::Baraff, ContactSolverKind::GaussSeidel}) {
    const auto make = [solver](bool reference) {
      auto simulator = std::make_unique<Simulator>();
      simulator->setContactSolver(solver);
      simulator->setGravity({0, real(-2)});
      scenes::addPile(*simulator, 200, 5);
      simulator->referenceMode = reference;
      return simulator;
    };
    auto fast = make(false);
    auto plain = make(true);
    for (int step = 0; step < 800; ++step) {
      if (step >= 400 && step % 20 == 0) {
        const std::size_t body = 3 + static_cast<std::size_t>(step / 20) % 200;
        fast->objects[body].externalForce = {real(0.5), 0};
        plain->objects[body].externalForce = {real(0.5), 0};
      }
      fast->advanceTime();
      plain->advanceTime();
      ASSERT_EQ(fast->saveState(), plain->saveState())
          << (solver == ContactSolverKind::Baraff ? "Baraff" : "Gauss-Seidel") << ", step " << step;
    }
  }
}

}  // namespace
}  // namespace thyrix
