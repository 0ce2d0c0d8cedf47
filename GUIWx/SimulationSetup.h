#pragma once
/// @file SimulationSetup.h
/// @brief What an application hands the GUI: how to build its world, what its agent senses and
/// does, and how the run starts.

#include <ThyrixLite/ContactSolver.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/World.h>
#include <ThyrixLite/WorldDrawing.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace thyrix {

/// The agent's activity shown as live bars: views of its sensor and effector values (each in
/// [0, 1]). They are read on the simulation thread right after a step and copied into the
/// snapshot, so they may point into the simulator.
struct AgentSignals {
  std::span<const real> sensors;    ///< sensor activations
  std::span<const real> effectors;  ///< effector activations
};

/// Everything a SimulationRunner and a SimulationFrame need from the application.
struct SimulationSetup {
  /// The window title.
  std::string title = "Thyrix";
  /// Builds a fresh world: called on the simulation thread at start and at each reset, so
  /// the world is created, stepped and destroyed by that thread alone. Must return a world:
  /// any World, stepped by its advanceTime() and drawn by its draw(); a Simulator's objects
  /// can also be dragged with the mouse, and its contacts drawn.
  std::function<std::unique_ptr<World>()> makeWorld;
  /// Optional: the agent's sensors and effectors, for the side panel (none if empty). Called
  /// on the simulation thread with the current world.
  std::function<AgentSignals(const World&)> agentSignals;
  /// Contact solver of every Simulator built (the GUI can change it while running).
  ContactSolverKind solver = ContactSolverKind::Baraff;
  /// Steps per second to aim at; 0 runs as fast as possible.
  double stepsPerSecond = 100;
  /// Start stepping at once (true) or wait for Run (false).
  bool startRunning = true;
  /// Pause when the step count reaches this (0: never), e.g. to stop after N steps.
  std::uint64_t pauseAtStep = 0;
  /// Overlays drawn over the objects at start (contacts, forces, sensors).
  DrawOptions drawOptions;
};

/// Adapts a function of the application's own world type to SimulationSetup::agentSignals,
/// e.g. `agentSignalsOf<SpherusSimulator>([](const SpherusSimulator& s) { ... })`. The world
/// passed in is the one built by SimulationSetup::makeWorld, so it must be of type @p Derived.
template <class Derived, class Function>
std::function<AgentSignals(const World&)> agentSignalsOf(Function function) {
  return [function](const World& world) { return function(static_cast<const Derived&>(world)); };
}

}  // namespace thyrix
