#include <ThyrixLite/Circle.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>

namespace thyrix {
namespace {
real checkedRadius(real radius) {
  requirePositive(radius, "Circle.radius");
  return radius;
}
real checkedMass(real mass) {
  requireInvertible(mass, "Circle.mass");
  return mass;
}
}  // namespace

Circle::Circle(real radius, real mass)
    : Primitive(ShapeType::Circle, checkedRadius(radius), 0, checkedMass(mass),
                mass * radius * radius / 2) {}

void Circle::setTactileSensors(int count, real startAngle, real saturation) {
  installTactileSensors(TactileSensors::circle(count, startAngle, saturation));
}

void Circle::draw(GUI& gui) const { gui.drawCircle(r, radius(), alpha, color, outlineColor); }

}  // namespace thyrix
