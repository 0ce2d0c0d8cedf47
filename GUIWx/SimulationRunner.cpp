#include <GUIWx/SimulationRunner.h>

#include <stdexcept>

namespace thyrix {
namespace {

// While running, a snapshot at most this often: more than a 60 Hz screen shows, and few enough
// that copying the drawing costs a fast run little.
constexpr auto publishInterval = std::chrono::microseconds(8333);
// The measured steps per second are refreshed this often.
constexpr auto rateWindow = std::chrono::milliseconds(500);
// A run at a chosen speed that falls further behind than this (a slow step, a busy machine)
// resumes from now rather than race to catch up.
constexpr auto maxLag = std::chrono::milliseconds(100);

}  // namespace

SimulationRunner::SimulationRunner(SimulationSetup setup, DragListener dragListener)
    : setup_(std::move(setup)),
      dragListener_(std::move(dragListener)),
      latest_(std::make_shared<WorldSnapshot>()),
      drawShown_(setup_.drawOptions),
      runningShown_(setup_.startRunning),
      stepsPerSecondShown_(setup_.stepsPerSecond > 0 ? setup_.stepsPerSecond : 0),
      solverShown_(setup_.solver),
      running_(setup_.startRunning),
      stepsPerSecond_(setup_.stepsPerSecond > 0 ? setup_.stepsPerSecond : 0),
      solver_(setup_.solver),
      draw_(setup_.drawOptions),
      pauseAt_(setup_.pauseAtStep) {
  if (!setup_.makeWorld) throw std::invalid_argument("SimulationSetup.makeWorld is empty");
  latest_->clearWorld();
  thread_ = std::thread(&SimulationRunner::threadMain, this);
}

SimulationRunner::~SimulationRunner() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SimulationRunner::post(const Command& command) {
  {
    const std::lock_guard lock(mutex_);
    queue_.push_back(command);
    hasCommands_ = true;
  }
  wake_.notify_all();
}

void SimulationRunner::run() {
  runningShown_ = true;
  post({.type = Command::Type::Run});
}

void SimulationRunner::pause() {
  runningShown_ = false;
  post({.type = Command::Type::Pause});
}

void SimulationRunner::singleStep() {
  runningShown_ = false;
  post({.type = Command::Type::Step});
}

void SimulationRunner::reset() { post({.type = Command::Type::Reset}); }

void SimulationRunner::setStepsPerSecond(double stepsPerSecond) {
  const double value = stepsPerSecond > 0 ? stepsPerSecond : 0;
  stepsPerSecondShown_ = value;
  post({.type = Command::Type::Speed, .value = value});
}

void SimulationRunner::setSolver(ContactSolverKind solver) {
  solverShown_ = solver;
  post({.type = Command::Type::Solver, .solver = solver});
}

void SimulationRunner::setDrawOptions(const DrawOptions& options) {
  {
    const std::lock_guard lock(mutex_);
    drawShown_ = options;
  }
  post({.type = Command::Type::Draw, .draw = options});
}

DrawOptions SimulationRunner::drawOptions() const {
  const std::lock_guard lock(mutex_);
  return drawShown_;
}

void SimulationRunner::pauseAtStep(std::uint64_t step) {
  post({.type = Command::Type::PauseAt, .number = step});
}

void SimulationRunner::startDrag(std::uint64_t generation, std::uint32_t object,
                                 Vector2 grabPoint) {
  post({.type = Command::Type::StartDrag,
        .number = generation,
        .object = object,
        .point = grabPoint});
}

void SimulationRunner::dragTo(Vector2 target) {
  post({.type = Command::Type::DragTo, .point = target});
}

void SimulationRunner::stopDrag() { post({.type = Command::Type::StopDrag}); }

std::shared_ptr<const WorldSnapshot> SimulationRunner::latest() const {
  const std::lock_guard lock(mutex_);
  return latest_;
}

// --- everything below runs on the simulation thread ---

void SimulationRunner::threadMain() {
  rebuild();
  rateStart_ = Clock::now();
  nextStep_ = rateStart_;
  for (;;) {
    drainCommands();
    if (stop_) break;

    bool stepNow = false;
    const Clock::time_point now = Clock::now();
    if (world_ && pendingSteps_ > 0) {
      --pendingSteps_;
      stepNow = true;
    } else if (world_ && running_) {
      if (stepsPerSecond_ <= 0) {
        stepNow = true;
      } else if (now >= nextStep_) {
        stepNow = true;
        nextStep_ += std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(1 / stepsPerSecond_));
        if (nextStep_ < now - maxLag) nextStep_ = now;
      }
    }
    if (stepNow) step();

    const Clock::time_point after = Clock::now();
    if (after - rateStart_ >= rateWindow) {
      rate_ = static_cast<double>(rateSteps_) /
              std::chrono::duration<double>(after - rateStart_).count();
      rateSteps_ = 0;
      rateStart_ = after;
      dirty_ = dirty_ || running_;
    }
    if (dirty_ || (stepNow && after - lastPublish_ >= publishInterval)) publish();

    if (!stepNow) {
      // Nothing to do now: sleep until a command comes, or the next step is due.
      std::unique_lock lock(mutex_);
      const auto woken = [this] { return stop_ || !queue_.empty(); };
      if (world_ && running_ && stepsPerSecond_ > 0)
        wake_.wait_until(lock, nextStep_, woken);
      else if (!(world_ && (running_ || pendingSteps_ > 0)))
        wake_.wait(lock, woken);
    }
  }
  simulator_ = nullptr;
  world_.reset();  // the world is destroyed by the thread that built it
}

