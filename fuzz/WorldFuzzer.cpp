/// @file WorldFuzzer.cpp
/// @brief libFuzzer target: worlds built from bytes and stepped stay finite, keep every contact
/// force non-negative and keep every shape inside their closed box of four borders.
///
/// The bytes (then a stream they seed) choose the solver (Baraff or Gauss-Seidel), the time
/// step, the box, 1 to 40 circles, capsules and two-part composed bodies (masses 1e-2 to 1e2,
/// inside the box, apart or, in a quarter of the worlds, overlapping), each pushed by a smooth
/// bounded force and torque, and gravity or none.
///
/// THYRIX_FUZZ_LEAK_FOLDER (a folder): a shape found outside the box saves the input there
/// instead of failing, and the other checks go on (long runs while leaks are known).
#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/MTRandom.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using thyrix::real;
using thyrix::Vector2;

/// A body's smooth push: amplitude times a sine of its own frequency and phase, per component.
struct Push {
  thyrix::PhysicalObject* body = nullptr;
  Vector2 amplitude;
  real torque = 0;
  real frequency = 0;
  real phase = 0;
};

[[noreturn]] void fail(const char* what, int step, std::size_t object, double value) {
  std::fprintf(stderr, "WorldFuzzer: %s at step %d, object %zu (%g)\n", what, step, object, value);
  std::abort();
}

/// Writes @p bytes to @p folder, named by their FNV-1a hash.
void saveInput(const char* folder, const std::uint8_t* bytes, std::size_t size) {
  std::uint64_t hash = 14695981039346656037u;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211u;
  const std::string path = std::string(folder) + "/leak-" + std::to_string(hash);
  if (FILE* file = std::fopen(path.c_str(), "wb")) {
    std::fwrite(bytes, 1, size, file);
    std::fclose(file);
  }
}

/// The world's numbers: from the bytes while they last, then from a stream seeded by them, so
/// that a short input still gives a world of distinct bodies (not 40 copies of the last one).
class Source {
 public:
  Source(const std::uint8_t* bytes, std::size_t size) : data_(bytes, size) {
    std::uint32_t seed = 2166136261u;
    for (std::size_t i = 0; i < size; ++i) seed = (seed ^ bytes[i]) * 16777619u;
    random_.seed(seed);
  }
  real uniform(double low, double high) {
    if (data_.remaining_bytes() == 0) return static_cast<real>(random_.uniform(low, high));
    return static_cast<real>(data_.ConsumeFloatingPointInRange(low, high));
  }
  real logUniform(double lowExponent, double highExponent) {
    return static_cast<real>(std::pow(10.0, double(uniform(lowExponent, highExponent))));
  }
  int integer(int low, int high) {
    if (data_.remaining_bytes() == 0) return random_.integer(low, high);
    return data_.ConsumeIntegralInRange(low, high);
  }
  bool coin() { return integer(0, 1) == 1; }

 private:
  FuzzedDataProvider data_;
  thyrix::MTRandom random_;
};

