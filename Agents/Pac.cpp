#include <Agents/Pac.h>

#include <ThyrixLite/GUI.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/World.h>
#include <Tools/MathTools.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thyrix {
namespace {

constexpr real pixelAngle = pi<real> / 12;  // 15 degrees

/// @p x limited to [0, 1]; NaN (a broken controller's output) becomes 0, so that it cannot
/// reach a rest length or a force.
real unit(real x) { return x > 0 ? (x < 1 ? x : real(1)) : real(0); }

/// Checks what Circle and ElasticLink do not, before any body is made.
const PacParameters& checked(const PacParameters& p) {
  if (p.circleCount < 5) throw InvalidArgument("Pac.circleCount", "must be at least 5");
  requirePositive(p.ringRadius, "Pac.ringRadius");
  requirePositive(p.maxForce, "Pac.maxForce");
  requirePositive(p.tactileSaturation, "Pac.tactileSaturation");
  if (p.crossLinkSpan < 1 || p.crossLinkSpan > p.circleCount / 2)
    throw InvalidArgument("Pac.crossLinkSpan", "must be between 1 and circleCount / 2 (got " +
                                                   std::to_string(p.crossLinkSpan) + ")");
  const real chord = 2 * p.ringRadius * std::sin(pi<real> / static_cast<real>(p.circleCount));
  if (!(p.mouthWidth > chord) || !(p.mouthWidth < static_cast<real>(p.circleCount - 1) * chord))
    throw InvalidArgument("Pac.mouthWidth",
                          "must lie between the closed chord (" + std::to_string(chord) + ") and " +
                              std::to_string(p.circleCount - 1) + " times it (got " +
                              std::to_string(p.mouthWidth) + ")");
  return p;
}

/// The half gap angle x in (0, pi / n] at which the mouth chord is @p ratio times the other
/// chords: on a circle, `mouth / chord = sin((n - 1) x) / sin(x)`, which falls from n - 1 to 1
/// as x grows from 0 to pi / n (the mouth takes what the other gaps leave). Bisection in
/// double, once per Pac.
double halfGapForRatio(int n, double ratio) {
  double low = 0;                // ratio n - 1 at the limit
  double high = pi<double> / n;  // ratio 1
  for (int i = 0; i < 100; ++i) {
    const double mid = (low + high) / 2;
    if (std::sin((n - 1) * mid) / std::sin(mid) > ratio)
      low = mid;
    else
      high = mid;
  }
  return (low + high) / 2;
}

}  // namespace

Pac::Pac(std::unique_ptr<Controller> controller, const Parameters& parameters)
    : parameters_(checked(parameters)),
      controller_(std::move(controller)),
      eye_(*this, {parameters.ringRadius + parameters.radius, 0}, 0, pixelCount, pixelAngle) {
  const int n = parameters_.circleCount;
  closedGap_ = 2 * pi<real> / static_cast<real>(n);
  chord_ = 2 * parameters_.ringRadius * std::sin(closedGap_ / 2);
  openGap_ = static_cast<real>(
      2 * halfGapForRatio(n, static_cast<double>(parameters_.mouthWidth / chord_)));

  circles_.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    Circle& circle = addBody(std::make_unique<Circle>(parameters_.radius, parameters_.mass));
    // Two touch sensors: sector 0 is the outer half once the circle's x axis points away from
    // the ring's centre (orientCircles), sector 1 the inner half.
    circle.setTactileSensors(2, -pi<real> / 2, parameters_.tactileSaturation);
    circle.color = colors::yellow;
    circles_.push_back(&circle);
  }
  // Neighbours first (links 0 .. n - 2), then the mouth (n - 1), then the cross-links. A span of
  // n / 2 on an even ring reaches the opposite circle from both sides: link it once.
  const auto link = [this](int a, int b, real stiffness) {
    addLink(*circles_[static_cast<std::size_t>(a)], {}, *circles_[static_cast<std::size_t>(b)], {},
            chord_, stiffness);
    linkEnds_.emplace_back(a, b);
  };
  for (int k = 0; k + 1 < n; ++k) link(k, k + 1, parameters_.ringStiffness);
  link(n - 1, 0, parameters_.ringStiffness);
  links()[mouthLinkIndex()]->color = colors::red;
  for (int span = 2; span <= parameters_.crossLinkSpan; ++span)
    for (int k = 0; k < n; ++k)
      if (!(2 * span == n && k >= span)) link(k, (k + span) % n, parameters_.crossStiffness);

  shape_.resize(static_cast<std::size_t>(n));
  sensors_.assign(static_cast<std::size_t>(firstTouch) + static_cast<std::size_t>(n), 0);
  setShape(0);
  place({0, 0}, 0);
}

void Pac::setShape(real mouthActivation) {
  if (mouthActivation == shapeMouth_) return;  // rest lengths are already those of this shape
  shapeMouth_ = mouthActivation;
  const int n = parameters_.circleCount;
  const real gap = closedGap_ + mouthActivation * (openGap_ - closedGap_);
  const real radius = chord_ / (2 * std::sin(gap / 2));
  // The mouth, centred on the heading (+x), takes the angle the other n - 1 gaps leave.
  const real first = pi<real> - static_cast<real>(n - 1) * gap / 2;
  shapeCentroid_ = {};
  for (int k = 0; k < n; ++k) {
    const real angle = first + static_cast<real>(k) * gap;
    const Vector2 p{radius * std::cos(angle), radius * std::sin(angle)};
    shape_[static_cast<std::size_t>(k)] = p;
    shapeCentroid_ += p;
  }
  shapeCentroid_ = shapeCentroid_ / static_cast<real>(n);
  for (std::size_t i = 0; i < linkEnds_.size(); ++i) {
    const auto [a, b] = linkEnds_[i];
    links()[i]->setRestLength(
        distance(shape_[static_cast<std::size_t>(a)], shape_[static_cast<std::size_t>(b)]));
  }
}

