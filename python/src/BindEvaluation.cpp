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

  m.def("derive_seed", &deriveSeed, py::arg("run_seed"), py::arg("generation"),
        py::arg("individual"), py::arg("trial"),
        "The seed of one episode of evaluate(): a splitmix64 chain of the four numbers.");
}

}  // namespace thyrix::python
