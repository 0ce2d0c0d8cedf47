#include <GUIWx/WorldSnapshot.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

// worldBounds() leaves borders out (they are unbounded); a walled arena then fits with its
// walls just outside the window. Each border's anchor point (Border::r, where the program put
// it) is taken in too, with a margin, so the walls show.
BoundingBox viewBounds(const World& world) {
  BoundingBox box = worldBounds(world);
  bool anyBorder = false;
  for (const PhysicalObject& object : world.objects)
    for (const Primitive* primitive : object.primitives())
      if (primitive->shapeType() == ShapeType::HalfPlane && std::isfinite(primitive->r.x) &&
          std::isfinite(primitive->r.y)) {
        box.lower = {std::min(box.lower.x, primitive->r.x), std::min(box.lower.y, primitive->r.y)};
        box.upper = {std::max(box.upper.x, primitive->r.x), std::max(box.upper.y, primitive->r.y)};
        anyBorder = true;
      }
  if (anyBorder) {
    const real pad = real(0.02) * std::max(box.upper.x - box.lower.x, box.upper.y - box.lower.y);
    box.lower -= Vector2{pad, pad};
    box.upper += Vector2{pad, pad};
  }
  return box;
}

}  // namespace

void WorldSnapshot::capture(const World& world, const DrawOptions& options) {
  drawing.clear();
  drawWorld(world, drawing, options);

  const auto* simulator = dynamic_cast<const Simulator*>(&world);
  isSimulator = simulator != nullptr;
  shapes.clear();
  std::uint32_t index = 0;
  for (const PhysicalObject& object : world.objects) {
    // Fixed bodies do not move under the mouse force, and only a simulator pulls a grabbed
    // object: neither can be grabbed.
    if (isSimulator && !object.fixed) {
      for (const Primitive* primitive : object.primitives()) {
        const ShapeType type = primitive->shapeType();
        if (type == ShapeType::HalfPlane) continue;
        // The pose from the owner, as worldBounds() does, so it is right before the first step
        // too (parts follow their owner only during a step).
        const PhysicalObject& owner = primitive->owner();
        const Vector2 centre = owner.toWorld(primitive->localPosition());
        const real angle = owner.alpha + primitive->localAngle();
        const Vector2 axis = type == ShapeType::Capsule
                                 ? Vector2{primitive->halfLength(), 0}.rotated(angle)
                                 : Vector2{};
        shapes.push_back({type, centre - axis, centre + axis, primitive->radius(), index});
      }
    }
    ++index;
  }
  bounds = viewBounds(world);
  step = world.stepCount();
  time = world.time();
  contacts = isSimulator ? simulator->contacts.size() : 0;
  if (isSimulator) solver = simulator->contactSolver();
}

void WorldSnapshot::clearWorld() {
  drawing.clear();
  shapes.clear();
  bounds = {Vector2{0, 0}, Vector2{10, 10}};
  step = 0;
  time = 0;
  contacts = 0;
  isSimulator = false;
  sensors.clear();
  effectors.clear();
  dragging = false;
}

}  // namespace thyrix
