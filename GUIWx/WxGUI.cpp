#include <GUIWx/WxGUI.h>

#include <wx/dc.h>
#include <wx/pen.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace thyrix {
namespace {

constexpr double pi = 3.14159265358979323846;
// Shapes this many pixels outside the view are still drawn (outlines, thick lines); beyond,
// they are skipped or clipped, which keeps every coordinate far inside the range of int.
constexpr double margin = 64;
constexpr int borderLineWidth = 2;
constexpr double borderStripPixels = 8;
constexpr double borderStripOpacity = 0.35;

wxColour toWx(Color c) { return {c.red, c.green, c.blue, c.alpha}; }

// Device coordinates are ints (and cairo's fixed point reaches about 8 million pixels): every
// coordinate is clamped far inside both; what is drawn that far out is never on screen.
constexpr double maxCoordinate = 4e6;

int rounded(double v) {
  return static_cast<int>(std::lround(std::clamp(v, -maxCoordinate, maxCoordinate)));
}

wxPoint toPoint(PixelPoint p) { return {rounded(p.x), rounded(p.y)}; }

bool finite(Vector2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Liang-Barsky: clips the segment p-q to the rectangle [low, high]; false if nothing is left.
bool clipSegment(PixelPoint& p, PixelPoint& q, PixelPoint low, PixelPoint high) {
  double t0 = 0;
  double t1 = 1;
  const double dx = q.x - p.x;
  const double dy = q.y - p.y;
  const auto clip = [&](double denominator, double numerator) {
    if (denominator == 0) return numerator >= 0;
    const double t = numerator / denominator;
    if (denominator < 0) {
      if (t > t1) return false;
      t0 = std::max(t0, t);
    } else {
      if (t < t0) return false;
      t1 = std::min(t1, t);
    }
    return true;
  };
  if (!clip(-dx, p.x - low.x) || !clip(dx, high.x - p.x) || !clip(-dy, p.y - low.y) ||
      !clip(dy, high.y - p.y))
    return false;
  const PixelPoint start{p.x + t0 * dx, p.y + t0 * dy};
  q = {p.x + t1 * dx, p.y + t1 * dy};
  p = start;
  return true;
}

// Sutherland-Hodgman step: the part of the convex polygon @p in where `a x + b y <= c`.
std::vector<PixelPoint> clipToHalfPlane(const std::vector<PixelPoint>& in, double a, double b,
                                        double c) {
  std::vector<PixelPoint> out;
  const auto side = [&](PixelPoint p) { return a * p.x + b * p.y - c; };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const PixelPoint p = in[i];
    const PixelPoint q = in[(i + 1) % in.size()];
    const double sp = side(p);
    const double sq = side(q);
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

}  // namespace

bool WxGUI::visible(PixelPoint low, PixelPoint high) const {
  return high.x >= -margin && high.y >= -margin && low.x <= view_.width() + margin &&
         low.y <= view_.height() + margin;
}

void WxGUI::drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) {
  if (!finite(centre) || !std::isfinite(radius) || !std::isfinite(angle)) return;
  const PixelPoint c = view_.toPixel(centre);
  const double r = view_.toPixels(std::max(real(0), radius));
  if (!visible({c.x - r, c.y - r}, {c.x + r, c.y + r})) return;
  dc_.SetPen(wxPen(toWx(outline), 1));
  dc_.SetBrush(wxBrush(toWx(fill)));
  if (std::abs(c.x) + r > maxCoordinate || std::abs(c.y) + r > maxCoordinate) {
    // Zoomed far into a large circle: beyond the device's coordinates. Its outline is then
    // nearly straight; show its inside if it covers the view, else leave it out.
    const double w = view_.width();
    const double h = view_.height();
    const double farthest = std::hypot(std::max(std::abs(c.x), std::abs(c.x - w)),
                                       std::max(std::abs(c.y), std::abs(c.y - h)));
    if (farthest < r) {
      dc_.SetPen(*wxTRANSPARENT_PEN);
      dc_.DrawRectangle(0, 0, view_.width(), view_.height());
    }
    return;
  }
  dc_.DrawCircle(toPoint(c), std::max(1, rounded(r)));
  // The orientation mark: a radius at the body's angle (counter-clockwise in the world, so
  // clockwise on the y-down screen).
  PixelPoint p = c;
  PixelPoint q{c.x + r * std::cos(static_cast<double>(angle)),
               c.y - r * std::sin(static_cast<double>(angle))};
  if (clipSegment(p, q, {-margin, -margin}, {view_.width() + margin, view_.height() + margin}))
    dc_.DrawLine(toPoint(p), toPoint(q));
}

void WxGUI::drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) {
  if (!finite(a) || !finite(b) || !std::isfinite(radius)) return;
  const PixelPoint pa = view_.toPixel(a);
  const PixelPoint pb = view_.toPixel(b);
  const double r = view_.toPixels(std::max(real(0), radius));
  if (!visible({std::min(pa.x, pb.x) - r, std::min(pa.y, pb.y) - r},
               {std::max(pa.x, pb.x) + r, std::max(pa.y, pb.y) + r}))
    return;
  // The outline as one polygon (two half-circles joined by the sides), so fill and outline
  // come from one call on any device context.
  const double axis = std::atan2(pb.y - pa.y, pb.x - pa.x);
  const int segments = std::clamp(rounded(r / 2), 6, 32);
  std::vector<wxPoint> outlinePoints;
  outlinePoints.reserve(2 * static_cast<std::size_t>(segments + 1));
  for (int end = 0; end < 2; ++end) {
    const PixelPoint centre = end == 0 ? pb : pa;
    const double start = axis - pi / 2 + end * pi;
    for (int k = 0; k <= segments; ++k) {
      const double t = start + pi * k / segments;
      outlinePoints.push_back(toPoint({centre.x + r * std::cos(t), centre.y + r * std::sin(t)}));
    }
  }
  dc_.SetPen(wxPen(toWx(outline), 1));
  dc_.SetBrush(wxBrush(toWx(fill)));
  dc_.DrawPolygon(static_cast<int>(outlinePoints.size()), outlinePoints.data());
}

