#include "ArrayChecks.h"
#include "Bindings.h"

#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/VisualSensor.h>
#include <ThyrixLite/World.h>

namespace py = pybind11;

namespace thyrix::python {

void bindSensors(py::module_& m) {
  addProperty(
      m.attr("Primitive"), "tactile_activations",
      [](const Primitive& p) { return copyOf(p.tactileActivations()); },
      "A copy of the tactile sensors' activations of the last step, each in [0, 1] (empty "
      "without sensors).");

  addMethod(
      m.attr("Circle"), "set_tactile_sensors",
      [](Circle& c, int count, double startAngle, double saturation) {
        c.setTactileSensors(count, finiteReal(startAngle, "start_angle"),
                            static_cast<real>(saturation));
      },
      py::arg("count"), py::arg("start_angle") = 0.0, py::arg("saturation") = 1.0,
      "Puts `count` touch sensors around the circle, sensor 0 from body angle `start_angle`; "
      "a sensor saturates at a summed contact force of `saturation` (N).");

  addMethod(
      m.attr("CappedRectangle"), "set_tactile_sensors",
      [](CappedRectangle& c, int perSide, int perCap, double saturation) {
        c.setTactileSensors(perSide, perCap, static_cast<real>(saturation));
      },
      py::arg("per_side"), py::arg("per_cap"), py::arg("saturation") = 1.0,
      "Touch sensors along each side and around each cap.");

  addProperty(
      m.attr("PhysicalObject"), "visual_sensors",
      [](py::object self) {
        py::list list;
        for (const VisualSensor& eye : self.cast<const PhysicalObject&>().visualSensors())
          list.append(viewOf(eye, self));
        return list;
      },
      "The object's own eyes (an agent's), as VisualSensor views.");

  py::class_<VisualSensor>(m, "VisualSensor",
                           "An eye on a body: a row of pixels, each activated by the fraction "
                           "of its angle that circles and capsules cover (infinite range).")
      .def(py::init([](const PhysicalObject& body, py::handle position, double direction,
                       int pixels, double pixelAngle) {
             return VisualSensor(body, toVector2(position, "VisualSensor.local_position"),
                                 static_cast<real>(direction), pixels,
                                 static_cast<real>(pixelAngle));
           }),
           py::arg("body"), py::arg("local_position"), py::arg("local_direction"),
           py::arg("pixel_count"), py::arg("pixel_angle"), py::keep_alive<1, 2>(),
           "An eye on `body` at `local_position`, looking along `local_direction` (body frame, "
           "rad), with `pixel_count` pixels of `pixel_angle` rad each.")
      .def(
          "update", [](VisualSensor& eye, const World& world) { eye.update(world.objects); },
          py::arg("world"), "Recomputes the pixels from the objects of `world`.")
      .def_property_readonly(
          "activations", [](const VisualSensor& eye) { return copyOf(eye.activations()); },
          "A copy of the pixels' activations, each in [0, 1].")
      .def_property_readonly("pixel_count", &VisualSensor::pixelCount, "Pixels.")
      .def_property_readonly(
          "field_of_view",
          [](const VisualSensor& eye) { return static_cast<double>(eye.fieldOfView()); },
          "Angle covered by the pixels, rad.");
}

}  // namespace thyrix::python