void SimulationRunner::drainCommands() {
  if (!hasCommands_) return;
  {
    const std::lock_guard lock(mutex_);
    applying_.swap(queue_);
    hasCommands_ = false;
  }
  for (const Command& command : applying_) apply(command);
  applying_.clear();
}

void SimulationRunner::setRunning(bool running) {
  if (running && !running_) nextStep_ = Clock::now();
  if (!running) rate_ = 0;
  running_ = running;
  runningShown_ = running;
  dirty_ = true;
}

void SimulationRunner::apply(const Command& command) {
  switch (command.type) {
    case Command::Type::Run:
      setRunning(world_ != nullptr);
      break;
    case Command::Type::Pause:
      setRunning(false);
      pendingSteps_ = 0;
      break;
    case Command::Type::Step:
      setRunning(false);
      if (world_) ++pendingSteps_;
      break;
    case Command::Type::Reset:
      rebuild();
      break;
    case Command::Type::Speed:
      stepsPerSecond_ = command.value;
      nextStep_ = Clock::now();
      dirty_ = true;
      break;
    case Command::Type::Solver:
      solver_ = command.solver;
      if (simulator_) simulator_->setContactSolver(solver_);
      dirty_ = true;
      break;
    case Command::Type::Draw:
      draw_ = command.draw;
      dirty_ = true;
      break;
    case Command::Type::PauseAt:
      pauseAt_ = command.number;
      if (pauseAt_ > 0 && world_ && world_->stepCount() >= pauseAt_) {
        pauseAt_ = 0;
        setRunning(false);
      }
      break;
    case Command::Type::StartDrag: {
      if (!simulator_ || command.number != generation_ ||
          command.object >= simulator_->objects.size())
        break;
      PhysicalObject& object = simulator_->objects[command.object];
      if (object.fixed) break;
      try {
        simulator_->startDrag(object, command.point);
      } catch (const std::exception&) {
        break;  // a non-finite point: no drag
      }
      const PhysicalObject* body = simulator_->draggedObject();
      dragging_ = body != nullptr;
      if (!dragging_) break;
      dragObject_ = command.object;
      dragLocal_ = body->toLocal(command.point);
      dragTarget_ = command.point;
      settling_ = false;
      dirty_ = true;
      emit(DragEvent::Kind::Start);
      break;
    }
    case Command::Type::DragTo:
      if (!dragging_) break;
      try {
        simulator_->dragTo(command.point);
      } catch (const std::exception&) {
        break;
      }
      dragTarget_ = command.point;
      dirty_ = true;
      emit(DragEvent::Kind::Move);
      break;
    case Command::Type::StopDrag:
      if (!dragging_) break;
      simulator_->stopDrag();
      dragging_ = false;
      settling_ = true;
      releaseStep_ = simulator_->stepCount();
      dirty_ = true;
      emit(DragEvent::Kind::End);
      break;
  }
}

