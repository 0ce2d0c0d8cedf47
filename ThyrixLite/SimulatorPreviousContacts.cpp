/// @file SimulatorPreviousContacts.cpp
/// @brief The last step's contacts, found by shape pair: what rest skipping reuses and where
/// the warm start finds each contact's last force.
#include <ThyrixLite/Simulator.h>

#include <algorithm>

namespace thyrix {

namespace {

/// A shape A with up to this many of the last step's contacts has its pairs found by a scan;
/// above, they are sorted by shape B and found by a binary search.
constexpr std::size_t scannedGroup = 8;

/// A pair of shapes as one number, ordered by shape A, then shape B.
std::uint64_t pairKey(std::uint32_t shapeA, std::uint32_t shapeB) {
  return std::uint64_t{shapeA} << 32 | shapeB;
}

}  // namespace

void Simulator::indexPreviousContacts() {
  // A counting sort by shape A (stable: a pair's points stay together, in order). Within a
  // shape A, a pair is found by a scan; only a shape A with many contacts (a floor under a
  // crowd), whose search would otherwise be a long scan, is also sorted by shape B, for a
  // binary search. (A circle's few pairs come in no order: sorting them all cost a
  // mispredicted branch per contact, a third of the function.)
  // The contacts are read once, their pairs copied to previousListKeys_ for the second pass (a
  // contact is as long as a cache line and more: a second pass over them cost as much again).
  // Counts are kept one entry late, so that the fill's cursors are previousStart_ itself:
  // shape A's group is then previousStart_[A] to previousStart_[A + 1].
  const std::size_t count = previousContacts_.size();
  const std::size_t shapes = shapes_.size();
  previousStart_.assign(shapes + 2, 0);
  previousListKeys_.resize(count);
  std::uint32_t* const start = previousStart_.data();
  for (std::size_t k = 0; k < count; ++k) {
    const GlobalContactInfo& c = previousContacts_[k];
    ++start[c.shapeA + 2];
    previousListKeys_[k] = pairKey(c.shapeA, c.shapeB);
  }
  for (std::size_t s = 0; s < shapes; ++s) start[s + 2] += start[s + 1];
  previousOrder_.resize(count);
  previousSortedKeys_.resize(count);
  std::uint64_t* const pairs = previousSortedKeys_.data();
  std::uint32_t* const order = previousOrder_.data();
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint64_t key = previousListKeys_[k];
    const std::uint32_t i = start[(key >> 32) + 1]++;
    order[i] = k;
    pairs[i] = key;
  }
  for (std::size_t s = 0; s < shapes; ++s) {
    if (start[s + 1] - start[s] <= scannedGroup) continue;
    // A stable insertion by shape B. The largest pair so far stays in a register: an entry
    // already in place (most: a border's contacts follow the shapes' order) is neither stored
    // back nor read again.
    const std::size_t begin = start[s];
    std::uint64_t largest = pairs[begin];
    for (std::size_t i = begin + 1; i < start[s + 1]; ++i) {
      const std::uint64_t pair = pairs[i];
      if (pair >= largest) {
        largest = pair;
        continue;
      }
      const std::uint32_t position = order[i];
      std::size_t j = i;
      for (; j > begin && pairs[j - 1] > pair; --j) {
        order[j] = order[j - 1];
        pairs[j] = pairs[j - 1];
      }
      order[j] = position;
      pairs[j] = pair;
    }
  }
  previousCursor_ = 0;
  previousIndexed_ = true;
}

std::span<const std::uint32_t> Simulator::previousContactsOf(std::uint32_t shapeA,
                                                             std::uint32_t shapeB) {
  if (!previousIndexed_) indexPreviousContacts();
  const std::uint64_t pair = pairKey(shapeA, shapeB);
  const std::uint64_t* const pairs = previousSortedKeys_.data();
  const std::size_t count = previousSortedKeys_.size();
  // Pairs come in nearly the last step's order (a border's with the shapes in order): the
  // pair's contacts usually begin where the last pair's ended (a pair's entries are
  // consecutive). Else a scan of shape A's group, or a binary search of a large one.
  std::size_t first = previousCursor_;
  if (!(first < count && pairs[first] == pair && (first == 0 || pairs[first - 1] != pair))) {
    const std::size_t begin = previousStart_[shapeA];
    const std::size_t end = previousStart_[shapeA + 1];
    if (end - begin > scannedGroup) {
      first = static_cast<std::size_t>(std::lower_bound(pairs + begin, pairs + end, pair) - pairs);
    } else {
      first = begin;
      while (first < end && pairs[first] != pair) ++first;
    }
  }
  std::size_t last = first;
  while (last < count && pairs[last] == pair) ++last;
  previousCursor_ = last;
  return std::span(previousOrder_).subspan(first, last - first);
}

real Simulator::searchPreviousForce(const GlobalContactInfo& contact, std::size_t position,
                                    std::size_t& hint) {
  // Detection lists the contacts in nearly the last step's order: after the contact after the
  // last found (solveIsland()), the one at the same place, before a search.
  if (position < previousContacts_.size() && previousContacts_[position].sameContactAs(contact)) {
    hint = position + 1;
    return previousContacts_[position].force;
  }
  for (const std::uint32_t k : previousContactsOf(contact.shapeA, contact.shapeB)) {
    if (previousContacts_[k].feature == contact.feature) {
      hint = std::size_t{k} + 1;
      return previousContacts_[k].force;
    }
  }
  return 0;
}

}  // namespace thyrix
