#include "ArrayChecks.h"
#include "Bindings.h"

#include <Evolution/Evaluate.h>
#include <Evolution/SeedDerivation.h>
#include <Evolution/ThreadPool.h>
#include <SpherusTask.h>

namespace py = pybind11;

namespace thyrix::python {

namespace {

// thyrix.EpisodeRunner: a generation's population and threads, kept for all its chunks.
class EpisodeRunner {
 public:
  EpisodeRunner(const SpherusTask& task, py::handle genomes, std::size_t trials,
                std::size_t threads, std::uint64_t seed, std::uint64_t generation)
      : task_(task), pool_(checkedThreads(threads)) {
    const auto dimension = static_cast<py::ssize_t>(task.network.parameterCount());
    const auto array = realArray(genomes, "genomes");
    if (array.ndim() != 2 || array.shape(1) != dimension)
      throw py::value_error("genomes must have shape (P, " + std::to_string(dimension) + "), not " +
                            std::string(py::str(py::tuple(array.attr("shape")))));
    if (trials == 0) throw py::value_error("trials must be at least 1 (got 0)");
    requireFinite({array.data(), static_cast<std::size_t>(array.size())}, "genomes");
    population_.resize(static_cast<std::size_t>(array.shape(0)));
    for (std::size_t i = 0; i < population_.size(); ++i) {
      const real* row = array.data() + static_cast<py::ssize_t>(i) * dimension;
      population_[i].assign(row, row + dimension);
    }
    options_.trials = trials;
    options_.seed = seed;
    options_.generation = generation;
  }

  [[nodiscard]] std::size_t episodes() const { return population_.size() * options_.trials; }

  py::array_t<double> run(std::size_t first, std::size_t count) {
    if (first > episodes() || count > episodes() - first)
      throw py::value_error("episodes " + std::to_string(first) + " to " +
                            std::to_string(first + count) + " are not among the " +
                            std::to_string(episodes()));
    py::array_t<double> result(static_cast<py::ssize_t>(count));
    const std::span<double> fitness(result.mutable_data(), count);
    py::gil_scoped_release release;
    evaluateEpisodes(task_, population_, options_, first, fitness, pool_);
    return result;
  }

 private:
  static std::size_t checkedThreads(std::size_t threads) {
    if (threads == 0) throw py::value_error("threads must be at least 1 (got 0)");
    return threads;
  }

  SpherusTask task_;
  std::vector<std::vector<double>> population_;
  EvaluationOptions options_;
  ThreadPool pool_;
};

}  // namespace

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

  py::class_<EpisodeRunner>(
      m, "EpisodeRunner",
      "The episodes of one call of thyrix::evaluate() (episode i * trials + t is trial t of "
      "genome i), run chunk by chunk: the chunks that thyrix.evaluate(..., comm=...) hands to "
      "the ranks of an mpi4py job. The genomes are copied and the threads started once.")
      .def(py::init<const SpherusTask&, py::handle, std::size_t, std::size_t, std::uint64_t,
                    std::uint64_t>(),
           py::arg("task"), py::arg("genomes"), py::arg("trials"), py::arg("threads"),
           py::arg("seed"), py::arg("generation"),
           "The episodes of thyrix::evaluate() of `task` on the rows of `genomes` (a finite "
           "P x parameters array), on `threads` threads.")
      .def_property_readonly("episodes", &EpisodeRunner::episodes, "genomes x trials")
      .def("run", &EpisodeRunner::run, py::arg("first"), py::arg("count"),
           "The fitnesses of episodes first to first + count - 1.");

  m.def("derive_seed", &deriveSeed, py::arg("run_seed"), py::arg("generation"),
        py::arg("individual"), py::arg("trial"),
        "The seed of one episode of evaluate(): a splitmix64 chain of the four numbers.");
}

}  // namespace thyrix::python
