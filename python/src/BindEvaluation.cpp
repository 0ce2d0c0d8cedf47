#include "ArrayChecks.h"
#include "Bindings.h"

#include <Evolution/Evaluate.h>
#include <Evolution/SeedDerivation.h>
#include <SpherusTask.h>

namespace py = pybind11;

namespace thyrix::python {

void bindEvaluation(py::module_& m) {
  m.def(
      "evaluate_task",
      [](const SpherusTask& task, py::handle genomes, std::size_t trials, std::size_t threads,
         std::uint64_t seed, std::uint64_t generation) {
        const auto dimension = static_cast<py::ssize_t>(task.network.parameterCount());
        const auto array = realArray(genomes, "genomes");
        if (array.ndim() != 2 || array.shape(1) != dimension)
          throw py::value_error("genomes must have shape (P, " + std::to_string(dimension) +
                                ") for the network " + std::to_string(task.network.layers.front()) +
                                "-...-" + std::to_string(task.network.layers.back()) + ", not " +
                                std::string(py::str(py::tuple(array.attr("shape")))));
        requireFinite({array.data(), static_cast<std::size_t>(array.size())}, "genomes");
        std::vector<std::vector<double>> population(static_cast<std::size_t>(array.shape(0)));
        for (std::size_t i = 0; i < population.size(); ++i) {
          const real* row = array.data() + static_cast<py::ssize_t>(i) * dimension;
          population[i].assign(row, row + dimension);
        }
        EvaluationOptions options;
        options.trials = trials;
        options.threads = threads;
        options.seed = seed;
        options.generation = generation;
        std::vector<double> fitness;
        {
          py::gil_scoped_release release;
          fitness = evaluate(task, population, options);
        }
        py::array_t<double> result(static_cast<py::ssize_t>(fitness.size()));
        std::copy(fitness.begin(), fitness.end(), result.mutable_data());
        return result;
      },
      py::arg("task"), py::arg("genomes"), py::arg("trials"), py::arg("threads"), py::arg("seed"),
      py::arg("generation"),
      "thyrix::evaluate() of `task` on each row of `genomes` (use thyrix.evaluate).");

  m.def(
      "evaluate_episodes",
      [](const SpherusTask& task, py::handle genomes, std::size_t trials, std::size_t threads,
         std::uint64_t seed, std::uint64_t generation, std::size_t first, std::size_t count) {
        const auto dimension = static_cast<py::ssize_t>(task.network.parameterCount());
        const auto array = realArray(genomes, "genomes");
        if (array.ndim() != 2 || array.shape(1) != dimension)
          throw py::value_error("genomes must have shape (P, " + std::to_string(dimension) +
                                "), not " + std::string(py::str(py::tuple(array.attr("shape")))));
        if (trials == 0) throw py::value_error("trials must be at least 1 (got 0)");
        if (threads == 0) throw py::value_error("threads must be at least 1 (got 0)");
        const auto episodes = static_cast<std::size_t>(array.shape(0)) * trials;
        if (first > episodes || count > episodes - first)
          throw py::value_error("episodes " + std::to_string(first) + " to " +
                                std::to_string(first + count) + " are not among the " +
                                std::to_string(episodes));
        requireFinite({array.data(), static_cast<std::size_t>(array.size())}, "genomes");
        std::vector<std::vector<double>> population(static_cast<std::size_t>(array.shape(0)));
        for (std::size_t i = 0; i < population.size(); ++i) {
          const real* row = array.data() + static_cast<py::ssize_t>(i) * dimension;
          population[i].assign(row, row + dimension);
        }
        EvaluationOptions options;
        options.trials = trials;
        options.seed = seed;
        options.generation = generation;
        py::array_t<double> result(static_cast<py::ssize_t>(count));
        const std::span<double> fitness(result.mutable_data(), count);
        {
          py::gil_scoped_release release;
          ThreadPool pool(threads);
          evaluateEpisodes(task, population, options, first, fitness, pool);
        }
        return result;
      },
      py::arg("task"), py::arg("genomes"), py::arg("trials"), py::arg("threads"), py::arg("seed"),
      py::arg("generation"), py::arg("first"), py::arg("count"),
      "The fitnesses of episodes first to first + count - 1 of thyrix::evaluate() (episode "
      "i * trials + t is trial t of genome i): the chunks that thyrix.evaluate(..., comm=...) "
      "hands to the ranks of an mpi4py job.");

  m.def("derive_seed", &deriveSeed, py::arg("run_seed"), py::arg("generation"),
        py::arg("individual"), py::arg("trial"),
        "The seed of one episode of evaluate(): a splitmix64 chain of the four numbers.");
}

}  // namespace thyrix::python
