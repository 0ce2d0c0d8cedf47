#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/GlobalContactInfo.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/VisualSensor.h>
#include <ThyrixLite/WorldDrawing.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

// Contact marks scale with the shapes they sit on, so they read the same in a world of
// millimetres or of kilometres: a fraction of the smaller touching radius (borders have none).
real contactMarkSize(const GlobalContactInfo& contact) {
  real radius = realMax;
  for (const Primitive* primitive : {contact.primitiveA, contact.primitiveB})
    if (primitive != nullptr && primitive->radius() > 0)
      radius = std::min(radius, primitive->radius());
  return radius < realMax ? real(0.3) * radius : real(0.05);
}

void drawContact(const GlobalContactInfo& contact, GUI& gui, const DrawOptions& options) {
  const real size = contactMarkSize(contact);
  const Vector2 p = contact.point;
  if (options.contactForces && contact.force > 0)
    gui.drawLine(p, p + contact.normal * (contact.force * options.forceScale), colors::contactForce,
                 real(0.4) * size);
  if (options.contacts) {
    gui.drawLine(p + Vector2{-size, -size}, p + Vector2{size, size}, colors::contact);
    gui.drawLine(p + Vector2{-size, size}, p + Vector2{size, -size}, colors::contact);
    gui.drawLine(p, p + contact.normal * (3 * size), colors::contact);
  }
}

// Sensor overlays, drawn over the objects and contacts: tactile sectors (DrawOptions::tactile)
// and visual rays (DrawOptions::visualRays) of the objects that carry such sensors. No object
// of the core exposes sensors in this version, so no object has an overlay to draw.
/// A colour from white (0) to @p full (1).
Color shade(Color full, real activation) {
  const auto mix = [activation](std::uint8_t channel) {
    return static_cast<std::uint8_t>(255 -
                                     (255 - channel) * std::clamp(activation, real(0), real(1)));
  };
  return {mix(full.red), mix(full.green), mix(full.blue), 255};
}

void drawTactile(const Primitive& primitive, GUI& gui) {
  const TactileSensors& sensors = primitive.tactileSensors();
  const auto activations = sensors.activations();
  const real dot = primitive.radius() * real(0.15);
  for (int k = 0; k < static_cast<int>(activations.size()); ++k) {
    const Vector2 local = primitive.shapeType() == ShapeType::Circle
                              ? sensors.circleSectorMiddle(k, primitive.radius() - dot)
                              : sensors.cappedRectangleSectorMiddle(k, primitive.halfLength(),
                                                                    primitive.radius() - dot);
    gui.drawCircle(primitive.toWorld(local), dot, 0, shade(colors::red, activations[k]),
                   colors::darkGray);
  }
}

void drawRays(const VisualSensor& eye, GUI& gui) {
  // Each pixel's central ray, 1 m long, darker the more the pixel is covered.
  const Vector2 from = eye.eyePosition();
  for (int i = 0; i < eye.pixelCount(); ++i) {
    const auto [begin, end] = eye.pixelBounds(i);
    const real angle = (begin + end) / 2;
    const Vector2 to = from + Vector2{std::cos(angle), std::sin(angle)};
    gui.drawLine(from, to, shade(colors::cyan, real(0.25) + real(0.75) * eye.activations()[i]));
  }
}

void drawSensorOverlays(const World& world, GUI& gui, const DrawOptions& options) {
  for (const PhysicalObject& object : world.objects) {
    if (options.tactile)
      for (const Primitive* primitive : object.primitives())
        if (primitive->tactileSensors().enabled()) drawTactile(*primitive, gui);
    if (options.visualRays)
      for (const VisualSensor& eye : object.visualSensors()) drawRays(eye, gui);
  }
}

}  // namespace

void drawWorld(const World& world, GUI& gui, const DrawOptions& options) {
  world.draw(gui);
  if (options.contacts || options.contactForces)
    if (const auto* simulator = dynamic_cast<const Simulator*>(&world))
      for (const GlobalContactInfo& contact : simulator->contacts)
        drawContact(contact, gui, options);
  if (options.tactile || options.visualRays) drawSensorOverlays(world, gui, options);
}

BoundingBox worldBounds(const World& world) {
  Vector2 lower{realMax, realMax};
  Vector2 upper{-realMax, -realMax};
  bool any = false;
  for (const PhysicalObject& object : world.objects) {
    for (const Primitive* primitive : object.primitives()) {
      const ShapeType type = primitive->shapeType();
      if (type == ShapeType::HalfPlane) continue;
      // The pose from the owner, as Primitive::followOwner sets it at each step; for a
      // standalone primitive (its own owner, at local position zero) this is its r and alpha.
      const PhysicalObject& owner = primitive->owner();
      const bool followsOwner = primitive->rigidlyAttached();
      const Vector2 centre =
          followsOwner ? owner.toWorld(primitive->localPosition()) : primitive->r;
      const real angle = followsOwner ? owner.alpha + primitive->localAngle() : primitive->alpha;
      const Vector2 axis = type == ShapeType::Capsule
                               ? Vector2{primitive->halfLength(), 0}.rotated(angle)
                               : Vector2{};
      const Vector2 reach = Vector2{std::abs(axis.x), std::abs(axis.y)} +
                            Vector2{primitive->radius(), primitive->radius()};
      const Vector2 low = centre - reach;
      const Vector2 high = centre + reach;
      if (!std::isfinite(low.x) || !std::isfinite(low.y) || !std::isfinite(high.x) ||
          !std::isfinite(high.y))
        continue;
      lower = {std::min(lower.x, low.x), std::min(lower.y, low.y)};
      upper = {std::max(upper.x, high.x), std::max(upper.y, high.y)};
      any = true;
    }
  }
  if (!any) return {Vector2{0, 0}, Vector2{10, 10}};
  const real pad = real(0.05) * std::max(upper.x - lower.x, upper.y - lower.y);
  return {lower - Vector2{pad, pad}, upper + Vector2{pad, pad}};
}

}  // namespace thyrix