void WxGUI::drawLine(Vector2 a, Vector2 b, Color color, real width) {
  if (!finite(a) || !finite(b)) return;
  PixelPoint p = view_.toPixel(a);
  PixelPoint q = view_.toPixel(b);
  if (!clipSegment(p, q, {-margin, -margin}, {view_.width() + margin, view_.height() + margin}))
    return;
  const double pixels = width > 0 && std::isfinite(width) ? view_.toPixels(width) : 1;
  wxPen pen(toWx(color), std::clamp(rounded(pixels), 1, 1000));
  pen.SetCap(wxCAP_ROUND);
  dc_.SetPen(pen);
  dc_.DrawLine(toPoint(p), toPoint(q));
}

void WxGUI::drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) {
  if (vertices.empty()) return;
  std::vector<wxPoint> points;
  points.reserve(vertices.size());
  PixelPoint low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  PixelPoint high{-low.x, -low.y};
  for (const Vector2 v : vertices) {
    if (!finite(v)) return;
    const PixelPoint p = view_.toPixel(v);
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    points.push_back(toPoint(p));
  }
  if (!visible(low, high) || high.x - low.x > 1e7 || high.y - low.y > 1e7) return;
  dc_.SetPen(wxPen(toWx(outline), 1));
  dc_.SetBrush(wxBrush(toWx(fill)));
  dc_.DrawPolygon(static_cast<int>(points.size()), points.data());
}

void WxGUI::drawText(Vector2 position, std::string_view text, Color color) {
  if (!finite(position)) return;
  const PixelPoint p = view_.toPixel(position);
  if (!visible(p, p)) return;
  const wxString label = wxString::FromUTF8(text.data(), text.size());
  wxCoord width = 0;
  wxCoord height = 0;
  wxCoord descent = 0;
  dc_.GetTextExtent(label, &width, &height, &descent);
  dc_.SetTextForeground(toWx(color));
  // wx places text by its top-left corner; the GUI interface by the start of its baseline.
  dc_.DrawText(label, rounded(p.x), rounded(p.y) - (height - descent));
}

void WxGUI::drawBorder(Vector2 point, Vector2 normal, Color color) {
  if (!finite(point) || !finite(normal)) return;
  // On the screen the map is a uniform scale and a flip of y: the screen normal is the world
  // normal with y negated.
  const PixelPoint p = view_.toPixel(point);
  const double length = std::hypot(static_cast<double>(normal.x), static_cast<double>(normal.y));
  if (!(length > 0)) return;
  const double nx = normal.x / length;
  const double ny = -normal.y / length;
  const double offset = nx * p.x + ny * p.y;  // the line is n . x = offset on the screen
  const double w = view_.width();
  const double h = view_.height();

  // The solid side within the strip's reach: where offset - strip <= n . x <= offset.
  std::vector<PixelPoint> strip{{0, 0}, {w, 0}, {w, h}, {0, h}};
  strip = clipToHalfPlane(strip, nx, ny, offset);
  strip = clipToHalfPlane(strip, -nx, -ny, borderStripPixels - offset);
  if (strip.size() >= 3) {
    std::vector<wxPoint> points;
    points.reserve(strip.size());
    for (const PixelPoint q : strip) points.push_back(toPoint(q));
    Color shaded = color;
    shaded.alpha = static_cast<std::uint8_t>(std::lround(color.alpha * borderStripOpacity));
    dc_.SetPen(*wxTRANSPARENT_PEN);
    dc_.SetBrush(wxBrush(toWx(shaded)));
    dc_.DrawPolygon(static_cast<int>(points.size()), points.data());
  }

  // The line p + s t (t along it), clipped to the view.
  const double reach = 2 * (w + h) + std::abs(p.x) + std::abs(p.y);
  PixelPoint a{p.x + ny * reach, p.y - nx * reach};
  PixelPoint b{p.x - ny * reach, p.y + nx * reach};
  if (!clipSegment(a, b, {0, 0}, {w, h})) return;
  dc_.SetPen(wxPen(toWx(color), borderLineWidth));
  dc_.DrawLine(toPoint(a), toPoint(b));
}

}  // namespace thyrix
