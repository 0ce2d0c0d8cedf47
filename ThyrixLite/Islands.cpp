#include <ThyrixLite/Islands.h>

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

void Islands::build(std::span<const ContactConstraint> rows, std::span<const std::uint8_t> movable,
                    std::span<const std::uint32_t> bodies) {
  constexpr std::uint32_t none = ~0u;
  const auto bodyCount = static_cast<std::uint32_t>(movable.size());
  if (parent_.size() < bodyCount) {
    parent_.resize(bodyCount);
    islandOfBody_.resize(bodyCount);
  }
  for (const std::uint32_t body : bodies) {
    parent_[body] = body;
    islandOfBody_[body] = none;
  }
  for (const ContactConstraint& row : rows) {
    if (!movable[row.a] || !movable[row.b]) continue;
    std::uint32_t rootA = find(row.a);
    std::uint32_t rootB = find(row.b);
    if (rootA == rootB) continue;
    if (rootB < rootA) std::swap(rootA, rootB);
    parent_[rootB] = rootA;
  }

  // Number the islands in order of their first contact (the contact order is reproducible).
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
