/// @file SimulatorContainment.cpp
/// @brief What keeps shapes inside the borders whatever the mass ratios: phase 6's check that
/// the solved motion stays within the walls detection saw (with the detection again, with
/// margins that cover the motion, when it does not), and Gauss-Seidel's error kept off walls.
#include <ThyrixLite/Integrator.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

// How far a point of a body moves in @p dt at the body's velocity @p v, @p omega, @p arm from
// its centre, bounded from above (|dx| + |dy|: no square root).
real travelBound(Vector2 v, real omega, Vector2 arm, real dt) {
  const Vector2 velocity = v + arm.perpendicular() * omega;
  return (std::abs(velocity.x) + std::abs(velocity.y)) * dt;
}

// How far a point of @p object (its box holds them and its centre of mass) moves in @p dt at
// @p v, @p omega, bounded from above.
real freeTravel(const PhysicalObject& object, Vector2 v, real omega, real dt) {
  const Vector2 size = object.boxMax - object.boxMin;
  return (std::abs(v.x) + std::abs(v.y) + std::abs(omega) * (size.x + size.y)) * dt;
}

}  // namespace

bool Simulator::outranMargins(std::span<const std::uint32_t> moved) const {
  const real dt = solveStep();
  // Every shape's reach is at least the margin of the smallest radius: a body none of whose
  // points moves farther (judged from its box, which its centre of mass is in) needs no more.
  const real leastReach = settings_.speculativeFraction * smallestRadius_;
  for (const std::uint32_t i : moved) {
    const SolverBody& body = bodies_[i];
    if (freeTravel(objects[i], body.v, body.omega, dt) > leastReach &&
        endsOutranMargins(i, body.v, body.omega))
      return true;
  }
  // A body no row touched moves at its free velocity, which the last step's travel does not
  // bound either: a push that a contact held back last step moves the body as soon as the
  // contact is out of reach (a light body lifted off a wall, then pushed back onto it).
  const auto freeOutran = [&](std::uint32_t i) {
    const PhysicalObject& object = objects[i];
    return touchedStamp_[i] != stamp_ && !object.fixed &&
           endsOutranMargins(i, object.v, object.omega);
  };
  for (const std::uint32_t i : freeRunners_)
    if (freeOutran(i)) return true;
  // The others move at the field (or not at all): all are checked only if it outruns the least
  // reach in the step.
  if ((std::abs(gravity_.x) + std::abs(gravity_.y)) * dt > leastReach) {
    for (std::uint32_t i = 0; i < objects.size(); ++i)
      if (bodyStates_[i].shapeCount != 0 && freeOutran(i)) return true;
  }
  return false;
}

void Simulator::noteFreeMotion(const PhysicalObject& object) {
  // (The whole step's length: a substep is no longer.)
  if (freeTravel(object, object.v, object.omega, timestep()) >
      settings_.speculativeFraction * smallestRadius_)
    freeRunners_.push_back(object.index_);
}

bool Simulator::endsOutranMargins(std::uint32_t body, Vector2 v, real omega) const {
  // Detection made a contact for every end of a shape within its margin plus travel of a
  // border: an end that moves less cannot cross a border unseen (the common case, one test per
  // end). One that moves more is checked against each border.
  const real dt = solveStep();
  const Vector2 r = objects[body].r;
  const BodyState& state = bodyStates_[body];
  for (std::uint32_t s = state.firstShape; s < state.firstShape + state.shapeCount; ++s) {
    const ShapeGeometry& g = geometry_[s];
    const real reach = g.travel + g.margin;
    // (A circle's axis is its centre twice: one end.)
    const int ends = shapes_[s].type == ShapeType::Circle ? 1 : 2;
    for (int e = 0; e < ends; ++e) {
      const Vector2 end = e == 0 ? g.p0 : g.p1;
      if (travelBound(v, omega, end - r, dt) <= reach) continue;
      const Vector2 displacement = (v + (end - r).perpendicular() * omega) * dt;
      if (crossesUnseenBorder(s, end, displacement, reach)) return true;
    }
  }
  return false;
}

