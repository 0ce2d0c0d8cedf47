#include "ArrayChecks.h"
#include "Bindings.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/WorldState.h>

#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <memory>
#include <sstream>
#include <string>

namespace py = pybind11;

namespace thyrix::python {

namespace {

/// An (N, 3) array, row i from `row(objects[i], out)`.
template <class Row>
py::array_t<real> objectRows(const World& world, Row row) {
  const auto count = static_cast<py::ssize_t>(world.objects.size());
  py::array_t<real> result({count, py::ssize_t{3}});
  real* out = result.mutable_data();
  for (const PhysicalObject& object : world.objects) {
    row(object, out);
    out += 3;
  }
  return result;
}

/// Places @p object at @p position and @p angle (checked), fixed or not, then registers it.
template <class T>
T& addObject(Simulator& simulator, std::unique_ptr<T> object, py::handle position, double angle,
             bool fixed, const std::string& what) {
  object->r = toVector2(position, what + ".position");
  object->alpha = finiteReal(angle, what + ".angle");
  object->fixed = fixed;
  return simulator.registerObject(std::move(object));
}

py::dict contactArrays(const Simulator& simulator) {
  const std::size_t count = simulator.contacts.size();
  const auto n = static_cast<py::ssize_t>(count);
  py::array_t<std::uint32_t> bodyA(n), bodyB(n);
  py::array_t<real> point({n, py::ssize_t{2}}), normal({n, py::ssize_t{2}});
  py::array_t<real> depth(n), force(n);
  for (std::size_t i = 0; i < count; ++i) {
    const GlobalContactInfo& contact = simulator.contacts[i];
    const auto k = static_cast<py::ssize_t>(i);
    bodyA.mutable_at(k) = contact.bodyA;
    bodyB.mutable_at(k) = contact.bodyB;
    point.mutable_at(k, 0) = contact.point.x;
    point.mutable_at(k, 1) = contact.point.y;
    normal.mutable_at(k, 0) = contact.normal.x;
    normal.mutable_at(k, 1) = contact.normal.y;
    depth.mutable_at(k) = contact.depth;
    force.mutable_at(k) = contact.force;
  }
  py::dict result;
  result["body_a"] = bodyA;
  result["body_b"] = bodyB;
  result["point"] = point;
  result["normal"] = normal;
  result["depth"] = depth;
  result["force"] = force;
  return result;
}

}  // namespace

namespace {

/// @p state in its binary form (WorldState::write()).
py::bytes stateBytes(const WorldState& state) {
  std::ostringstream out;
  state.write(out);
  return py::bytes(out.str());
}

/// The state written in @p data (WorldState::read()).
WorldState stateFromBytes(const py::bytes& data) {
  std::istringstream in(std::string{data});
  return WorldState::read(in);
}

}  // namespace

void bindWorld(py::module_& m) {
  py::class_<WorldState>(m, "WorldState",
                         "Everything that can change a simulator's next step, as a value "
                         "(Simulator.save_state()). Copyable and picklable: its bytes are its "
                         "versioned, checksummed binary form.")
      .def(py::init(&stateFromBytes), py::arg("data"),
           "The state written in `data` (bytes(state)); raises RuntimeError if it is not "
           "one, truncated or corrupt.")
      .def("__bytes__", &stateBytes, "The versioned, checksummed binary form.")
      .def("hash", &WorldState::hash, "A 64-bit hash of the whole state.")
      .def_property_readonly("make_up", &WorldState::makeUp,
                             "The make-up it was saved from: object types and shapes.")
      .def(py::self == py::self)  // NOLINT(misc-redundant-expression)
      .def("__copy__", [](const WorldState& state) { return WorldState(state); })
      .def(
          "__deepcopy__", [](const WorldState& state, py::dict) { return WorldState(state); },
          py::arg("memo"))
      .def(py::pickle([](const WorldState& state) { return py::make_tuple(stateBytes(state)); },
                      [](const py::tuple& saved) {
                        if (saved.size() != 1) throw py::value_error("not a pickled WorldState");
                        return stateFromBytes(saved[0].cast<py::bytes>());
                      }));

  py::enum_<ContactSolverKind>(m, "ContactSolver", "The contact solver of a Simulator.")
      .value("BARAFF", ContactSolverKind::Baraff, "Baraff's pivoting method: exact")
      .value("GAUSS_SEIDEL", ContactSolverKind::GaussSeidel, "projected Gauss-Seidel: iterative");

  py::class_<ContactSolverSettings>(m, "ContactSolverSettings",
                                    "Tuning of the contact solvers (see ContactSolver.h).")
      .def_readwrite("gauss_seidel_tolerance", &ContactSolverSettings::gaussSeidelTolerance,
                     "Gauss-Seidel stops when no contact velocity changes by more (m/s).")
      .def_readwrite("gauss_seidel_max_iterations",
                     &ContactSolverSettings::gaussSeidelMaxIterations,
                     "Gauss-Seidel's sweeps at most.")
      .def_readwrite("gauss_seidel_height_order", &ContactSolverSettings::gaussSeidelHeightOrder,
                     "Sweep the contacts in order of height against gravity.")
      .def_readwrite("gauss_seidel_max_iterations_in_height_order",
                     &ContactSolverSettings::gaussSeidelMaxIterationsInHeightOrder,
                     "Sweeps at most in height order.")
      .def_readwrite("accelerate_gauss_seidel", &ContactSolverSettings::accelerateGaussSeidel,
                     "Accelerate Gauss-Seidel's convergence.")
      .def_readwrite("warm_start", &ContactSolverSettings::warmStart,
                     "Start from the last step's forces.")
      .def_readwrite("relaxation", &ContactSolverSettings::relaxation,
                     "Gauss-Seidel's relaxation factor.")
      .def_readwrite("baraff_max_island_contacts", &ContactSolverSettings::baraffMaxIslandContacts,
                     "Islands with more contacts go to Gauss-Seidel, counted as oversized.")
      .def_readwrite("penetration_correction", &ContactSolverSettings::penetrationCorrection,
                     "Fraction of an overlap corrected in a step.")
      .def_readwrite("speculative_fraction", &ContactSolverSettings::speculativeFraction,
                     "Speculative contact margin, as a fraction of the radius.")
      .def_readwrite("speculative_travel", &ContactSolverSettings::speculativeTravel,
                     "Speculative margin per unit of the last step's travel.");

  py::class_<PhysicalObject>(m, "PhysicalObject",
                             "A body of a world. It belongs to its world; the Python object is a "
                             "view that keeps the world alive.")
      .def_property(
          "position", [](const PhysicalObject& o) { return fromVector2(o.r); },
          [](PhysicalObject& o, py::handle v) { o.r = toVector2(v, "PhysicalObject.position"); },
          "Centre of mass (x, y), m.")
      .def_property(
          "angle", [](const PhysicalObject& o) { return static_cast<double>(o.alpha); },
          [](PhysicalObject& o, double a) { o.alpha = finiteReal(a, "PhysicalObject.angle"); },
          "Orientation, rad, counter-clockwise.")
      .def_property_readonly(
          "velocity", [](const PhysicalObject& o) { return fromVector2(o.v); },
          "Linear velocity (vx, vy) of the last step, m/s.")
      .def_property_readonly(
          "angular_velocity", [](const PhysicalObject& o) { return static_cast<double>(o.omega); },
          "Angular velocity of the last step, rad/s.")
      .def_property_readonly(
          "mass", [](const PhysicalObject& o) { return static_cast<double>(o.m); },
          "Quasistatic mass: force per unit velocity, N s/m.")
      .def_property_readonly(
          "inertia", [](const PhysicalObject& o) { return static_cast<double>(o.I); },
          "Moment of inertia: torque per unit angular velocity.")
      .def_readwrite("fixed", &PhysicalObject::fixed, "A fixed object never moves.")
      .def_readwrite("collision_group", &PhysicalObject::collisionGroup,
                     "Objects of the same non-zero group do not touch each other.")
      .def_property(
          "external_force", [](const PhysicalObject& o) { return fromVector2(o.externalForce); },
          [](PhysicalObject& o, py::handle v) {
            o.externalForce = toVector2(v, "PhysicalObject.external_force");
          },
          "Force for the next step (N), reset after use.")
      .def_property(
          "external_torque",
          [](const PhysicalObject& o) { return static_cast<double>(o.externalTorque); },
          [](PhysicalObject& o, double t) {
            o.externalTorque = finiteReal(t, "PhysicalObject.external_torque");
          },
          "Torque for the next step (N m), reset after use.")
      .def(
          "apply_force",
          [](PhysicalObject& o, py::handle force, py::handle point) {
            o.applyForce(toVector2(force, "force"), toVector2(point, "point"));
          },
          py::arg("force"), py::arg("point"),
          "Adds a force (N) applied at a world point to the next step's force and torque.")
      .def_property_readonly("type_name", &PhysicalObject::typeName, "The class's name.")
      .def("__repr__", [](const PhysicalObject& o) {
        return "<thyrix." + o.typeName() + " at (" + std::to_string(o.r.x) + ", " +
               std::to_string(o.r.y) + ")>";
      });

  py::class_<Primitive, PhysicalObject>(m, "Primitive", "A circle or a capsule.")
      .def_property_readonly(
          "radius", [](const Primitive& p) { return static_cast<double>(p.radius()); },
          "Radius of the circle, or of the capsule's caps, m.");
  py::class_<Circle, Primitive>(m, "Circle", "A circle (made by Simulator.add_circle).");
  py::class_<CappedRectangle, Primitive>(m, "CappedRectangle",
                                         "A capsule (made by Simulator.add_capped_rectangle).");
  py::class_<Border, PhysicalObject>(m, "Border",
                                     "A fixed half-plane (made by Simulator.add_border).")
      .def_property_readonly(
          "normal", [](const Border& b) { return fromVector2(b.normal()); },
          "Unit normal into the simulation area.");

  py::class_<World>(m, "World", "A process updated in discrete time steps.")
      .def_property("timestep", &World::timestep, &World::setTimestep, "The time step, s.")
      .def_property_readonly("step_count", &World::stepCount, "Steps taken.")
      .def_property_readonly("time", &World::time, "Simulated time, s.")
      .def(
          "advance_time",
          [](World& world, long steps) {
            if (steps < 0)
              throw py::value_error("steps must be >= 0 (got " + std::to_string(steps) + ")");
            for (long i = 0; i < steps; ++i) world.advanceTime();
          },
          py::arg("steps") = 1, "Takes `steps` time steps.")
      .def_property_readonly(
          "objects",
          [](py::object self) {
            py::list list;
            for (PhysicalObject& object : self.cast<const World&>().objects)
              list.append(viewOf(object, self));
            return list;
          },
          "The objects in registration order.")
      .def(
          "poses",
          [](const World& world) {
            return objectRows(world, [](const PhysicalObject& o, real* row) {
              row[0] = o.r.x;
              row[1] = o.r.y;
              row[2] = o.alpha;
            });
          },
          "A copy of every object's pose, shape (N, 3): x, y, angle.")
      .def(
          "set_poses",
          [](World& world, py::handle poses) {
            const auto n = static_cast<py::ssize_t>(world.objects.size());
            const auto array = checkedArray(poses, {n, 3}, "poses");
            const real* row = array.data();
            for (PhysicalObject& o : world.objects) {
              o.r = {row[0], row[1]};
              o.alpha = row[2];
              row += 3;
            }
          },
          py::arg("poses"), "Sets every object's pose from an array of shape (N, 3).")
      .def(
          "velocities",
          [](const World& world) {
            return objectRows(world, [](const PhysicalObject& o, real* row) {
              row[0] = o.v.x;
              row[1] = o.v.y;
              row[2] = o.omega;
            });
          },
          "A copy of every object's velocity in the last step, shape (N, 3): vx, vy, omega.");

  py::class_<Simulator, World>(m, "Simulator",
                               "A world of bodies moved by F = m v, their contacts solved.")
      .def(py::init<real>(), py::arg("timestep") = real(0.01),
           "An empty world stepped `timestep` seconds at a time.")
      .def(
          "add_circle",
          [](Simulator& s, double radius, double mass, py::handle position, double angle,
             bool fixed) -> Circle& {
            return addObject(
                s, std::make_unique<Circle>(static_cast<real>(radius), static_cast<real>(mass)),
                position, angle, fixed, "Circle");
          },
          py::arg("radius"), py::arg("mass"), py::arg("position") = py::make_tuple(0, 0),
          py::arg("angle") = 0.0, py::arg("fixed") = false,
          py::return_value_policy::reference_internal, "Registers a new circle and returns it.")
      .def(
          "add_capped_rectangle",
          [](Simulator& s, double length, double radius, double mass, py::handle position,
             double angle, bool fixed) -> CappedRectangle& {
            return addObject(
                s,
                std::make_unique<CappedRectangle>(
                    static_cast<real>(length), static_cast<real>(radius), static_cast<real>(mass)),
                position, angle, fixed, "CappedRectangle");
          },
          py::arg("length"), py::arg("radius"), py::arg("mass"),
          py::arg("position") = py::make_tuple(0, 0), py::arg("angle") = 0.0,
          py::arg("fixed") = false, py::return_value_policy::reference_internal,
          "Registers a new capsule (a segment of `length` swept by a circle of `radius`).")
      .def(
          "add_border",
          [](Simulator& s, py::handle point, py::handle normal) -> Border& {
            return s.registerObject(std::make_unique<Border>(toVector2(point, "Border.point"),
                                                             toVector2(normal, "Border.normal")));
          },
          py::arg("point"), py::arg("normal"), py::return_value_policy::reference_internal,
          "Registers a fixed half-plane through `point` whose `normal` points into the world.")
      .def_property("contact_solver", &Simulator::contactSolver, &Simulator::setContactSolver,
                    "The contact solver.")
      .def_property_readonly(
          "solver_settings",
          [](Simulator& s) -> ContactSolverSettings& { return s.solverSettings(); },
          py::return_value_policy::reference_internal, "The solvers' tuning, to read and change.")
      .def_property(
          "gravity", [](const Simulator& s) { return fromVector2(s.gravity()); },
          [](Simulator& s, py::handle g) { s.setGravity(toVector2(g, "Simulator.gravity")); },
          "Gravity (m/s^2); (0, 0) by default.")
      .def_readwrite("rest_skipping", &Simulator::restSkipping,
                     "Leave bodies at rest out of the step (same results, faster).")
      .def_readwrite("reference_mode", &Simulator::referenceMode,
                     "Every cache and shortcut off: the plain algorithm, bit-identical results, "
                     "much slower (the tests' oracle).")
      .def("save_state", &Simulator::saveState,
           "Everything that can change the next step, as a WorldState.")
      .def("restore_state", &Simulator::restoreState, py::arg("state"),
           "Puts the world in `state`, saved from this world or one built the same way; "
           "raises ValueError saying what differs otherwise (the world is then unchanged).")
      .def("contacts", &contactArrays,
           "The last step's contacts as a dict of arrays: body_a, body_b (object indices), "
           "point (K, 2), normal (K, 2, from a to b), depth (K,), force (K,).");
}

}  // namespace thyrix::python
