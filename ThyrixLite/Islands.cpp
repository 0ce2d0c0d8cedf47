#include <ThyrixLite/Islands.h>

namespace thyrix {

void Islands::reserve(std::size_t bodies, std::size_t rows) {
  parent_.reserve(bodies);
  rank_.reserve(bodies);
  islandOfBody_.reserve(bodies);
  islandOfRow_.reserve(rows);
  islandStart_.reserve(rows + 2);
  contacts_.reserve(rows);
}

Islands::Adder Islands::start(std::size_t bodies, std::size_t rows) {
  if (parent_.size() < bodies) {
    parent_.resize(bodies);
    rank_.resize(bodies);
    islandOfBody_.resize(bodies);
  }
  islandOfRow_.resize(rows);
  return {parent_.data(), rank_.data(), islandOfBody_.data(), islandOfRow_.data()};
}

void Islands::finish() {
  // Number the islands in order of their first contact (the contact order is reproducible),
  // counting each island's rows as they are numbered. Counts are kept one entry late (island
  // i's count at i + 2), so that the fill's cursors are islandStart_ itself: island i's cursor
  // is entry i + 1, which ends as its end, the start of island i + 1.
  const std::size_t rowCount = islandOfRow_.size();
  std::uint32_t* const islandOfRow = islandOfRow_.data();
  std::uint32_t* const islandOfBody = islandOfBody_.data();
  islandStart_.assign(2, 0);
  std::uint32_t islandCount = 0;
  for (std::size_t k = 0; k < rowCount; ++k) {
    const std::uint32_t root = find(parent_.data(), islandOfRow[k]);
    if (islandOfBody[root] == none) {
      islandOfBody[root] = islandCount++;
      islandStart_.push_back(0);
    }
    const std::uint32_t island = islandOfBody[root];
    islandOfRow[k] = island;
    ++islandStart_[island + 2];
  }
  std::uint32_t* const start = islandStart_.data();
  for (std::uint32_t i = 0; i < islandCount; ++i) start[i + 2] += start[i + 1];
  contacts_.resize(rowCount);
  for (std::size_t k = 0; k < rowCount; ++k)
    contacts_[start[islandOfRow[k] + 1]++] = static_cast<std::uint32_t>(k);
  islandStart_.pop_back();  // the entry one late: islandCount + 1 starts remain
}

}  // namespace thyrix
