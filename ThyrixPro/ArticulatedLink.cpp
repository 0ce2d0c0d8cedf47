#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <cmath>
#include <string>

namespace thyrix {

ArticulatedLink ArticulatedLink::capsule(int parent, Vector2 jointPosition, real halfLength,
                                         real radius, real mass) {
  requirePositive(2 * halfLength, "ArticulatedLink.length");
  requirePositive(radius, "ArticulatedLink.radius");
  requirePositive(mass, "ArticulatedLink.mass");
  ArticulatedLink link;
  link.parent = parent;
  link.jointPosition = jointPosition;
  link.length = 2 * halfLength;
  link.centerOfMass = {halfLength, 0};
  link.mass = mass;
  // The same inertia as a free CappedRectangle of this mass, so a link and a loose capsule
  // respond alike to the same push.
  link.inertia = CappedRectangle::momentOfInertia(halfLength, radius, mass);
  return link;
}

void ArticulatedLink::validate(int index) const {
  const std::string where = "of link " + std::to_string(index);
  if (parent < base || parent >= index)
    throw InvalidArgument("ArticulatedLink.parent",
                          where + " must be -1 (the base) or an earlier link, in [-1, " +
                              std::to_string(index - 1) + "], so the links form a tree (got " +
                              std::to_string(parent) + ")");
  auto positive = [&](real value, const char* field) {
    if (!(value > 0) || !std::isfinite(value))
      throw InvalidArgument(
          field, where + " must be positive and finite (got " + std::to_string(value) + ")");
  };
  auto finite = [&](Vector2 value, const char* field) {
    if (!std::isfinite(value.x) || !std::isfinite(value.y))
      throw InvalidArgument(field, where + " must be finite (got (" + std::to_string(value.x) +
                                       ", " + std::to_string(value.y) + "))");
  };
  finite(jointPosition, "ArticulatedLink.jointPosition");
  positive(length, "ArticulatedLink.length");
  finite(centerOfMass, "ArticulatedLink.centerOfMass");
  positive(mass, "ArticulatedLink.mass");
  positive(inertia, "ArticulatedLink.inertia");
  if (hasLimits) {
    if (!std::isfinite(qMin))
      throw InvalidArgument("ArticulatedLink.qMin",
                            where + " must be finite (got " + std::to_string(qMin) + ")");
    if (!std::isfinite(qMax) || qMax < qMin)
      throw InvalidArgument("ArticulatedLink.qMax", where + " must be finite and at least qMin (" +
                                                        std::to_string(qMin) + ") (got " +
                                                        std::to_string(qMax) + ")");
  }
}

}  // namespace thyrix
