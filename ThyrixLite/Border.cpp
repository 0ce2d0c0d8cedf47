#include <ThyrixLite/Border.h>
#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>

#include <limits>

namespace thyrix {
namespace {
Vector2 checkedNormal(Vector2 normal) {
  requireFinite(normal, "Border.normal");
  if (!(normal.length() > 0)) throw InvalidArgument("Border.normal", "must not be the zero vector");
  // A subnormal length has lost its precision (and its inverse may overflow): too short.
  if (!(normal.length() >= std::numeric_limits<real>::min()))
    throw InvalidArgument("Border.normal", "is too short to normalize (a subnormal length)");
  return normal.normalized();
}
}  // namespace

Border::Border(Vector2 point, Vector2 normal)
    : Primitive(ShapeType::HalfPlane, 0, 0, std::numeric_limits<real>::infinity(),
                std::numeric_limits<real>::infinity()),
      normal_(checkedNormal(normal)) {
  requireFinite(point, "Border.point");
  r = point;
  fixed = true;
  color = colors::fixedObject;
}

void Border::draw(GUI& gui) const { gui.drawBorder(r, normal(), color); }

}  // namespace thyrix
