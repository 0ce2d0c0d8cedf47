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

void Primitive::saveState(StateRecord& record) const {
  PhysicalObject::saveState(record);
  record.add(direction_);
  record.add(directionAngle_);
  tactile_.saveState(record);
}

void Primitive::restoreState(StateRecord::Reader& reader) {
  PhysicalObject::restoreState(reader);
  direction_ = reader.vector();
  directionAngle_ = reader.value();
  tactile_.restoreState(reader);
}

}  // namespace thyrix
