#include <ThyrixLite/BroadPhase.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace thyrix {
namespace {

std::uint32_t hashCell(std::int64_t x, std::int64_t y, std::uint32_t mask) {
  const auto h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                 static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full;
  return static_cast<std::uint32_t>(h >> 32) & mask;
}

real extent(const BoundingBox& box) {
  return std::max(box.upper.x - box.lower.x, box.upper.y - box.lower.y);
}

constexpr std::uint32_t oversizedMark = ~0u;

}  // namespace

void BroadPhase::findPairs(std::span<const BoundingBox> boxes, std::vector<BoxPair>& pairs) {
  pairs.clear();
  const auto count = static_cast<std::uint32_t>(boxes.size());
  if (count < 2) return;
  // Few boxes: testing every pair is cheaper than building the grid (measured: a 22-body
  // arena spent a quarter of its step in the grid).
  if (count <= smallCount) {
    for (std::uint32_t i = 0; i < count; ++i)
      for (std::uint32_t j = i + 1; j < count; ++j)
        if (boxes[i].overlaps(boxes[j])) pairs.push_back({i, j});
    return;
  }

  // Cells as small as the largest box allows (about one box per cell for similar sizes), but
  // no larger than twice the mean: rare big boxes are handled as oversized instead.
  real meanExtent = 0;
  real maxExtent = 0;
  for (const BoundingBox& box : boxes) {
    meanExtent += extent(box);
    maxExtent = std::max(maxExtent, extent(box));
  }
  meanExtent /= static_cast<real>(count);
  const real cellSize = std::max(std::min(maxExtent, 2 * meanExtent), realEpsilon);

  std::uint32_t bucketCount = 1;
  while (bucketCount < 2 * count) bucketCount <<= 1;
  const std::uint32_t mask = bucketCount - 1;

  // Cells of the regular boxes, and the bucket sizes.
  cellOfBox_.resize(count);
  cellX_.resize(count);
  cellY_.resize(count);
  bucketStart_.assign(bucketCount + 1, 0);
  oversized_.clear();
  for (std::uint32_t i = 0; i < count; ++i) {
    const BoundingBox& box = boxes[i];
    if (extent(box) > cellSize) {
      cellOfBox_[i] = oversizedMark;
      oversized_.push_back(i);
      continue;
    }
    const Vector2 centre = (box.lower + box.upper) * real(0.5);
    cellX_[i] = static_cast<std::int64_t>(std::floor(centre.x / cellSize));
    cellY_[i] = static_cast<std::int64_t>(std::floor(centre.y / cellSize));
    cellOfBox_[i] = hashCell(cellX_[i], cellY_[i], mask);
    ++bucketStart_[cellOfBox_[i] + 1];
  }
  for (std::uint32_t b = 0; b < bucketCount; ++b) bucketStart_[b + 1] += bucketStart_[b];

  // Counting sort in index order, so each bucket lists its boxes by increasing index.
  bucketCursor_.assign(bucketStart_.begin(), bucketStart_.end() - 1);
  sortedBoxes_.resize(bucketStart_[bucketCount]);
  for (std::uint32_t i = 0; i < count; ++i)
    if (cellOfBox_[i] != oversizedMark) sortedBoxes_[bucketCursor_[cellOfBox_[i]]++] = i;

  // Regular pairs. A box can only overlap boxes whose centres lie in the 3 x 3 cells around
  // its own; visiting its own cell (higher indices only) and the four "forward" cells (all
  // boxes) meets every such pair exactly once. A bucket may hold other cells' boxes (hash
  // collisions): the cell coordinates are compared, so nothing is paired twice.
  constexpr std::int64_t forward[4][2] = {{1, -1}, {1, 0}, {1, 1}, {0, 1}};
  for (std::uint32_t i = 0; i < count; ++i) {
    if (cellOfBox_[i] == oversizedMark) continue;
    const std::int64_t x = cellX_[i];
    const std::int64_t y = cellY_[i];
    const std::uint32_t own = cellOfBox_[i];
    for (std::uint32_t k = bucketStart_[own]; k < bucketStart_[own + 1]; ++k) {
      const std::uint32_t j = sortedBoxes_[k];
      if (j > i && cellX_[j] == x && cellY_[j] == y && boxes[i].overlaps(boxes[j]))
        pairs.push_back({i, j});
    }
    for (const auto& [dx, dy] : forward) {
      const std::uint32_t bucket = hashCell(x + dx, y + dy, mask);
      for (std::uint32_t k = bucketStart_[bucket]; k < bucketStart_[bucket + 1]; ++k) {
        const std::uint32_t j = sortedBoxes_[k];
        if (cellX_[j] == x + dx && cellY_[j] == y + dy && boxes[i].overlaps(boxes[j]))
          pairs.push_back({std::min(i, j), std::max(i, j)});
      }
    }
  }

  // Oversized boxes against everything (each pair once).
  for (const std::uint32_t big : oversized_) {
    for (std::uint32_t j = 0; j < count; ++j) {
      if (j == big || (cellOfBox_[j] == oversizedMark && j < big)) continue;
      if (boxes[big].overlaps(boxes[j])) pairs.push_back({std::min(big, j), std::max(big, j)});
    }
  }
}

}  // namespace thyrix
