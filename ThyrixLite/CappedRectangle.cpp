#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>
#include <Tools/MathTools.h>

namespace thyrix {
namespace {
real checked(real value, const char* field) {
  requirePositive(value, field);
  return value;
}
real invertible(real value, const char* field) {
  requireInvertible(value, field);
  return value;
}
}  // namespace

CappedRectangle::CappedRectangle(real l, real R, real mass)
    : Primitive(ShapeType::Capsule, checked(R, "CappedRectangle.R"),
                checked(l, "CappedRectangle.l"), invertible(mass, "CappedRectangle.mass"),
                momentOfInertia(l, R, mass)) {}

real CappedRectangle::momentOfInertia(real l, real R, real mass) {
  // Mass splits by area between the 2l x 2R rectangle and the two half-disks (one disk).
  const real rectangleArea = 4 * l * R;
  const real capsArea = pi<real> * R * R;
  const real rectangleMass = mass * rectangleArea / (rectangleArea + capsArea);
  const real capsMass = mass - rectangleMass;
  const real rectangle = rectangleMass * (4 * l * l + 4 * R * R) / 12;
  // Each half-disk: I about its centroid plus the parallel-axis shift to the capsule centre;
  // summed over both this is capsMass * (R^2/2 + l^2 + 8 l R / (3 pi)).
  const real caps = capsMass * (R * R / 2 + l * l + 8 * l * R / (3 * pi<real>));
  return rectangle + caps;
}

Vector2 CappedRectangle::endPoint(int end) const {
  const Vector2 axis = Vector2{halfLength(), 0}.rotated(alpha);
  return end == 0 ? r - axis : r + axis;
}

void CappedRectangle::setTactileSensors(int perSide, int perCap, real saturation) {
  installTactileSensors(TactileSensors::cappedRectangle(perSide, perCap, saturation));
}

void CappedRectangle::draw(GUI& gui) const {
  gui.drawCapsule(endPoint(0), endPoint(1), radius(), color, outlineColor);
}

}  // namespace thyrix
