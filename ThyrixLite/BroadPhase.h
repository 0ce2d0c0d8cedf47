#pragma once
/// @file BroadPhase.h
/// @brief Finds the pairs of overlapping bounding boxes in near-linear time.

#include <ThyrixLite/Vector2.h>

#include <cstdint>
#include <span>
#include <vector>

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

/// A uniform grid rebuilt every step by counting sort into hashed cells.
///
/// The cell side is twice the mean box size; a box larger than a cell is "oversized" and is
/// tested against all boxes (few such boxes keep this linear). Every other box lies in one cell
/// (by its centre) and can only overlap boxes in the 3 x 3 neighbouring cells. The output order
/// depends only on the input, so runs are reproducible. Buffers are kept between calls: once
/// warmed up, finding pairs allocates nothing.
class BroadPhase {
 public:
  /// Up to this many boxes, every pair is tested directly.
  static constexpr std::uint32_t smallCount = 48;

  /// Replaces @p pairs with every overlapping pair of @p boxes.
  void findPairs(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs);

 private:
  std::vector<std::uint32_t> cellOfBox_;     // hashed cell of each regular box
  std::vector<std::int64_t> cellX_, cellY_;  // integer cell coordinates of each regular box
  std::vector<std::uint32_t> bucketStart_;   // counting-sort offsets, one per hash bucket + 1
  std::vector<std::uint32_t> bucketCursor_;  // fill position of each bucket during the sort
  std::vector<std::uint32_t> sortedBoxes_;   // regular boxes grouped by bucket, by index within
  std::vector<std::uint32_t> oversized_;     // boxes larger than a cell
};

}  // namespace thyrix
