#include "Scenes.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <Tools/MTRandom.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace thyrix::scenes {

void addWalls(Simulator& simulator, real width, real height) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, height}, Vector2{0, -1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
  simulator.registerObject(std::make_unique<Border>(Vector2{width, 0}, Vector2{-1, 0}));
}

std::vector<PhysicalObject*> addRandomCircles(Simulator& simulator, int count, real radius,
                                              real size, std::uint32_t seed) {
  MTRandom random(seed);
  std::vector<PhysicalObject*> circles;
  std::vector<Vector2> placed;
  for (const PhysicalObject& object : simulator.objects)
    if (!object.fixed) placed.push_back(object.r);
  int attempts = 0;
  while (static_cast<int>(circles.size()) < count && attempts++ < 100000) {
    const Vector2 p{static_cast<real>(random.uniform(radius, size - radius)),
                    static_cast<real>(random.uniform(radius, size - radius))};
    // Keep clear of every body placed so far (bodies are assumed no larger than 2 radii).
    if (std::any_of(placed.begin(), placed.end(),
                    [&](Vector2 q) { return distance(p, q) < 4 * radius; }))
      continue;
    placed.push_back(p);
    auto& circle = simulator.registerObject(std::make_unique<Circle>(radius, real(1)));
    circle.r = p;
    circles.push_back(&circle);
  }
  return circles;
}

std::vector<PhysicalObject*> addPile(Simulator& simulator, int count, std::uint32_t seed,
                                     int columns) {
  MTRandom random(seed);
  if (columns <= 0) columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const real pitch = real(1.2);
  const real width = pitch * static_cast<real>(columns) + real(0.2);
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{-real(0.1), 0}, Vector2{1, 0}));
  simulator.registerObject(std::make_unique<Border>(Vector2{width, 0}, Vector2{-1, 0}));
  std::vector<PhysicalObject*> circles;
  for (int i = 0; i < count; ++i) {
    auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    const int row = i / columns;
    const int column = i % columns;
    circle.r = {pitch * (static_cast<real>(column) + real(0.5)) +
                    static_cast<real>(random.uniform(-0.1, 0.1)),
                real(0.5) + pitch * static_cast<real>(row)};
    circles.push_back(&circle);
  }
  return circles;
}

std::vector<PhysicalObject*> addMixedPile(Simulator& simulator, int count, std::uint32_t seed) {
  MTRandom random(seed);
  addWalls(simulator, 6, 6);
  std::vector<PhysicalObject*> bodies;
  for (int i = 0; i < count; ++i) {
    PhysicalObject* body = nullptr;
    if (i % 3 == 2) {
      body = &simulator.registerObject(std::make_unique<CappedRectangle>(
          real(0.3), real(0.15), static_cast<real>(random.uniform(0.5, 2.0))));
    } else {
      body = &simulator.registerObject(
          std::make_unique<Circle>(static_cast<real>(random.uniform(0.15, 0.3)),
                                   static_cast<real>(random.uniform(0.5, 2.0))));
    }
    body->r = {static_cast<real>(random.uniform(0.4, 2.6)),
               static_cast<real>(random.uniform(0.4, 2.6))};
    body->alpha = static_cast<real>(random.uniform(-3.14, 3.14));
    bodies.push_back(body);
  }
  return bodies;
}

void push(const std::vector<PhysicalObject*>& bodies, Vector2 force) {
  for (PhysicalObject* body : bodies) body->externalForce += force * body->m;
}

std::uint64_t stateHash(const Simulator& simulator) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto mix = [&hash](real value) {
    unsigned char bytes[sizeof(real)];
    std::memcpy(bytes, &value, sizeof(real));
    for (const unsigned char byte : bytes) {
      hash ^= byte;
      hash *= 1099511628211ull;
    }
  };
  for (const PhysicalObject& object : simulator.objects) {
    mix(object.r.x);
    mix(object.r.y);
    mix(object.alpha);
    mix(object.v.x);
    mix(object.v.y);
    mix(object.omega);
  }
  return hash;
}

real largestOverlap(const Simulator& simulator) {
  real overlap = 0;
  for (const GlobalContactInfo& contact : simulator.contacts)
    overlap = std::max(overlap, contact.depth);
  return overlap;
}

}  // namespace thyrix::scenes