bool Simulator::crossesUnseenBorder(std::uint32_t shape, Vector2 end, Vector2 displacement,
                                    real reach) const {
  const Shape& moving = shapes_[shape];
  const real radius = geometry_[shape].radius;
  for (const std::uint32_t border : borderShapes_) {
    const Shape& wall = shapes_[border];
    if (wall.body == moving.body || (wall.group != 0 && wall.group == moving.group)) continue;
    const ShapeGeometry& line = geometry_[border];  // point p0, normal p1
    const real gap = dot(end - line.p0, line.p1) - radius;
    // (At or beyond the reach, as the narrow phase judges it: no contact for this end.)
    if (gap >= reach && gap + dot(displacement, line.p1) < 0) return true;
  }
  return false;
}

void Simulator::widenMargins() {
  // Every movable body's shapes get a margin of four times what they move this step (the
  // solve's velocities where it ran, else the free ones), so that the next solve, which may
  // move them faster, still sees every border they can reach. (Travel is 0 in a detection at
  // the same poses: the margin alone must cover the motion.)
  const real dt = solveStep();
  for (std::uint32_t i = 0; i < objects.size(); ++i) {
    const PhysicalObject& object = objects[i];
    if (object.fixed) continue;
    const bool solved = touchedStamp_[i] == stamp_;
    const Vector2 v = solved ? bodies_[i].v : object.v;
    const real omega = solved ? bodies_[i].omega : object.omega;
    const BodyState& state = bodyStates_[i];
    for (std::uint32_t s = state.firstShape; s < state.firstShape + state.shapeCount; ++s) {
      ShapeGeometry& g = geometry_[s];
      const real travel = std::max(travelBound(v, omega, g.p0 - object.r, dt),
                                   travelBound(v, omega, g.p1 - object.r, dt));
      g.margin = std::max(settings_.speculativeFraction * g.radius, 4 * travel);
    }
  }
}

void Simulator::redetect() {
  widenMargins();
  eraseContacts();
  marginsWidened_ = false;  // (the margins just set are this detection's)
  widening_ = true;         // every shape's geometry again, with the margins just set
  detectContacts();
  widening_ = false;
  marginsWidened_ = true;  // the next detection sets them back
}

void Simulator::holdWalls(std::span<const std::uint32_t> island) {
  // Gauss-Seidel stopped at its cap leaves an error in the rows; where a light body carries a
  // load between heavy ones it can be many times the body's size per step. Between movable
  // bodies such an error is an overlap that the next steps push apart, but against an
  // immovable body it carries the shape through a wall. So a body whose wall contact is left
  // violated by more than its margin in the step gets its wall rows solved alone, the walls
  // as the last word: the error stays between bodies.
  const real dt = solveStep();
  const std::size_t contactCount = contacts.size();
  for (const std::uint32_t k : island) {
    if (k >= contactCount) continue;
    const ContactConstraint& row = rows_[k];
    const bool wallA = immovable(bodies_[row.a]);
    if (wallA == immovable(bodies_[row.b])) continue;
    const GlobalContactInfo& c = contacts.items_[rowsFiltered_ ? activeRows_[k] : k];
    const real margin =
        settings_.speculativeFraction * geometry_[wallA ? c.shapeB : c.shapeA].radius;
    const real violation = row.target - row.normalVelocity(bodies_[row.a], bodies_[row.b]);
    if (violation * dt > margin) holdAtWalls(island, wallA ? row.b : row.a);
  }
}

