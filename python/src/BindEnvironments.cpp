#include "ArrayChecks.h"
#include "Bindings.h"
#include "SpherusEnvironment.h"
#include "SpherusVectorEnvironment.h"

#include <Agents/Spherus.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <pybind11/stl.h>

#include <thread>

namespace py = pybind11;

namespace thyrix::python {

namespace {

constexpr py::ssize_t actionSize = Spherus::effectorCount;
constexpr py::ssize_t observationSize = Spherus::sensorCount;

const SpherusEpisode& checkedWorld(const SpherusEnvironment& e) {
  if (e.world() == nullptr) throw py::value_error("reset() must be called first");
  return *e.world();
}

std::string renderSvg(const SpherusEnvironment& e, int width) {
  const SpherusEpisode& world = checkedWorld(e);
  const real size = e.task().arena.size;
  SvgGUI svg({0, 0}, {size, size}, width);
  DrawOptions options;
  options.tactile = true;
  options.visualRays = true;
  drawWorld(world, svg, options);
  return svg.svg();
}

std::span<real> spanOf(py::array_t<real>& array) {
  return {array.mutable_data(), static_cast<std::size_t>(array.size())};
}

}  // namespace

void bindEnvironments(py::module_& m) {
  py::class_<SpherusTask>(m, "SpherusTask",
                          "What a Spherus episode rewards, how long it lasts and its arena: the "
                          "task of evaluate() and of the Spherus environments.")
      .def(py::init([](const std::string& goal, long steps, py::object network, int objects,
                       bool randomPose) {
             SpherusTask task;
             task.goal = parseSpherusGoal(goal);
             task.stepCount = steps;
             task.network = py::isinstance<py::str>(network)
                                ? parseSpherusNetwork(network.cast<std::string>())
                                : network.cast<NetworkSpec>();
             task.arena.objects = objects;
             task.randomPose = randomPose;
             if (steps <= 0)
               throw py::value_error("steps must be positive (got " + std::to_string(steps) + ")");
             return task;
           }),
           py::arg("task") = "distance", py::arg("steps") = 1000, py::arg("network") = "ff:8",
           py::arg("objects") = 20, py::arg("random_pose") = true,
           "task: 'distance' (straight distance from start to end, m) or 'clear' (how far the "
           "balls were pushed toward the walls, m); network: 'ff', 'ff:H1[,H2...]', "
           "'ctrnn:N' or a NetworkSpec; random_pose: start the agent at a pose drawn from the "
           "episode's seed.")
      .def_property_readonly(
          "task", [](const SpherusTask& t) { return std::string(toString(t.goal)); },
          "'distance' or 'clear'.")
      .def_readonly("steps", &SpherusTask::stepCount, "Steps of an episode.")
      .def_readonly("network", &SpherusTask::network, "The controller's network.")
      .def_readonly("random_pose", &SpherusTask::randomPose, "Random start pose.")
      .def_property_readonly(
          "objects", [](const SpherusTask& t) { return t.arena.objects; }, "Balls.")
      .def(
          "make_world",
          [](const SpherusTask& t, py::handle parameters, std::uint64_t seed) {
            const auto array = checkedArray(
                parameters, {static_cast<py::ssize_t>(t.network.parameterCount())}, "parameters");
            const std::vector<double> values(array.data(), array.data() + array.size());
            return std::unique_ptr<SpherusSimulator>(t.makeWorld(values, seed));
          },
          py::arg("parameters"), py::arg("seed"),
          "The episode evaluate() runs for these parameters and this episode seed (a "
          "SpherusSimulator driven by the network).")
      .def(
          "fitness",
          [](const SpherusTask& t, const SpherusSimulator& world) {
            const auto* episode = dynamic_cast<const SpherusEpisode*>(&world);
            if (episode == nullptr) throw py::type_error("world must come from make_world()");
            return t.fitness(*episode);
          },
          py::arg("world"), "The fitness of a world made by make_world().");

  py::class_<SpherusEnvironment>(m, "SpherusEnvCore",
                                 "The C++ core of thyrix.envs.SpherusEnv (use that).")
      .def(py::init<const SpherusTask&>(), py::arg("task"), "An environment of `task`.")
      .def(
          "reset",
          [](SpherusEnvironment& e, std::uint64_t seed) {
            e.reset(seed);
            py::array_t<real> observation(observationSize);
            e.observe(spanOf(observation));
            return observation;
          },
          py::arg("seed"), "Episode 0 of the stream of `seed`; returns the observation.")
      .def(
          "reset_next",
          [](SpherusEnvironment& e) {
            if (e.world() == nullptr) throw py::value_error("reset(seed) must come first");
            e.resetNext();
            py::array_t<real> observation(observationSize);
            e.observe(spanOf(observation));
            return observation;
          },
          "The stream's next episode; returns the observation.")
      .def(
          "step",
          [](SpherusEnvironment& e, py::handle action) {
            if (e.world() == nullptr) throw py::value_error("reset() must be called before step()");
            const auto checked = checkedArray(action, {actionSize}, "action");
            py::array_t<real> observation(observationSize);
            const StepOutcome outcome =
                e.step({checked.data(), static_cast<std::size_t>(actionSize)}, spanOf(observation));
            return py::make_tuple(observation, outcome.reward, outcome.terminated,
                                  outcome.truncated);
          },
          py::arg("action"), "One step; returns (observation, reward, terminated, truncated).")
      .def(
          "render", [](const SpherusEnvironment& e, int width) { return renderSvg(e, width); },
          py::arg("width") = 600, "The arena as an SVG document, touch and vision drawn.")
      .def_property_readonly(
          "agent_centre",
          [](const SpherusEnvironment& e) {
            return fromVector2(checkedWorld(e).spherus().centre());
          },
          "The agent's centre (x, y).")
      .def(
          "save_state",
          [](const SpherusEnvironment& e) {
            checkedWorld(e);
            const EnvironmentState state = e.saveState();
            return py::make_tuple(state.world, state.seed, state.episode, state.step, state.score);
          },
          "The environment's state: (world state, seed, episode, step, score).")
      .def(
          "restore_state",
          [](SpherusEnvironment& e, const WorldState& world, std::uint64_t seed,
             std::uint64_t episode, long step, double score) {
            e.restoreState({world, seed, episode, step, score});
            py::array_t<real> observation(observationSize);
            e.observe(spanOf(observation));
            return observation;
          },
          py::arg("world"), py::arg("seed"), py::arg("episode"), py::arg("step"), py::arg("score"),
          "Puts the environment in a saved state; returns the observation.")
      .def_property_readonly("step_index", &SpherusEnvironment::stepIndex,
                             "Steps taken in the episode.")
      .def_property_readonly("episode", &SpherusEnvironment::episode,
                             "The episode's index since the last seeded reset.");

  py::class_<SpherusVectorEnvironment>(m, "SpherusVectorEnvCore",
                                       "The C++ core of thyrix.envs.SpherusVectorEnv (use that).")
      .def(py::init([](std::size_t count, std::size_t threads, const SpherusTask& task) {
             return std::make_unique<SpherusVectorEnvironment>(count, threads, task);
           }),
           py::arg("num_envs"), py::arg("threads"), py::arg("task"),
           "`num_envs` environments of `task` stepped on `threads` threads.")
      .def_property_readonly("num_envs", &SpherusVectorEnvironment::size, "Worlds.")
      .def_property_readonly("threads", &SpherusVectorEnvironment::threadCount,
                             "Threads stepping them, the caller's included.")
      .def(
          "reset",
          [](SpherusVectorEnvironment& v, std::uint64_t seed) {
            py::array_t<real> observations({static_cast<py::ssize_t>(v.size()), observationSize});
            {
              py::gil_scoped_release release;
              v.reset(seed, spanOf(observations));
            }
            return observations;
          },
          py::arg("seed"), "Resets world i with seed `seed + i`; returns the observations.")
      .def(
          "reset_next",
          [](SpherusVectorEnvironment& v) {
            if (v.environment(0).world() == nullptr)
              throw py::value_error("reset(seed) must come first");
            py::array_t<real> observations({static_cast<py::ssize_t>(v.size()), observationSize});
            {
              py::gil_scoped_release release;
              v.resetNext(spanOf(observations));
            }
            return observations;
          },
          "Starts every world's next episode; returns the observations.")
      .def(
          "step",
          [](SpherusVectorEnvironment& v, py::handle actions) {
            const auto n = static_cast<py::ssize_t>(v.size());
            if (v.environment(0).world() == nullptr)
              throw py::value_error("reset() must be called before step()");
            const auto checked = checkedArray(actions, {n, actionSize}, "actions");
            py::array_t<real> observations({n, observationSize});
            py::array_t<double> rewards(n);
            py::array_t<bool> terminated(n), truncated(n);
            py::array_t<real> finals({n, observationSize});
            {
              py::gil_scoped_release release;
              v.step({checked.data(), static_cast<std::size_t>(checked.size())},
                     spanOf(observations), {rewards.mutable_data(), v.size()},
                     {terminated.mutable_data(), v.size()}, {truncated.mutable_data(), v.size()},
                     spanOf(finals));
            }
            return py::make_tuple(observations, rewards, terminated, truncated, finals);
          },
          py::arg("actions"),
          "One step of every world, GIL released; returns (observations, rewards, terminated, "
          "truncated, final_observations), the last meaningful only in the rows of worlds "
          "whose episode ended (and were reset).")
      .def(
          "render",
          [](const SpherusVectorEnvironment& v, std::size_t i, int width) {
            if (i >= v.size()) throw py::index_error("world index out of range");
            return renderSvg(v.environment(i), width);
          },
          py::arg("index"), py::arg("width") = 600, "World i's arena as an SVG document.")
      .def(
          "step_in_cpp",
          [](SpherusVectorEnvironment& v, py::handle actions, long steps) {
            const auto n = static_cast<py::ssize_t>(v.size());
            const auto checked = checkedArray(actions, {n, actionSize}, "actions");
            std::vector<real> observations(v.size() * observationSize), finals(observations.size());
            std::vector<double> rewards(v.size());
            std::unique_ptr<bool[]> terminated(new bool[v.size()]), truncated(new bool[v.size()]);
            py::gil_scoped_release release;
            for (long s = 0; s < steps; ++s)
              v.step({checked.data(), static_cast<std::size_t>(checked.size())}, observations,
                     rewards, {terminated.get(), v.size()}, {truncated.get(), v.size()}, finals);
          },
          py::arg("actions"), py::arg("steps"),
          "Benchmark baseline: `steps` steps with the same actions, all in C++ (no Python "
          "between steps).");

  m.def(
      "hardware_threads", [] { return std::max(1u, std::thread::hardware_concurrency()); },
      "The processor's hardware threads (at least 1).");
}

}  // namespace thyrix::python
