// The simulation thread: it steps the world exactly as a plain loop does (bit for bit), pauses
// at a chosen step, single-steps, resets through the factory, applies queued drags between
// steps and reports them, turns exceptions into a message, and joins when destroyed even while
// running flat out. No window is involved; nothing is timed except generous waits.

#include <GUIWx/SimulationRunner.h>

#include <ThyrixLite/Border.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/World.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace thyrix {
namespace {

// A circle pushed by a constant force, so the world changes at every step.
class PushedCircle : public Circle {
 public:
  PushedCircle(Vector2 force) : Circle(real(0.3), real(1)), force_(force) {}
  void control() override { externalForce += force_; }

 private:
  Vector2 force_;
};

// A floor, a pushed circle shoving a row of three: contacts at every step.
std::unique_ptr<Simulator> makePushWorld() {
  auto simulator = std::make_unique<Simulator>();
  simulator->registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& pusher = simulator->registerObject(std::make_unique<PushedCircle>(Vector2{1, -0.2}));
  pusher.r = {0, real(0.3)};
  for (int i = 1; i <= 3; ++i) {
    auto& c = simulator->registerObject(std::make_unique<Circle>(real(0.3), real(1)));
    c.r = {real(0.62) * i, real(0.3)};
  }
  return simulator;
}

// One free circle at the origin and nothing else.
std::unique_ptr<Simulator> makeLoneCircle() {
  auto simulator = std::make_unique<Simulator>();
  simulator->registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  return simulator;
}

template <class Predicate>
std::shared_ptr<const WorldSnapshot> waitFor(const SimulationRunner& runner, Predicate done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    std::shared_ptr<const WorldSnapshot> s = runner.latest();
    if (done(*s)) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "timed out waiting for a snapshot";
  return runner.latest();
}

TEST(SimulationRunner, StepsLikeAPlainLoopAndPausesAtTheChosenStep) {
  SimulationSetup setup;
  setup.makeWorld = makePushWorld;
  setup.stepsPerSecond = 0;
  setup.pauseAtStep = 120;
  SimulationRunner runner(setup);
  const auto s = waitFor(runner, [](const WorldSnapshot& w) { return !w.running && w.step > 0; });
  EXPECT_EQ(s->step, 120u);
  EXPECT_EQ(s->generation, 1u);
  EXPECT_FALSE(runner.running());

  std::unique_ptr<Simulator> reference = makePushWorld();
  for (int i = 0; i < 120; ++i) reference->advanceTime();
  ASSERT_EQ(s->shapes.size(), 4u);
  for (const PickShape& shape : s->shapes) {
    EXPECT_EQ(shape.a, reference->objects[shape.object].r) << "object " << shape.object;
  }
  EXPECT_EQ(s->contacts, reference->contacts.size());
  EXPECT_GT(s->contacts, 0u);
}

// A simulator whose own per-step logic, in its advanceTime() override, pushes the first
// movable object and counts the steps.
class ScriptedSimulator : public Simulator {
 public:
  int scriptedSteps = 0;
  void advanceTime() override {
    ++scriptedSteps;
    objects[1].externalForce += Vector2{2, 0};
    Simulator::advanceTime();
  }
};

TEST(SimulationRunner, RunsASimulatorSubclassesOwnStepLogic) {
  // The thread calls the world's advanceTime(): the subclass's logic runs at every step, as in
  // a console loop, and moves the pushed circle as it moves there.
  const auto make = [] {
    auto simulator = std::make_unique<ScriptedSimulator>();
    simulator->registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    simulator->registerObject(std::make_unique<Circle>(real(0.5), real(1))).r = {0, 1};
    return simulator;
  };
  SimulationSetup setup;
  setup.makeWorld = make;
  setup.stepsPerSecond = 0;
  setup.pauseAtStep = 60;
  SimulationRunner runner(setup);
  const auto s = waitFor(runner, [](const WorldSnapshot& w) { return !w.running && w.step > 0; });
  EXPECT_EQ(s->step, 60u);
  const auto reference = make();
  for (int i = 0; i < 60; ++i) reference->advanceTime();
  EXPECT_EQ(reference->scriptedSteps, 60);
  ASSERT_EQ(s->shapes.size(), 1u);
  EXPECT_EQ(s->shapes[0].a, reference->objects[1].r);
  EXPECT_GT(s->shapes[0].a.x, 1);  // pushed at 2 m/s for 0.6 s
}

// A World that is not a Simulator: one value that grows by its time step each step, drawn as a
// circle at that abscissa.
class CountingWorld : public World {
 public:
  CountingWorld() : World(real(0.25)) {}
  void advanceTime() override {
    World::advanceTime();
    x_ += timestep();
  }
  void draw(GUI& gui) const override {
    gui.drawCircle({x_, 0}, real(0.1), 0, colors::red, colors::black);
  }

