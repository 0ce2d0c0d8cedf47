#include <GUIWx/DrawingRecorder.h>

namespace thyrix {

DrawCommand& DrawingRecorder::add(DrawCommand::Kind kind, std::initializer_list<Vector2> points) {
  DrawCommand& c = commands_.emplace_back();
  c.kind = kind;
  c.first = static_cast<std::uint32_t>(points_.size());
  c.count = static_cast<std::uint32_t>(points.size());
  points_.insert(points_.end(), points);
  return c;
}

void DrawingRecorder::drawCircle(Vector2 centre, real radius, real angle, Color fill,
                                 Color outline) {
  DrawCommand& c = add(DrawCommand::Kind::Circle, {centre});
  c.radius = radius;
  c.angle = angle;
  c.fill = fill;
  c.outline = outline;
}

void DrawingRecorder::drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) {
  DrawCommand& c = add(DrawCommand::Kind::Capsule, {a, b});
  c.radius = radius;
  c.fill = fill;
  c.outline = outline;
}

void DrawingRecorder::drawLine(Vector2 a, Vector2 b, Color color, real width) {
  DrawCommand& c = add(DrawCommand::Kind::Line, {a, b});
  c.fill = color;
  c.width = width;
}

void DrawingRecorder::drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) {
  DrawCommand& c = add(DrawCommand::Kind::Polygon, {});
  c.count = static_cast<std::uint32_t>(vertices.size());
  points_.insert(points_.end(), vertices.begin(), vertices.end());
  c.fill = fill;
  c.outline = outline;
}

void DrawingRecorder::drawText(Vector2 position, std::string_view text, Color color) {
  DrawCommand& c = add(DrawCommand::Kind::Text, {position});
  c.fill = color;
  c.textFirst = static_cast<std::uint32_t>(text_.size());
  c.textCount = static_cast<std::uint32_t>(text.size());
  text_ += text;
}

void DrawingRecorder::drawBorder(Vector2 point, Vector2 normal, Color color) {
  DrawCommand& c = add(DrawCommand::Kind::Border, {point, normal});
  c.fill = color;
}

void DrawingRecorder::replay(GUI& gui) const {
  for (const DrawCommand& c : commands_) {
    const Vector2* p = points_.data() + c.first;
    switch (c.kind) {
      case DrawCommand::Kind::Circle:
        gui.drawCircle(p[0], c.radius, c.angle, c.fill, c.outline);
        break;
      case DrawCommand::Kind::Capsule:
        gui.drawCapsule(p[0], p[1], c.radius, c.fill, c.outline);
        break;
      case DrawCommand::Kind::Line:
        gui.drawLine(p[0], p[1], c.fill, c.width);
        break;
      case DrawCommand::Kind::Polygon:
        gui.drawPolygon(points(c), c.fill, c.outline);
        break;
      case DrawCommand::Kind::Text:
        gui.drawText(p[0], text(c), c.fill);
        break;
      case DrawCommand::Kind::Border:
        gui.drawBorder(p[0], p[1], c.fill);
        break;
    }
  }
}

void DrawingRecorder::clear() {
  commands_.clear();
  points_.clear();
  text_.clear();
}

}  // namespace thyrix