void Simulator::holdAtWalls(std::span<const std::uint32_t> island, std::uint32_t body) {
  // Projected Gauss-Seidel on this body's rows against immovable bodies only: they move this
  // body alone, a small problem that converges in a few sweeps.
  constexpr int maxSweeps = 100;
  for (int sweep = 0; sweep < maxSweeps; ++sweep) {
    real largest = 0;
    for (const std::uint32_t k : island) {
      ContactConstraint& row = rows_[k];
      SolverBody& a = bodies_[row.a];
      SolverBody& b = bodies_[row.b];
      const bool wallRow = (row.a == body && immovable(b)) || (row.b == body && immovable(a));
      if (!wallRow || k >= contacts.size()) continue;
      const real response = row.selfResponse(a, b);
      const real force =
          std::max(real(0), row.force - (row.normalVelocity(a, b) - row.target) / response);
      const real change = force - row.force;
      row.force = force;
      row.applyImpulse(change, a, b);
      largest = std::max(largest, std::abs(change) * response);
    }
    if (largest <= settings_.gaussSeidelTolerance) return;
  }
}

std::uint32_t Simulator::partsNeeded(std::span<const std::uint32_t> moved) const {
  // A contact is linear in the motion: the arc of a turning shape's end, or a body that a
  // Gauss-Seidel error throws across its neighbours, departs from it by more than the margins
  // once a point moves about its radius. Such a step is divided so that each part moves every
  // point by at most half its radius.
  const real dt = solveStep();
  std::uint32_t parts = 1;
  for (const std::uint32_t i : moved) {
    const SolverBody& body = bodies_[i];
    const PhysicalObject& object = objects[i];
    const Vector2 size = object.boxMax - object.boxMin;
    if ((std::abs(body.v.x) + std::abs(body.v.y) + std::abs(body.omega) * (size.x + size.y)) * dt <=
        smallestRadius_)
      continue;
    const BodyState& state = bodyStates_[i];
    for (std::uint32_t s = state.firstShape; s < state.firstShape + state.shapeCount; ++s) {
      const ShapeGeometry& g = geometry_[s];
      const real travel = std::max(travelBound(body.v, body.omega, g.p0 - object.r, dt),
                                   travelBound(body.v, body.omega, g.p1 - object.r, dt));
      if (!(travel > g.radius)) continue;
      const real wanted = std::ceil(2 * travel / g.radius);
      parts = std::max(
          parts, wanted < real(maxSubsteps) ? static_cast<std::uint32_t>(wanted) : maxSubsteps);
    }
  }
  return parts;
}

void Simulator::stepInParts() {
  // Under F = m v the free velocities hold for the whole step: each substep starts from them,
  // detects at its poses and solves for its length.
  if (stepStarts_.size() < objects.size()) stepStarts_.resize(objects.size());
  for (std::uint32_t i = 0; i < objects.size(); ++i) {
    const PhysicalObject& object = objects[i];
    stepStarts_[i] = {object.r, object.alpha, object.v, object.omega};
  }
  std::uint32_t total = parts_;
  std::uint32_t left = parts_;
  real time = timestep();
  while (left > 0) {
    substep_ = time / static_cast<real>(left);
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
      objects[i].v = stepStarts_[i].v;
      objects[i].omega = stepStarts_[i].omega;
    }
    eraseContacts();
    detectContacts();
    parts_ = 1;
    mayDivide_ = 2 * total <= maxSubsteps;
    solveContacts();
    mayDivide_ = false;
    if (parts_ > 1) {
      const std::uint32_t more = std::min(parts_, maxSubsteps / total);
      total *= more;
      left *= more;
      continue;
    }
    if (referenceMode)
      integrator_->integrate(*this, substep_);
    else
      Integrator::integrateExcept(objects, customObjects_, substep_);
    time -= substep_;
    --left;
  }
  // The velocities the step ends with are those that moved each body over the whole step (the
  // last substep's say little about the step, and can be many times faster).
  const real dt = timestep();
  for (std::uint32_t i = 0; i < objects.size(); ++i) {
    PhysicalObject& object = objects[i];
    if (object.fixed) continue;
    object.v = (object.r - stepStarts_[i].r) / dt;
    object.omega = (object.alpha - stepStarts_[i].alpha) / dt;
  }
  parts_ = 1;
  substep_ = 0;
  statistics_.substeps = total;
}

}  // namespace thyrix