/// A primitive's axis end points in the world (a circle's twice its centre), from its owner's
/// pose, which is where the next step puts it.
void axisOf(const thyrix::Primitive& primitive, Vector2& end0, Vector2& end1) {
  const thyrix::PhysicalObject& owner = primitive.owner();
  const bool part = &owner != &primitive;
  const Vector2 centre = part ? owner.toWorld(primitive.localPosition()) : primitive.r;
  const real angle = part ? owner.alpha + primitive.localAngle() : primitive.alpha;
  const Vector2 half = Vector2{primitive.halfLength(), 0}.rotated(angle);
  end0 = centre - half;
  end1 = centre + half;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  Source data(bytes, size);
  thyrix::Simulator simulator(data.uniform(0.001, 0.05));
  simulator.setContactSolver(data.coin() ? thyrix::ContactSolverKind::GaussSeidel
                                         : thyrix::ContactSolverKind::Baraff);
  const real halfWidth = data.uniform(1, 20);
  const real halfHeight = data.uniform(1, 20);
  // The closed box: its four walls, normals pointing in.
  const Vector2 wallPoints[4] = {
      {0, -halfHeight}, {0, halfHeight}, {-halfWidth, 0}, {halfWidth, 0}};
  const Vector2 wallNormals[4] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (int k = 0; k < 4; ++k)
    simulator.registerObject(std::make_unique<thyrix::Border>(wallPoints[k], wallNormals[k]));

  const int bodies = data.integer(1, 40);
  const real room = std::min(halfWidth, halfHeight);
  // The bodies' sizes shrink as they get more numerous, so that most worlds have room for all.
  const real scale = room / std::sqrt(real(bodies));
  const real dt = simulator.timestep();
  std::vector<Push> pushes;
  struct Placed {
    Vector2 centre;
    real reach;
  };
  std::vector<Placed> placed;
  const bool overlapping = data.integer(0, 3) == 0;  // a quarter of the worlds start overlapping
  real smallest = room;                              // the smallest radius
  for (int k = 0; k < bodies; ++k) {
    const int kind = data.integer(0, 2);
    const real mass = data.logUniform(-2, 2);
    const real radius = data.uniform(0.02, 0.5) * scale;
    const real halfLength = data.uniform(0.01, 1) * scale;
    smallest = std::min(smallest, radius);
    std::unique_ptr<thyrix::PhysicalObject> body;
    real extent = radius;  // how far the body reaches from its centre of mass, at most
    if (kind == 0) {
      body = std::make_unique<thyrix::Circle>(radius, mass);
    } else if (kind == 1) {
      body = std::make_unique<thyrix::CappedRectangle>(halfLength, radius, mass);
      extent += halfLength;
    } else {  // a capsule with a circle at one end
      auto composed = std::make_unique<thyrix::ComposedPhysicalObject>();
      composed->add(std::make_unique<thyrix::CappedRectangle>(halfLength, radius, mass), {0, 0});
      composed->add(std::make_unique<thyrix::Circle>(radius * real(1.5), mass * real(0.5)),
                    {halfLength, 0});
      body = std::move(composed);
      extent += 2 * halfLength + radius * 3;
    }
    // A body longer than the box cannot start inside it: it is left out of the world.
    if (extent >= room) continue;
    // Inside the box: the centre of mass at most the box less the reach from each wall; clear
    // of the bodies placed so far within a few tries, unless the world starts overlapping.
    const real freeX = std::max(real(0), halfWidth - extent);
    const real freeY = std::max(real(0), halfHeight - extent);
    for (int attempt = 0; attempt < 20; ++attempt) {
      body->r = {data.uniform(-1, 1) * freeX, data.uniform(-1, 1) * freeY};
      bool clear = true;
      for (const Placed& other : placed)
        clear = clear && (body->r - other.centre).length() > extent + other.reach;
      if (overlapping || clear) break;
    }
    placed.push_back({body->r, extent});
    body->alpha = data.uniform(0, 6.3);
    // Bounded pushes: alone, the body would move at most its radius in a step (F = m v), and
    // turn its far end at most as far; the speculative contacts are made for that.
    const real speed = data.uniform(0, 1) * radius / dt;
    Push push;
    push.amplitude = {data.uniform(-1, 1) * body->m * speed, data.uniform(-1, 1) * body->m * speed};
    push.torque = data.uniform(-1, 1) * body->I * speed / extent;
    push.frequency = data.uniform(0, 10);
    push.phase = data.uniform(0, 6.3);
    push.body = &simulator.registerObject(std::move(body));
    pushes.push_back(push);
  }
  // Gravity, bounded likewise by the smallest radius.
  const Vector2 gravity{0, data.coin() ? -data.uniform(0, 1) * smallest / dt : real(0)};

  // The forces and gravity grow over the first steps, as smooth forces do, so that the
  // speculative margins (a tenth of a radius plus the last step's travel) see them coming.
  constexpr int ramp = 20;
  const int steps = data.integer(10, 200);
  const char* leakFolder = std::getenv("THYRIX_FUZZ_LEAK_FOLDER");
  bool leaked = false;
  for (int step = 0; step < steps; ++step) {
    const real t = simulator.time();
    const real grow = real(std::min(step, ramp)) / real(ramp);
    simulator.setGravity(gravity * grow);
    for (const Push& push : pushes) {
      const real s = std::sin(push.frequency * t + push.phase);
      const real c = std::cos(push.frequency * t + push.phase);
      push.body->externalForce = {push.amplitude.x * s * grow, push.amplitude.y * c * grow};
      push.body->externalTorque = push.torque * s * grow;
    }
    simulator.advanceTime();
    for (const thyrix::GlobalContactInfo& contact : simulator.contacts) {
      if (!(contact.force >= 0) || !std::isfinite(contact.force))
        fail("contact force negative or not finite", step, contact.bodyA, double(contact.force));
    }
    for (std::size_t i = 4; i < simulator.objects.size(); ++i) {
      const thyrix::PhysicalObject& object = simulator.objects[i];
      if (!std::isfinite(object.r.x) || !std::isfinite(object.r.y) || !std::isfinite(object.alpha))
        fail("pose not finite", step, i, double(object.r.x));
      if (!std::isfinite(object.v.x) || !std::isfinite(object.v.y) || !std::isfinite(object.omega))
        fail("velocity not finite", step, i, double(object.v.x));
      for (const thyrix::Primitive* primitive : object.primitives()) {
        Vector2 ends[2];
        axisOf(*primitive, ends[0], ends[1]);
        for (const Vector2 end : ends)
          for (int w = 0; w < 4; ++w) {
            // An axis point behind a wall: the shape overlaps it by more than its radius.
            const real inside = thyrix::dot(end - wallPoints[w], wallNormals[w]);
            if (inside < 0 && !leaked) {
              if (leakFolder == nullptr)
                fail("shape outside the box (leak through a border)", step, i, double(inside));
              saveInput(leakFolder, bytes, size);
              leaked = true;  // the other checks go on
            }
          }
      }
    }
  }
  return 0;
}
