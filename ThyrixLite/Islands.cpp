#include <ThyrixLite/Islands.h>

#include <numeric>

namespace thyrix {

std::uint32_t Islands::find(std::uint32_t body) {
  while (parent_[body] != body) {
    parent_[body] = parent_[parent_[body]];  // path halving
    body = parent_[body];
  }
  return body;
}

void Islands::reserve(std::size_t bodies, std::size_t rows) {
  parent_.reserve(bodies);
  islandOfBody_.reserve(bodies);
  islandOfRow_.reserve(rows);
  islandStart_.reserve(rows + 1);
  cursor_.reserve(rows + 1);
  contacts_.reserve(rows);
}

void Islands::build(std::span<const ContactConstraint> rows,
                    std::span<const std::uint8_t> movable) {
  const auto bodyCount = static_cast<std::uint32_t>(movable.size());
  parent_.resize(bodyCount);
  std::iota(parent_.begin(), parent_.end(), 0u);
  for (const ContactConstraint& row : rows) {
    if (!movable[row.a] || !movable[row.b]) continue;
    std::uint32_t rootA = find(row.a);
    std::uint32_t rootB = find(row.b);
    if (rootA == rootB) continue;
    if (rootB < rootA) std::swap(rootA, rootB);
    parent_[rootB] = rootA;
  }

  // Number the islands in order of their first contact (the contact order is reproducible).
  constexpr std::uint32_t none = ~0u;
  islandOfBody_.assign(bodyCount, none);
  islandOfRow_.resize(rows.size());
  std::uint32_t islandCount = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const ContactConstraint& row = rows[k];
    const std::uint32_t root = find(movable[row.a] ? row.a : row.b);
    if (islandOfBody_[root] == none) islandOfBody_[root] = islandCount++;
    islandOfRow_[k] = islandOfBody_[root];
  }
  islandStart_.assign(islandCount + 1, 0);
  for (const std::uint32_t island : islandOfRow_) ++islandStart_[island + 1];
  for (std::uint32_t i = 0; i < islandCount; ++i) islandStart_[i + 1] += islandStart_[i];
  cursor_.assign(islandStart_.begin(), islandStart_.end() - 1);
  contacts_.resize(rows.size());
  for (std::uint32_t k = 0; k < rows.size(); ++k) contacts_[cursor_[islandOfRow_[k]]++] = k;
}

}  // namespace thyrix
