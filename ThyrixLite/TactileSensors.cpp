#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/TactileSensors.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>

namespace thyrix {
namespace {

/// The sector of @p angle (radians, any value) among @p count equal sectors of @p span radians
/// starting at 0, clamped to the valid range against round-off.
int sectorOf(real angle, real span, int count) {
  const int sector = static_cast<int>(std::floor(angle / span));
  return std::clamp(sector, 0, count - 1);
}

real positiveAngle(real angle) {
  const real turn = 2 * pi<real>;
  angle = std::fmod(angle, turn);
  return angle < 0 ? angle + turn : angle;
}

}  // namespace

TactileSensors TactileSensors::circle(int count, real startAngle, real saturation) {
  if (count < 1) throw InvalidArgument("TactileSensors.count", "must be at least 1");
  requireFinite(startAngle, "TactileSensors.startAngle");
  requirePositive(saturation, "TactileSensors.saturation");
  TactileSensors sensors;
  sensors.activations_.assign(static_cast<std::size_t>(count), 0);
  sensors.startAngle_ = startAngle;
  sensors.saturation_ = saturation;
  return sensors;
}

TactileSensors TactileSensors::cappedRectangle(int perSide, int perCap, real saturation) {
  if (perSide < 0) throw InvalidArgument("TactileSensors.perSide", "must not be negative");
  if (perCap < 0) throw InvalidArgument("TactileSensors.perCap", "must not be negative");
  if (perSide + perCap == 0)
    throw InvalidArgument("TactileSensors.perSide", "and perCap must not both be zero");
  requirePositive(saturation, "TactileSensors.saturation");
  TactileSensors sensors;
  sensors.activations_.assign(static_cast<std::size_t>(2 * (perSide + perCap)), 0);
  sensors.perSide_ = perSide;
  sensors.perCap_ = perCap;
  sensors.saturation_ = saturation;
  return sensors;
}

int TactileSensors::circleSector(Vector2 localPoint) const {
  const int count = static_cast<int>(activations_.size());
  const real angle = positiveAngle(std::atan2(localPoint.y, localPoint.x) - startAngle_);
  return sectorOf(angle, 2 * pi<real> / static_cast<real>(count), count);
}

int TactileSensors::cappedRectangleSector(Vector2 localPoint, real l) const {
  const int side = perSide_;
  const int cap = perCap_;
  const real x = localPoint.x;
  const real y = localPoint.y;
  // Which part of the outline: a cap when beyond an end (and the cap has sensors), else a side.
  if (cap > 0 && x > l) {
    const real angle = std::atan2(y, x - l) + pi<real> / 2;  // 0 .. pi over the right cap
    return side + sectorOf(angle, pi<real> / static_cast<real>(cap), cap);
  }
  if (cap > 0 && x < -l) {
    const real angle = positiveAngle(std::atan2(y, x + l) - pi<real> / 2);  // 0 .. pi, left cap
    return 2 * side + cap + sectorOf(angle, pi<real> / static_cast<real>(cap), cap);
  }
  if (side == 0) {  // sides without sensors: attribute to the nearer cap
    return x >= 0 ? (y < 0 ? 0 : cap - 1) : (y > 0 ? cap : 2 * cap - 1);
  }
  const real along = std::clamp(x + l, real(0), 2 * l);  // 0 at the left end
  const real segment = 2 * l / static_cast<real>(side);
  if (y < 0) return sectorOf(along, segment, side);            // lower side, rightwards
  return side + cap + sectorOf(2 * l - along, segment, side);  // upper side, leftwards
}

Vector2 TactileSensors::circleSectorMiddle(int k, real radius) const {
  const real span = 2 * pi<real> / static_cast<real>(activations_.size());
  const real angle = startAngle_ + (static_cast<real>(k) + real(0.5)) * span;
  return Vector2{std::cos(angle), std::sin(angle)} * radius;
}

Vector2 TactileSensors::cappedRectangleSectorMiddle(int k, real l, real R) const {
  const int side = perSide_;
  const int cap = perCap_;
  const real segment = side > 0 ? 2 * l / static_cast<real>(side) : 0;
  const real capSpan = cap > 0 ? pi<real> / static_cast<real>(cap) : 0;
  const auto middle = [](int i) { return static_cast<real>(i) + real(0.5); };
  if (k < side) return {-l + middle(k) * segment, -R};  // lower side, rightwards
  k -= side;
  if (k < cap) {  // right cap, from -90 degrees
    const real angle = -pi<real> / 2 + middle(k) * capSpan;
    return Vector2{l, 0} + Vector2{std::cos(angle), std::sin(angle)} * R;
  }
  k -= cap;
  if (k < side) return {l - middle(k) * segment, R};  // upper side, leftwards
  k -= side;
  const real angle = pi<real> / 2 + middle(k) * capSpan;  // left cap, from 90 degrees
  return Vector2{-l, 0} + Vector2{std::cos(angle), std::sin(angle)} * R;
}

void TactileSensors::clearSums() {
  std::fill(activations_.begin(), activations_.end(), real(0));
  touched_ = false;
}

void TactileSensors::finishSums() {
  // A local copy: the stores to the activations cannot change it, so the loop neither reloads
  // it nor stays scalar.
  const real saturation = saturation_;
  for (real& a : activations_) a = std::min(real(1), a / saturation);
}

void TactileSensors::saveState(StateRecord& record) const {
  record.add(std::span<const real>(activations_));
  record.add(touched_);
}

void TactileSensors::restoreState(StateRecord::Reader& reader) {
  reader.reals(activations_);
  touched_ = reader.flag();
}

}  // namespace thyrix
