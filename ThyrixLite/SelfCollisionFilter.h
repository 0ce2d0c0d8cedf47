#pragma once
/// @file SelfCollisionFilter.h
/// @brief Which primitives of one multi-body object may touch each other, as a table the
/// simulator reads inline for every candidate pair (no virtual call per pair).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace thyrix {

/// The self-collision rules of a multi-body object (MultiBodyObject), declared once when the
/// object is built: each of its primitives belongs to a part (for an articulated agent: the
/// base or one link), two primitives of one part never touch, nor do those of two parts declared
/// apart (a link and its parent, which overlap around their joint by construction); every other
/// pair of its primitives may touch.
///
/// A chain of n links has about n candidate pairs of neighbours in every step, which must be
/// dropped before the narrow phase: mayTouch() is inline and reads a few integers (the parts
/// declared apart from a part are listed next to each other), where a virtual call per pair
/// used to decide. Without assign(), every pair of different primitives may touch.
class SelfCollisionFilter {
 public:
  // Copies only, no moves (a moved-from filter would keep a stamp its rules no longer
  // match): the rules are set once per object.

  /// A filter without rules: every pair of different primitives may touch.
  SelfCollisionFilter() = default;
  /// A filter with the rules of @p other, and its stamp (the same rules).
  SelfCollisionFilter(const SelfCollisionFilter& other) = default;
  /// Takes the rules of @p other, with a stamp new for this filter (see stamp()); unchanged if
  /// the copy fails.
  SelfCollisionFilter& operator=(const SelfCollisionFilter& other);
  ~SelfCollisionFilter() = default;

  /// Sets the rules: primitive k (in the object's `primitives()` order) belongs to part
  /// `partOf[k]` (one entry per primitive), and the parts of each pair in @p apart never touch
  /// (either order; a pair may repeat). Part numbers are small: the table has one entry per
  /// part up to the largest.
  void assign(std::span<const std::uint32_t> partOf,
              std::span<const std::pair<std::uint32_t, std::uint32_t>> apart);

  /// Whether the object's primitives number @p a and @p b (in `primitives()` order) may touch.
  [[nodiscard]] bool mayTouch(std::size_t a, std::size_t b) const {
    if (partOf_.empty()) return a != b;
    // Primitives near each other in the order (a chain's neighbouring links, the pairs asked
    // about in every step) are answered by one bit; the others by their parts' lists.
    const std::size_t low = std::min(a, b);
    const std::size_t gap = std::max(a, b) - low;
    if (gap - 1 < nearRange) return ((apartNear_[low] >> (gap - 1)) & 1) == 0;
    // assign() gave every part of a primitive its list: no range check.
    return listedPartsMayTouch(partOf_[a], partOf_[b]);
  }

  /// Bit `d - 1` set when mayTouch(k, k + d) is false, for d = 1 to 64 and k + d one of the
  /// object's primitives (the other bits are 0): the pairs of primitive @p k with those after
  /// it that never touch, in one word.
  [[nodiscard]] std::uint64_t apartAfter(std::size_t k) const {
    return partOf_.empty() ? 0 : apartNear_[k];
  }

  /// Whether primitives of parts @p a and @p b may touch: not within one part, nor between
  /// parts declared apart.
  [[nodiscard]] bool partsMayTouch(std::uint32_t a, std::uint32_t b) const {
    if (a + std::size_t{1} >= apartStart_.size()) return a != b;  // none declared apart from a
    return listedPartsMayTouch(a, b);
  }

  /// Counts this filter's changes: 0 before the first, larger after every assign() or
  /// assignment from another filter (a copy starts at its source's). A reader that kept what
  /// this filter's rules said (the simulator's broad phase) knows whether they changed. Its own
  /// history only, no counter shared by the program: the same program gives the same stamps,
  /// however many simulators run around it.
  [[nodiscard]] std::uint64_t stamp() const { return stamp_; }

  /// The part of primitive @p k (in `primitives()` order); k itself before assign().
  [[nodiscard]] std::uint32_t partOf(std::size_t k) const {
    return partOf_.empty() ? static_cast<std::uint32_t>(k) : partOf_[k];
  }

 private:
  // partsMayTouch() for a part @p a that has a list.
  [[nodiscard]] bool listedPartsMayTouch(std::uint32_t a, std::uint32_t b) const {
    if (a == b) return false;
    for (std::uint32_t k = apartStart_[a]; k < apartStart_[a + 1]; ++k)
      if (apart_[k] == b) return false;
    return true;
  }

  /// How far apart in the order two primitives may be for apartNear_ to answer.
  static constexpr std::size_t nearRange = 64;
  std::vector<std::uint32_t> partOf_;  // per primitive
  // Per primitive k, bit d - 1 set when k and k + d (d = 1 to nearRange) never touch: what
  // listedPartsMayTouch() says of their parts, read with one load.
  std::vector<std::uint64_t> apartNear_;
  std::vector<std::uint32_t> apartStart_;  // per part + 1: where its list in apart_ begins
  std::vector<std::uint32_t> apart_;       // per part, the parts it never touches
  std::uint64_t stamp_ = 0;                // see stamp()
};

}  // namespace thyrix
