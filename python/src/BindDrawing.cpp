#include "ArrayChecks.h"
#include "Bindings.h"

#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

namespace py = pybind11;

namespace thyrix::python {

void bindDrawing(py::module_& m) {
  m.def(
      "draw_svg",
      [](const World& world, py::handle lower, py::handle upper, int width, bool contacts,
         bool contactForces, bool tactile, bool visualRays) {
        Vector2 low, high;
        if (lower.is_none() || upper.is_none()) {
          const BoundingBox box = worldBounds(world);
          low = box.lower;
          high = box.upper;
        }
        if (!lower.is_none()) low = toVector2(lower, "lower");
        if (!upper.is_none()) high = toVector2(upper, "upper");
        SvgGUI svg(low, high, width);
        DrawOptions options;
        options.contacts = contacts;
        options.contactForces = contactForces;
        options.tactile = tactile;
        options.visualRays = visualRays;
        drawWorld(world, svg, options);
        return svg.svg();
      },
      py::arg("world"), py::arg("lower") = py::none(), py::arg("upper") = py::none(),
      py::arg("width") = 600, py::arg("contacts") = false, py::arg("contact_forces") = false,
      py::arg("tactile") = false, py::arg("visual_rays") = false,
      "The world as an SVG document (a string; no display needed): the rectangle [lower, "
      "upper] (default: around every object), `width` pixels wide, with the overlays asked "
      "for.");
}

}  // namespace thyrix::python