void Pac::place(Vector2 centre, real heading) {
  r = centre;
  alpha = heading;
  for (std::size_t k = 0; k < circles_.size(); ++k) circles_[k]->r = toWorld(shape_[k]);
  orientCircles();
}

Vector2 Pac::centre() const {
  Vector2 sum;
  for (const Circle* circle : circles_) sum += circle->r;
  return sum / static_cast<real>(circles_.size());
}

bool Pac::contains(Vector2 point) const {
  bool inside = false;
  const std::size_t n = circles_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vector2 a = circles_[i]->r;
    const Vector2 b = circles_[j]->r;
    if ((a.y > point.y) != (b.y > point.y) &&
        point.x < a.x + (point.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

void Pac::fitPose() {
  // Least-squares rigid fit of the commanded shape onto the circles (2D Kabsch): the centroids
  // match, and the angle maximises the sum of dot products of the centred point pairs. Robust
  // to the ring's small deformations, unlike the direction of any one pair of circles.
  const Vector2 centroid = centre();
  real sine = 0;
  real cosine = 0;
  for (std::size_t k = 0; k < circles_.size(); ++k) {
    const Vector2 a = shape_[k] - shapeCentroid_;
    const Vector2 b = circles_[k]->r - centroid;
    cosine += dot(a, b);
    sine += cross(a, b);
  }
  if (sine != 0 || cosine != 0) alpha = std::atan2(sine, cosine);
  r = centroid - shapeCentroid_.rotated(alpha);
}

void Pac::orientCircles() {
  // A circle's orientation has no effect on its physics (links hold it at its centre, contacts
  // are frictionless and pass through it): point each one's x axis away from the ring's centre
  // so that its touch sensors split the outer and inner halves.
  const Vector2 c = centre();
  for (Circle* circle : circles_) {
    const Vector2 out = circle->r - c;
    if (out.lengthSquared() > 0) circle->alpha = std::atan2(out.y, out.x);
  }
}

void Pac::updateSensors(const World& world) {
  fitPose();
  orientCircles();
  eye_.update(world.objects);
}

void Pac::readSensors() {
  real inside = 0;
  const std::size_t n = circles_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto touch = circles_[k]->tactileActivations();
    sensors_[static_cast<std::size_t>(firstTouch) + k] = touch[0];
    inside += touch[1];
  }
  sensors_[insideSensor] = unit(inside);
  sensors_[mouthSensor] = unit((mouthLink().length() - chord_) / (parameters_.mouthWidth - chord_));
  Vector2 velocity;
  for (const Circle* circle : circles_) velocity += circle->v;
  const real speed =
      dot(velocity / static_cast<real>(n), forward()) / (parameters_.maxForce / parameters_.mass);
  sensors_[forwardSensor] = unit(speed);
  sensors_[backwardSensor] = unit(-speed);
  const auto seen = eye_.activations();
  std::copy(seen.begin(), seen.end(), sensors_.begin() + firstPixel);
}

void Pac::applyEffectors() {
  for (real& e : effectors_) e = unit(e);
  const Vector2 f = forward();
  const real left = parameters_.maxForce * (effectors_[leftForward] - effectors_[leftBackward]);
  const real right = parameters_.maxForce * (effectors_[rightForward] - effectors_[rightBackward]);
  const std::size_t n = circles_.size();
  for (std::size_t k = 0; k < n; ++k) {
    // Circles 0 .. n/2 - 1 lie on the left of the heading; on an odd ring the middle one is at
    // the back, on the axis.
    const real push = 2 * k + 1 < n ? left : 2 * k + 1 > n ? right : (left + right) / 2;
    circles_[k]->externalForce += f * push;
  }
  setShape(effectors_[mouth]);
}

void Pac::control() {
  readSensors();
  if (controller_) controller_->control(sensors_, effectors_);
  applyEffectors();
}

void Pac::draw(GUI& gui) const {
  // Drawn before the circles (registration order), so the outline shows only through the gaps
  // between them: in practice, the mouth.
  const std::size_t n = circles_.size();
  for (std::size_t k = 0; k + 1 < n; ++k) links()[k]->draw(gui);
  mouthLink().draw(gui);
  gui.drawLine(r, r + forward() * parameters_.ringRadius, colors::black);
  gui.drawCircle(eye_.eyePosition(), parameters_.radius / 5, alpha, colors::black, colors::black);
}

void Pac::saveState(StateRecord& record) const {
  Elastoid::saveState(record);
  record.add(std::span<const real>(sensors_));
  record.add(shapeCentroid_);
  record.add(shapeMouth_);
  for (const Vector2 point : shape_) record.add(point);
  record.add(std::span<const real>(effectors_));
  record.add(controller_ != nullptr);
  if (controller_) controller_->saveState(record);
}

void Pac::restoreState(StateRecord::Reader& reader) {
  Elastoid::restoreState(reader);
  reader.reals(sensors_);
  shapeCentroid_ = reader.vector();
  shapeMouth_ = reader.value();
  for (Vector2& point : shape_) point = reader.vector();
  reader.reals(effectors_);
  if (reader.flag() != (controller_ != nullptr))
    throw std::runtime_error("WorldState: the Pac's controller is in one world, not the other");
  if (controller_) controller_->restoreState(reader);
}

}  // namespace thyrix
