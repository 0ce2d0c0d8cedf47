#include <ThyrixLite/Primitive.h>

namespace thyrix {

void Primitive::touch(Vector2 worldPoint, real force) {
  const Vector2 local = (worldPoint - r).rotated(-alpha);
  switch (shapeType_) {
    case ShapeType::Circle:
      tactile_.add(tactile_.circleSector(local), force);
      break;
    case ShapeType::Capsule:
      tactile_.add(tactile_.cappedRectangleSector(local, halfLength_), force);
      break;
    case ShapeType::HalfPlane:
      break;  // borders carry no sensors
  }
}

}  // namespace thyrix
