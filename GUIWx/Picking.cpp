#include <GUIWx/Picking.h>

#include <algorithm>

namespace thyrix {

real distanceToShape(const PickShape& shape, Vector2 point) {
  // A circle is a capsule whose segment is a point: the distance to the segment a-b, less the
  // radius, covers both.
  const Vector2 ab = shape.b - shape.a;
  const real lengthSquared = ab.lengthSquared();
  real t = 0;
  if (lengthSquared > 0) t = std::clamp(dot(point - shape.a, ab) / lengthSquared, real(0), real(1));
  return distance(point, shape.a + ab * t) - shape.radius;
}

std::optional<std::uint32_t> pickObject(std::span<const PickShape> shapes, Vector2 point,
                                        real tolerance) {
  std::optional<std::uint32_t> nearest;
  real nearestDistance = tolerance;
  // Backwards: the last shape drawn is on top, so it wins among those containing the point.
  for (std::size_t i = shapes.size(); i-- > 0;) {
    const PickShape& shape = shapes[i];
    const real d = distanceToShape(shape, point);
    if (d <= 0) return shape.object;
    if (d <= nearestDistance) {
      nearestDistance = d;
      nearest = shape.object;
    }
  }
  return nearest;
}

}  // namespace thyrix
