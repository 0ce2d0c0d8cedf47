#include <GUIWx/ViewTransform.h>

#include <algorithm>
#include <cmath>

namespace thyrix {

Vector2 ViewTransform::toWorld(PixelPoint p) const {
  return {static_cast<real>(cx_ + (p.x - width_ / 2.0) / scale_),
          static_cast<real>(cy_ - (p.y - height_ / 2.0) / scale_)};
}

PixelPoint ViewTransform::toPixel(Vector2 w) const {
  return {width_ / 2.0 + (static_cast<double>(w.x) - cx_) * scale_,
          height_ / 2.0 - (static_cast<double>(w.y) - cy_) * scale_};
}

void ViewTransform::setSize(int width, int height) {
  width_ = std::max(1, width);
  height_ = std::max(1, height);
}

void ViewTransform::set(double scale, Vector2 centre) {
  if (std::isfinite(scale)) scale_ = std::clamp(scale, minScale, maxScale);
  if (std::isfinite(centre.x) && std::isfinite(centre.y)) {
    cx_ = centre.x;
    cy_ = centre.y;
  }
}

void ViewTransform::zoomAbout(PixelPoint anchor, double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  // Keep the world point under the anchor there: it is at anchor before and after the change.
  const double wx = cx_ + (anchor.x - width_ / 2.0) / scale_;
  const double wy = cy_ - (anchor.y - height_ / 2.0) / scale_;
  scale_ = std::clamp(scale_ * factor, minScale, maxScale);
  cx_ = wx - (anchor.x - width_ / 2.0) / scale_;
  cy_ = wy + (anchor.y - height_ / 2.0) / scale_;
}

void ViewTransform::panBy(double dx, double dy) {
  if (!std::isfinite(dx) || !std::isfinite(dy)) return;
  cx_ -= dx / scale_;
  cy_ += dy / scale_;
}

void ViewTransform::fit(const BoundingBox& box) {
  const double w = static_cast<double>(box.upper.x) - box.lower.x;
  const double h = static_cast<double>(box.upper.y) - box.lower.y;
  if (!(w >= 0) || !(h >= 0) || !std::isfinite(w) || !std::isfinite(h)) return;
  const double sx = w > 0 ? width_ / w : maxScale;
  const double sy = h > 0 ? height_ / h : maxScale;
  scale_ = std::clamp(std::min(sx, sy), minScale, maxScale);
  cx_ = (static_cast<double>(box.lower.x) + box.upper.x) / 2;
  cy_ = (static_cast<double>(box.lower.y) + box.upper.y) / 2;
}

}  // namespace thyrix
