#include "ArrayChecks.h"
#include "Bindings.h"
#include "PythonController.h"

#include <Controller/Genome.h>
#include <Controller/NeuralController.h>
#include <SpherusTask.h>

#include <pybind11/stl.h>

#include <fstream>
#include <sstream>

namespace py = pybind11;

namespace thyrix::python {

namespace {

/// The parameters from a Python value, checked against @p count.
std::vector<real> parameterVector(py::handle value, std::size_t count, const std::string& name) {
  const auto array = checkedArray(value, {static_cast<py::ssize_t>(count)}, name);
  return {array.data(), array.data() + count};
}

}  // namespace

void bindControllers(py::module_& m) {
  py::enum_<NetworkKind>(m, "NetworkKind", "The kind of a neural network.")
      .value("FEED_FORWARD", NetworkKind::FeedForward, "layers fed one by the next; no state")
      .value("CTRNN", NetworkKind::Ctrnn, "a continuous-time recurrent network (Beer 1995)");
  py::enum_<Activation>(m, "Activation", "The units' function.")
      .value("TANH", Activation::Tanh, "tanh; an output is mapped to (0, 1) as (1 + tanh) / 2")
      .value("LOGISTIC", Activation::Logistic, "1 / (1 + exp(-x))");

  py::class_<NetworkSpec>(m, "NetworkSpec", "The shape of a neural controller's network.")
      .def(py::init([](NetworkKind kind, std::vector<std::size_t> layers, Activation activation) {
             NetworkSpec spec{kind, std::move(layers), activation};
             spec.validate();
             return spec;
           }),
           py::arg("kind") = NetworkKind::FeedForward, py::arg("layers"),
           py::arg("activation") = Activation::Tanh,
           "layers: feed-forward: inputs, hidden..., outputs; CTRNN: inputs, neurons, outputs.")
      .def_readonly("kind", &NetworkSpec::kind, "Feed-forward or recurrent.")
      .def_readonly("layers", &NetworkSpec::layers, "The layer sizes.")
      .def_readonly("activation", &NetworkSpec::activation, "The units' function.")
      .def_property_readonly("parameter_count", &NetworkSpec::parameterCount,
                             "Parameters of a network of this shape.")
      .def_property_readonly("input_count", &NetworkSpec::inputCount, "Inputs.")
      .def_property_readonly("output_count", &NetworkSpec::outputCount, "Outputs.")
      .def("__eq__", [](const NetworkSpec& a, const NetworkSpec& b) { return a == b; })
      .def("__repr__", [](const NetworkSpec& s) {
        std::string text = "NetworkSpec(" + std::string(toString(s.kind)) + ", [";
        for (std::size_t i = 0; i < s.layers.size(); ++i)
          text += (i ? ", " : "") + std::to_string(s.layers[i]);
        return text + "], " + std::string(toString(s.activation)) + ")";
      });

  m.def("spherus_network", &parseSpherusNetwork, py::arg("text"),
        "A network for Spherus's 35 sensors and 5 effectors from 'ff', 'ff:H1[,H2...]' (hidden "
        "layers) or 'ctrnn:N' (N neurons), with tanh units.");

  py::class_<Controller>(m, "Controller", "Maps sensor activations to effector activations.");

  py::class_<NeuralController, Controller>(
      m, "NeuralController",
      "A feed-forward or CTRNN network whose parameters are one flat vector; outputs in [0, 1].")
      .def(py::init<NetworkSpec, real>(), py::arg("spec"), py::arg("timestep") = real(0.01),
           "A network of shape `spec` with all parameters 0; `timestep` (s) steps a CTRNN.")
      .def_property_readonly("spec", &NeuralController::spec, "The network's shape.")
      .def_property_readonly("parameter_count", &NeuralController::parameterCount,
                             "Length of the parameter vector.")
      .def_property(
          "parameters", [](const NeuralController& c) { return copyOf(c.parameters()); },
          [](NeuralController& c, py::handle values) {
            c.setParameters(parameterVector(values, c.parameterCount(), "parameters"));
          },
          "A copy of the parameters; assign an array of parameter_count finite numbers.")
      .def(
          "control",
          [](NeuralController& c, py::handle sensors) {
            const auto in =
                checkedArray(sensors, {static_cast<py::ssize_t>(c.spec().inputCount())}, "sensors");
            py::array_t<real> out(static_cast<py::ssize_t>(c.spec().outputCount()));
            c.control({in.data(), static_cast<std::size_t>(in.size())},
                      {out.mutable_data(), static_cast<std::size_t>(out.size())});
            return out;
          },
          py::arg("sensors"), "One step of the network: the effectors for `sensors`.")
      .def("reset", &NeuralController::reset, "Back to the initial state.");

  py::class_<Genome>(m, "Genome", "A network's shape and parameters, saved as a text file.")
      .def(py::init([](const NetworkSpec& spec, py::handle parameters) {
             spec.validate();
             return Genome{spec, parameterVector(parameters, spec.parameterCount(), "parameters")};
           }),
           py::arg("spec"), py::arg("parameters"),
           "A genome of `spec` with `parameters` (spec.parameter_count finite numbers).")
      .def_readonly("spec", &Genome::spec, "The network the parameters are for.")
      .def_property_readonly(
          "parameters", [](const Genome& g) { return copyOf(g.parameters); },
          "A copy of the parameters.")
      .def(
          "to_text",
          [](const Genome& g) {
            std::ostringstream out;
            g.write(out);
            return out.str();
          },
          "The versioned text form (exact hexadecimal floats).")
      .def_static(
          "from_text",
          [](const std::string& text) {
            std::istringstream in(text);
            return Genome::read(in);
          },
          py::arg("text"), "Reads the text form; RuntimeError says what is wrong.")
      .def(
          "save",
          [](const Genome& g, const std::string& path) {
            std::ofstream out(path);
            g.write(out);
            out.close();
            if (!out) throw std::runtime_error("cannot write the genome to '" + path + "'");
          },
          py::arg("path"), "Writes the text form to a file.")
      .def_static("load", &Genome::load, py::arg("path"), "Reads a genome file.")
      .def("make_controller", &Genome::makeController, py::arg("timestep") = real(0.01),
           "A NeuralController with these parameters.");

  py::class_<PythonController, Controller>(m, "PythonController",
                                           "A Python callable driving an agent (made from a "
                                           "callable passed as controller=).")
      .def_property_readonly("function", &PythonController::function, "The callable.");
}

}  // namespace thyrix::python