 private:
  real x_ = 0;
};

TEST(SimulationRunner, StepsAndDrawsAnyWorld) {
  SimulationSetup setup;
  setup.makeWorld = [] { return std::make_unique<CountingWorld>(); };
  setup.stepsPerSecond = 0;
  setup.pauseAtStep = 8;
  SimulationRunner runner(setup);
  auto s = waitFor(runner, [](const WorldSnapshot& w) { return !w.running && w.step > 0; });
  EXPECT_EQ(s->step, 8u);
  EXPECT_DOUBLE_EQ(s->time, 8 * 0.25);
  EXPECT_FALSE(s->isSimulator);
  EXPECT_TRUE(s->error.empty()) << s->error;
  EXPECT_TRUE(s->shapes.empty());  // nothing to drag
  EXPECT_EQ(s->contacts, 0u);
  // Its drawing is its own draw(): the circle where 8 steps of 0.25 put it.
  ASSERT_EQ(s->drawing.commands().size(), 1u);
  const DrawCommand& circle = s->drawing.commands()[0];
  EXPECT_EQ(circle.kind, DrawCommand::Kind::Circle);
  ASSERT_EQ(circle.count, 1u);
  EXPECT_EQ(s->drawing.points(circle)[0], (Vector2{2, 0}));
  // Dragging needs a Simulator: ignored, and the world keeps stepping.
  runner.startDrag(s->generation, 0, {0, 0});
  runner.singleStep();
  s = waitFor(runner, [](const WorldSnapshot& w) { return w.step == 9; });
  EXPECT_FALSE(s->dragging);
}

TEST(SimulationRunner, SingleStepsRunsAndPauses) {
  SimulationSetup setup;
  setup.makeWorld = makePushWorld;
  setup.startRunning = false;
  SimulationRunner runner(setup);
  auto s = waitFor(runner, [](const WorldSnapshot& w) { return w.generation == 1; });
  EXPECT_EQ(s->step, 0u);
  EXPECT_FALSE(s->running);
  for (int i = 0; i < 3; ++i) runner.singleStep();
  s = waitFor(runner, [](const WorldSnapshot& w) { return w.step == 3; });
  EXPECT_FALSE(s->running);

  runner.setStepsPerSecond(0);
  runner.run();
  EXPECT_TRUE(runner.running());
  s = waitFor(runner, [](const WorldSnapshot& w) { return w.step >= 50 && w.running; });
  runner.pause();
  s = waitFor(runner, [](const WorldSnapshot& w) { return !w.running; });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(runner.latest()->step, s->step);  // paused means no more steps
}

TEST(SimulationRunner, ResetRebuildsTheWorldThroughTheFactory) {
  std::atomic<int> built{0};
  SimulationSetup setup;
  setup.makeWorld = [&built] {
    ++built;
    return makePushWorld();
  };
  setup.stepsPerSecond = 0;
  setup.pauseAtStep = 40;
  SimulationRunner runner(setup);
  waitFor(runner, [](const WorldSnapshot& w) { return w.step == 40 && !w.running; });
  runner.reset();
  const auto s = waitFor(runner, [](const WorldSnapshot& w) { return w.generation == 2; });
  EXPECT_EQ(s->step, 0u);
  EXPECT_EQ(built.load(), 2);
  const std::unique_ptr<Simulator> fresh = makePushWorld();
  EXPECT_EQ(s->shapes[0].a, fresh->objects[s->shapes[0].object].r);
}

TEST(SimulationRunner, DragPullsTheObjectAndReportsEachEvent) {
  std::mutex mutex;
  std::vector<DragEvent> events;
  SimulationSetup setup;
  setup.makeWorld = makeLoneCircle;
  setup.stepsPerSecond = 0;
  SimulationRunner runner(setup, [&](const DragEvent& e) {
    const std::lock_guard lock(mutex);
    events.push_back(e);
  });
  waitFor(runner, [](const WorldSnapshot& w) { return w.generation == 1 && w.step > 0; });
  runner.startDrag(99, 0, {0, 0});  // a world that does not exist: ignored
  runner.startDrag(1, 5, {0, 0});   // no object 5: ignored
  runner.startDrag(1, 0, {0, 0});
  runner.dragTo({2, 1});
  auto s = waitFor(runner, [](const WorldSnapshot& w) {
    return w.dragging && distance(w.shapes[0].a, {2, 1}) < real(1e-3);
  });
  EXPECT_EQ(s->dragTarget, (Vector2{2, 1}));
  runner.stopDrag();
  waitFor(runner, [&](const WorldSnapshot&) {
    const std::lock_guard lock(mutex);
    return !events.empty() && events.back().kind == DragEvent::Kind::Settled &&
           events.back().stepsSinceRelease == 50;
  });

  const std::lock_guard lock(mutex);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].kind, DragEvent::Kind::Start);
  EXPECT_EQ(events[0].object, 0u);
  EXPECT_EQ(events[0].target, (Vector2{0, 0}));
  EXPECT_EQ(events[1].kind, DragEvent::Kind::Move);
  EXPECT_EQ(events[1].target, (Vector2{2, 1}));
  EXPECT_EQ(events[2].kind, DragEvent::Kind::End);
  EXPECT_LT(distance(events[2].position, {2, 1}), real(1e-3));
  // Released, it stops at once (F = m v): the same position 10 and 50 steps later.
  EXPECT_EQ(events[3].stepsSinceRelease, 10u);
  EXPECT_EQ(events[3].position, events[2].position);
  EXPECT_EQ(events[3].step, events[2].step + 10);
  EXPECT_EQ(events[4].stepsSinceRelease, 50u);
  EXPECT_EQ(events[4].position, events[2].position);
}

