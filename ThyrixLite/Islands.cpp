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
  // Both passes keep the count or cursor of the island of the last row in a register: rows
  // mostly follow rows of the same island (a pile is one), and an increment in memory at each
  // row made each row wait for the last one's store.
  // The starts are sized for one island per row, the most there can be, and only grow: a new
  // island then costs a store, not a push_back (in a small world most rows are islands of
  // their own); count() is kept apart.
  const std::size_t rowCount = islandOfRow_.size();
  if (islandStart_.size() < rowCount + 2) islandStart_.resize(rowCount + 2);
  std::uint32_t* const start = islandStart_.data();
  std::uint32_t* const parent = parent_.data();
  std::uint32_t* const islandOfRow = islandOfRow_.data();
  std::uint32_t* const islandOfBody = islandOfBody_.data();
  start[0] = start[1] = 0;
  std::uint32_t islandCount = 0;
  std::uint32_t current = 0;  // the island whose count is in `run` (its entry is stale)
  std::uint32_t run = 0;
  for (std::size_t k = 0; k < rowCount; ++k) {
    const std::uint32_t root = find(parent, islandOfRow[k]);
    if (islandOfBody[root] == none) {
      islandOfBody[root] = islandCount;
      start[islandCount + 2] = 0;
      ++islandCount;
    }
    const std::uint32_t island = islandOfBody[root];
    islandOfRow[k] = island;
    if (island != current) {
      start[current + 2] = run;
      current = island;
      run = start[island + 2];
    }
    ++run;
  }
  if (rowCount != 0) start[current + 2] = run;
  for (std::uint32_t i = 0; i < islandCount; ++i) start[i + 2] += start[i + 1];
  contacts_.resize(rowCount);
  std::uint32_t* const contacts = contacts_.data();
  current = 0;
  std::uint32_t cursor = start[1];
  for (std::size_t k = 0; k < rowCount; ++k) {
    const std::uint32_t island = islandOfRow[k];
    if (island != current) {
      start[current + 1] = cursor;
      current = island;
      cursor = start[island + 1];
    }
    contacts[cursor++] = static_cast<std::uint32_t>(k);
  }
  if (rowCount != 0) start[current + 1] = cursor;
  islandCount_ = islandCount;  // (the entry one late is not one of the islandCount + 1 starts)
}

}  // namespace thyrix
