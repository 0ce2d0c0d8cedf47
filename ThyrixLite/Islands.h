#pragma once
/// @file Islands.h
/// @brief Groups contacts into islands: sets of movable bodies linked by contacts.

#include <ThyrixLite/ContactSolver.h>

#include <cstdint>
#include <span>
#include <vector>

namespace thyrix {

/// Union-find over movable bodies, then a counting sort of the contacts by island. Fixed
/// bodies do not link islands (they never move). Islands come out in order of their first
/// contact and list their contacts in increasing order, so the result is reproducible.
class Islands {
 public:
  /// Groups @p rows; @p movable tells which bodies can move; @p bodies lists every body the
  /// rows name (each once), the only ones read (the work is proportional to the rows).
  void build(std::span<const ContactConstraint> rows, std::span<const std::uint8_t> movable,
             std::span<const std::uint32_t> bodies);

  /// Makes room for @p bodies bodies and @p rows contacts without further allocation.
  void reserve(std::size_t bodies, std::size_t rows);
  /// Number of islands found by the last build.
  [[nodiscard]] std::size_t count() const {
    return islandStart_.empty() ? 0 : islandStart_.size() - 1;
  }
  /// The contact indices of island @p i.
  [[nodiscard]] std::span<const std::uint32_t> island(std::size_t i) const {
    return std::span(contacts_).subspan(islandStart_[i], islandStart_[i + 1] - islandStart_[i]);
  }

 private:
  std::uint32_t find(std::uint32_t body);

  std::vector<std::uint32_t> parent_;        // union-find forest over bodies
  std::vector<std::uint32_t> islandOfBody_;  // dense island number of each root, or none
  std::vector<std::uint32_t> islandOfRow_;
  std::vector<std::uint32_t> islandStart_;
  std::vector<std::uint32_t> cursor_;
  std::vector<std::uint32_t> contacts_;
};

}  // namespace thyrix
