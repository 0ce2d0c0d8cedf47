#pragma once
/// @file SimulationRunner.h
/// @brief Runs a World (a Simulator or any other) in a thread of its own, at a chosen speed or
/// as fast as possible, and publishes snapshots of it for the window.

#include <GUIWx/SimulationSetup.h>
#include <GUIWx/WorldSnapshot.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace thyrix {

/// What happened to a dragged object, reported on the simulation thread.
struct DragEvent {
  /// The kind of event.
  enum class Kind : std::uint8_t {
    Start,    ///< an object was grabbed
    Move,     ///< the mouse target moved
    End,      ///< the object was released
    Settled,  ///< `stepsSinceRelease` steps after the release (reported at 10 and 50)
  };
  Kind kind = Kind::Start;              ///< the kind of event
  std::uint32_t object = 0;             ///< index of the grabbed object in Simulator::objects
  Vector2 position;                     ///< the object's position `r` at the event (m)
  Vector2 target;                       ///< Start: the grabbed point; Move: the mouse target (m)
  std::uint64_t step = 0;               ///< Simulator::stepCount at the event
  std::uint64_t stepsSinceRelease = 0;  ///< Settled: steps since the release
};

/// Owns a simulation thread that builds, steps (World::advanceTime(), virtual: a subclass's own
/// per-step logic runs) and destroys the world; nothing else touches the world (it is not
/// thread-safe). Dragging and the solver apply to a Simulator only; other worlds ignore them. The
/// other threads talk to it through commands, queued under a mutex and applied by the simulation
/// thread between steps, and read it through snapshots: after a step the thread captures a
/// WorldSnapshot and swaps it in as latest().
///
/// Snapshots are published after every change of state and, while running, at most about 120
/// times per second, so a fast run spends its time stepping, not drawing. Every public function
/// may be called from any thread; in practice the GUI thread. The destructor stops the thread
/// and joins it; a step in progress finishes first.
class SimulationRunner {
 public:
  /// Called on the simulation thread for each drag event (for logs and tests).
  using DragListener = std::function<void(const DragEvent&)>;

  /// Starts the simulation thread, which builds the first world with `setup.makeWorld`.
  /// @param setup the world's factory, the agent's signals and how the run starts
  /// @param dragListener optional, called on the simulation thread for each DragEvent
  /// @throws std::invalid_argument if `setup.makeWorld` is empty
  explicit SimulationRunner(SimulationSetup setup, DragListener dragListener = {});
  ~SimulationRunner();
  SimulationRunner(const SimulationRunner&) = delete;
  SimulationRunner& operator=(const SimulationRunner&) = delete;

  /// Steps continuously.
  void run();
  /// Stops stepping (the world stays as it is).
  void pause();
  /// Pauses, then does exactly one step.
  void singleStep();
  /// Replaces the world with a fresh one from SimulationSetup::makeWorld, keeping the run
  /// state, speed, solver and overlays. A drag in progress ends.
  void reset();
  /// Steps per second to aim at; 0 (or less) runs as fast as possible.
  void setStepsPerSecond(double stepsPerSecond);
  /// The contact solver, for this world and the ones reset() builds (when they are
  /// simulators).
  void setSolver(ContactSolverKind solver);
  /// The overlays drawn into the snapshots.
  void setDrawOptions(const DrawOptions& options);
  /// Pauses when the step count reaches @p step (0: never). Used to stop after N steps.
  void pauseAtStep(std::uint64_t step);

  /// Grabs object @p object of world @p generation (both as in the snapshot that was picked
  /// from) at @p grabPoint (m). Ignored if that world is gone or not a Simulator, the index is
  /// out of range or the object is fixed.
  void startDrag(std::uint64_t generation, std::uint32_t object, Vector2 grabPoint);
  /// Moves the mouse target of the current drag to @p target (m).
  void dragTo(Vector2 target);
  /// Releases the dragged object.
  void stopDrag();

  /// The latest snapshot; never null (before the first world is built it is empty).
  [[nodiscard]] std::shared_ptr<const WorldSnapshot> latest() const;
  /// Whether stepping was last asked for (by run(), or false after pause(), singleStep(),
  /// pauseAtStep() or an error): what a Run/Pause control shows.
  [[nodiscard]] bool running() const { return runningShown_.load(); }
  /// The speed last set (steps per second, 0 = as fast as possible).
  [[nodiscard]] double stepsPerSecond() const { return stepsPerSecondShown_.load(); }
  /// The solver last set.
  [[nodiscard]] ContactSolverKind solver() const { return solverShown_.load(); }
  /// The overlays last set.
  [[nodiscard]] DrawOptions drawOptions() const;

  /// Steps after a release at which a DragEvent::Kind::Settled is reported.
  static constexpr std::uint64_t settleReportSteps[2] = {10, 50};

 private:
  using Clock = std::chrono::steady_clock;
  struct Command {
    enum class Type : std::uint8_t {
      Run,
      Pause,
      Step,
      Reset,
      Speed,
      Solver,
      Draw,
      PauseAt,
      StartDrag,
      DragTo,
      StopDrag,
    };
    Type type = Type::Run;
    double value = 0;
    std::uint64_t number = 0;
    std::uint32_t object = 0;
    Vector2 point{};
    ContactSolverKind solver = ContactSolverKind::Baraff;
    DrawOptions draw{};
  };

  void post(const Command& command);
  void threadMain();
  void drainCommands();
  void apply(const Command& command);
  void rebuild();
  void step();
  void publish();
  void emit(DragEvent::Kind kind, std::uint64_t stepsSinceRelease = 0);
  void setRunning(bool running);
  void fail(const char* what, const std::exception& error);

  const SimulationSetup setup_;
  const DragListener dragListener_;

  // Shared between threads, under mutex_.
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Command> queue_;
  std::shared_ptr<WorldSnapshot> latest_;
  DrawOptions drawShown_;
  std::atomic<bool> stop_{false};  // written under mutex_, so a waiting thread cannot miss it
  std::atomic<bool> hasCommands_{false};  // lets a fast run skip the mutex when nothing is queued
  std::atomic<bool> runningShown_;
  std::atomic<double> stepsPerSecondShown_;
  std::atomic<ContactSolverKind> solverShown_;

  // The simulation thread's own state: touched by no other thread.
  std::unique_ptr<World> world_;
  Simulator* simulator_ = nullptr;  // world_ when it is a Simulator, else null
  std::vector<Command> applying_;
  std::shared_ptr<WorldSnapshot> building_;
  std::uint64_t generation_ = 0;
  std::uint64_t serial_ = 0;
  bool running_ = false;
  std::uint64_t pendingSteps_ = 0;
  double stepsPerSecond_ = 0;
  ContactSolverKind solver_ = ContactSolverKind::Baraff;
  DrawOptions draw_;
  std::uint64_t pauseAt_ = 0;
  std::string error_;
  bool dirty_ = true;  // state changed since the last snapshot
  Clock::time_point nextStep_;
  Clock::time_point lastPublish_;
  Clock::time_point rateStart_;
  std::uint64_t rateSteps_ = 0;
  double rate_ = 0;
  bool dragging_ = false;
  std::uint32_t dragObject_ = 0;
  Vector2 dragLocal_;  // grabbed point in the dragged body's frame, to draw the drag line
  Vector2 dragTarget_;
  bool settling_ = false;  // reporting Settled events for the last released object
  std::uint64_t releaseStep_ = 0;

  std::thread thread_;  // last: started once everything above is initialised
};

}  // namespace thyrix