TEST(SimulationRunner, SolverAndOverlaysReachTheWorld) {
  SimulationSetup setup;
  setup.makeWorld = makePushWorld;
  setup.stepsPerSecond = 0;
  setup.pauseAtStep = 30;
  SimulationRunner runner(setup);
  const auto before = waitFor(runner, [](const WorldSnapshot& w) { return !w.running && w.step; });
  EXPECT_EQ(before->solver, ContactSolverKind::Baraff);
  runner.setSolver(ContactSolverKind::GaussSeidel);
  DrawOptions options;
  options.contacts = true;
  runner.setDrawOptions(options);
  EXPECT_EQ(runner.solver(), ContactSolverKind::GaussSeidel);
  EXPECT_TRUE(runner.drawOptions().contacts);
  const auto after = waitFor(
      runner, [](const WorldSnapshot& w) { return w.solver == ContactSolverKind::GaussSeidel; });
  // Each contact adds three lines (a cross and the normal) to the drawing.
  EXPECT_EQ(after->drawing.commands().size(),
            before->drawing.commands().size() + 3 * before->contacts);
}

TEST(SimulationRunner, ReportsAFailingFactoryAndRecoversOnReset) {
  std::atomic<int> calls{0};
  SimulationSetup setup;
  setup.makeWorld = [&calls]() -> std::unique_ptr<Simulator> {
    if (calls++ == 0) throw std::runtime_error("no arena today");
    return makeLoneCircle();
  };
  SimulationRunner runner(setup);
  auto s = waitFor(runner, [](const WorldSnapshot& w) { return !w.error.empty(); });
  EXPECT_NE(s->error.find("no arena today"), std::string::npos);
  EXPECT_FALSE(s->running);
  EXPECT_TRUE(s->shapes.empty());
  runner.reset();
  s = waitFor(runner, [](const WorldSnapshot& w) { return w.generation == 2; });
  EXPECT_TRUE(s->error.empty());
  EXPECT_EQ(s->shapes.size(), 1u);
}

TEST(SimulationRunner, JoinsWhenDestroyedWhileRunningFlatOut) {
  for (int i = 0; i < 5; ++i) {
    SimulationSetup setup;
    setup.makeWorld = makePushWorld;
    setup.stepsPerSecond = 0;
    SimulationRunner runner(setup);
    waitFor(runner, [](const WorldSnapshot& w) { return w.step > 10; });
    runner.dragTo({1, 1});  // commands still queued at destruction are dropped
    runner.reset();
  }  // each destructor stops and joins the thread; a hang would time the test out
  SUCCEED();
}

}  // namespace
}  // namespace thyrix
