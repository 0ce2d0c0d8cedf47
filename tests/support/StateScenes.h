#pragma once
// The worlds the state tests run (WorldStateTest, ReferenceModeTest): the repository's agents'
// simulators and scenes, a pile, a mixed pile and an articulated chain, each built afresh.

#include <Agents/IunctusGrasper.h>
#include <Agents/IunctusSimulator.h>
#include <Agents/PacEatingSimulator.h>
#include <Agents/PacSimulator.h>
#include <Agents/SpherusSimulator.h>
#include <Controller/NeuralController.h>
#include <Controller/RandomController.h>
#include <Scenes.h>
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixPro/ArticulatedAgentQuasistatic.h>
#include <Tools/MTRandom.h>

#include <functional>
#include <memory>
#include <vector>

namespace thyrix::state_scenes {

/// A world to test, built afresh by each call.
using Factory = std::function<std::unique_ptr<Simulator>()>;

/// A pile of 60 circles falling into an open box (more boxes than the broad phase tests all
/// pairs of), one of them dragged by the mouse.
inline std::unique_ptr<Simulator> pile() {
  auto simulator = std::make_unique<Simulator>();
  simulator->setGravity({0, real(-2)});
  const auto bodies = scenes::addPile(*simulator, 60, 3);
  simulator->startDrag(*bodies[7], bodies[7]->r + Vector2{real(0.2), 0});
  simulator->dragTo({real(1), real(9)});
  return simulator;
}

/// Circles and capsules jammed into a corner, pushing each other apart.
inline std::unique_ptr<Simulator> mixedPile() {
  auto simulator = std::make_unique<Simulator>();
  scenes::addMixedPile(*simulator, 30, 4);
  return simulator;
}

/// An articulated chain of 5 links over a floor, curled by its joint torques until its links
/// meet, its base falling.
inline std::unique_ptr<Simulator> chain() {
  auto simulator = std::make_unique<Simulator>();
  simulator->setGravity({0, real(-1)});
  simulator->registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& agent = simulator->registerObject(std::make_unique<ArticulatedAgentQuasistatic>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, 5, real(0.8), real(0.15), real(0.5))}));
  agent.setPose({0, real(1.5)}, 0);
  for (int i = 1; i < 5; ++i) agent.setJointTorque(i, real(0.3));
  agent.setServoTarget(0, real(0.4), 5);
  return simulator;
}

inline std::unique_ptr<Simulator> spherus() {
  SpherusSimulator::Options options;
  return std::make_unique<SpherusSimulator>(options, std::make_unique<RandomController>(7, 5, 30));
}

inline std::unique_ptr<Simulator> spherusNeural() {
  // A recurrent network carries its neurons' states from step to step.
  NetworkSpec spec;
  spec.kind = NetworkKind::Ctrnn;
  spec.layers = {Spherus::sensorCount, 6, Spherus::effectorCount};
  auto controller = std::make_unique<NeuralController>(spec, real(0.01));
  std::vector<real> parameters(controller->parameterCount());
  MTRandom random(11);
  for (real& value : parameters) value = static_cast<real>(random.uniform(-1, 1));
  // (Slow neurons: their states carry over many steps.)
  for (std::size_t i = 0; i < 6; ++i) parameters[i] = real(-1);
  controller->setParameters(parameters);
  SpherusSimulator::Options options;
  return std::make_unique<SpherusSimulator>(options, std::move(controller));
}

inline std::unique_ptr<Simulator> pac() {
  PacSimulator::Options options;
  return std::make_unique<PacSimulator>(options, std::make_unique<RandomController>(3, 5, 40),
                                        std::make_unique<RandomController>(4, 5, 40));
}

inline std::unique_ptr<Simulator> pacEating() {
  PacSimulator::Options options;
  return std::make_unique<PacEatingSimulator>(options,
                                              std::make_unique<RandomController>(5, 5, 40));
}

inline std::unique_ptr<Simulator> iunctus() {
  IunctusSimulator::Options options;
  options.objects = 3;
  return std::make_unique<IunctusSimulator>(options, std::make_unique<RandomController>(9, 5, 40));
}

inline std::unique_ptr<Simulator> iunctusGrasping() {
  IunctusSimulator::Options options;
  auto simulator = std::make_unique<IunctusSimulator>(options, nullptr);
  simulator->useGrasper();
  return simulator;
}

/// An articulated chain of 60 capsule links curling over a floor (more boxes than the broad
/// phase tests all pairs of, and runs of links placed together).
inline std::unique_ptr<Simulator> longChain() {
  auto simulator = std::make_unique<Simulator>();
  simulator->setGravity({0, real(-1)});
  simulator->registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& agent = simulator->registerObject(std::make_unique<ArticulatedAgentQuasistatic>(
      std::vector<ArticulatedBasePart>{ArticulatedBasePart::circle(real(0.5), 2)},
      std::vector<ArticulatedLimb>{
          ArticulatedLimb::chain({real(0.5), 0}, 60, real(0.4), real(0.1), real(0.5))}));
  agent.setPose({0, real(3)}, 0);
  for (int i = 1; i < 60; i += 3) agent.setJointTorque(i, real(0.05));
  return simulator;
}

/// 150 circles and capsules in a walled arena, pushed at random before each step (the broad
/// phase's grid and its memory of the last call, bodies that move and bodies at rest side by
/// side).
inline std::unique_ptr<Simulator> crowd() {
  auto simulator = std::make_unique<Simulator>();
  scenes::addWalls(*simulator, 30, 30);
  scenes::addRandomCircles(*simulator, 120, real(0.6), 30, 5);
  MTRandom random(6);
  for (int i = 0; i < 30; ++i) {
    auto& capsule =
        simulator->registerObject(std::make_unique<CappedRectangle>(real(0.6), real(0.2), real(1)));
    capsule.r = {static_cast<real>(random.uniform(1, 29)),
                 static_cast<real>(random.uniform(1, 29))};
    capsule.alpha = static_cast<real>(random.uniform(0, 3));
  }
  return simulator;
}

struct Scene {
  const char* name;
  Factory make;
};

inline const Scene scenesToTest[] = {
    {"Pile", pile},
    {"MixedPile", mixedPile},
    {"Chain", chain},
    {"LongChain", longChain},
    {"Crowd", crowd},
    {"Spherus", spherus},
    {"SpherusNeural", spherusNeural},
    {"Pac", pac},
    {"PacEating", pacEating},
    {"Iunctus", iunctus},
    {"IunctusGrasping", iunctusGrasping},
};

}  // namespace thyrix::state_scenes
