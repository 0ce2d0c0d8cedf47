#pragma once
/// @file BoundingBox.h
/// @brief Axis-aligned bounding boxes and the candidate pairs the broad phase finds among them.

#include <ThyrixLite/Vector2.h>

#include <cstdint>

namespace thyrix {

/// An axis-aligned bounding box.
struct BoundingBox {
  Vector2 lower;  ///< minimum corner
  Vector2 upper;  ///< maximum corner

  /// True when the two boxes overlap or touch.
  [[nodiscard]] bool overlaps(const BoundingBox& o) const {
    return lower.x <= o.upper.x && o.lower.x <= upper.x && lower.y <= o.upper.y &&
           o.lower.y <= upper.y;
  }
};

/// A candidate pair of box indices, `first < second`.
struct BoxPair {
  std::uint32_t first;   ///< lower index
  std::uint32_t second;  ///< higher index
};

}  // namespace thyrix