void SimulationRunner::rebuild() {
  dragging_ = false;
  settling_ = false;
  pendingSteps_ = 0;
  simulator_ = nullptr;
  world_.reset();  // free the old world before building the new one
  ++generation_;
  error_.clear();
  try {
    world_ = setup_.makeWorld();
    if (!world_) throw std::runtime_error("SimulationSetup.makeWorld returned no world");
    simulator_ = dynamic_cast<Simulator*>(world_.get());
    if (simulator_) simulator_->setContactSolver(solver_);
  } catch (const std::exception& error) {
    simulator_ = nullptr;
    world_.reset();
    fail("building the world failed: ", error);
  }
  rateSteps_ = 0;
  rateStart_ = Clock::now();
  nextStep_ = rateStart_;
  dirty_ = true;
}

void SimulationRunner::fail(const char* what, const std::exception& error) {
  error_ = std::string(what) + error.what();
  setRunning(false);
  pendingSteps_ = 0;
}

void SimulationRunner::step() {
  try {
    world_->advanceTime();  // virtual: a subclass's own per-step logic runs here too
  } catch (const std::exception& error) {
    fail("step failed: ", error);
    return;
  }
  ++rateSteps_;
  const std::uint64_t steps = world_->stepCount();
  if (pauseAt_ > 0 && steps >= pauseAt_) {
    pauseAt_ = 0;
    setRunning(false);
  }
  if (settling_) {
    const std::uint64_t since = steps - releaseStep_;
    for (const std::uint64_t report : settleReportSteps)
      if (since == report) emit(DragEvent::Kind::Settled, since);
    if (since >= settleReportSteps[1]) settling_ = false;
  }
  if (!running_) dirty_ = true;  // a single step (or the last one): show it at once
}

void SimulationRunner::emit(DragEvent::Kind kind, std::uint64_t stepsSinceRelease) {
  if (!dragListener_ || !simulator_ || dragObject_ >= simulator_->objects.size()) return;
  DragEvent event;
  event.kind = kind;
  event.object = dragObject_;
  event.position = simulator_->objects[dragObject_].r;
  event.target = dragTarget_;
  event.step = simulator_->stepCount();
  event.stepsSinceRelease = stepsSinceRelease;
  dragListener_(event);
}

void SimulationRunner::publish() {
  // Reuse the snapshot replaced last time unless a reader still holds it: once out of latest_,
  // nobody can newly get hold of it, so a use count of one means it is ours alone.
  if (!building_ || building_.use_count() > 1) building_ = std::make_shared<WorldSnapshot>();
  WorldSnapshot& s = *building_;
  if (world_) {
    s.capture(*world_, draw_);
    s.sensors.clear();
    s.effectors.clear();
    if (setup_.agentSignals) {
      try {
        const AgentSignals signals = setup_.agentSignals(*world_);
        s.sensors.assign(signals.sensors.begin(), signals.sensors.end());
        s.effectors.assign(signals.effectors.begin(), signals.effectors.end());
      } catch (const std::exception& error) {
        fail("reading the agent's signals failed: ", error);
      }
    }
    const PhysicalObject* body = simulator_ != nullptr ? simulator_->draggedObject() : nullptr;
    s.dragging = dragging_ && body != nullptr;
    if (s.dragging) {
      s.dragPoint = body->toWorld(dragLocal_);
      s.dragTarget = dragTarget_;
    }
  } else {
    s.clearWorld();
  }
  s.generation = generation_;
  s.serial = ++serial_;
  s.running = running_;
  s.stepsPerSecond = running_ ? rate_ : 0;
  s.solver = solver_;
  s.error = error_;
  {
    const std::lock_guard lock(mutex_);
    std::swap(latest_, building_);
  }
  lastPublish_ = Clock::now();
  dirty_ = false;
}

}  // namespace thyrix
