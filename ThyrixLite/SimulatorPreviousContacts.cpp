/// @file SimulatorPreviousContacts.cpp
/// @brief The last step's contacts, found by shape pair: what rest skipping reuses and where
/// the warm start finds each contact's last force.
#include <ThyrixLite/Simulator.h>

#include <algorithm>

namespace thyrix {

namespace {

/// A pair of shapes as one number, ordered by shape A, then shape B.
std::uint64_t pairKey(std::uint32_t shapeA, std::uint32_t shapeB) {
  return std::uint64_t{shapeA} << 32 | shapeB;
}

}  // namespace

void Simulator::indexPreviousContacts() {
  // A counting sort by shape A (a pair's points stay in order), then a stable insertion by
  // shape B within each shape A: the contacts mostly come so already (a border's follow the
  // shapes' order). A pair is then found by binary search, so that a shape with many contacts
  // (a floor under a crowd) costs a logarithm, not a scan. The pairs are kept as numbers
  // beside the positions, for the searches.
  // The contacts are read once, their pairs copied to previousKeys_ for the second pass (a
  // contact is as long as a cache line and more: a second pass over them cost as much again).
  const std::size_t count = previousContacts_.size();
  previousStart_.assign(shapes_.size() + 1, 0);
  previousKeys_.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const GlobalContactInfo& c = previousContacts_[k];
    ++previousStart_[c.shapeA + 1];
    previousKeys_[k] = pairKey(c.shapeA, c.shapeB);
  }
  for (std::size_t s = 0; s < shapes_.size(); ++s) previousStart_[s + 1] += previousStart_[s];
  previousOrder_.resize(count);
  previousPairs_.resize(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint64_t key = previousKeys_[k];
    const std::uint32_t i = previousStart_[key >> 32]++;
    previousOrder_[i] = k;
    previousPairs_[i] = key;
  }
  // The largest pair so far stays in a register: an entry already in place (most) is neither
  // stored back nor read again (measured: the store of each entry, read back by the next
  // one's comparison, made the loop wait on memory).
  std::uint64_t* const pairs = previousPairs_.data();
  std::uint32_t* const order = previousOrder_.data();
  std::uint64_t largest = count > 0 ? pairs[0] : 0;
  for (std::size_t i = 1; i < count; ++i) {
    const std::uint64_t pair = pairs[i];
    if (pair >= largest) {
      largest = pair;
      continue;
    }
    const std::uint32_t position = order[i];
    std::size_t j = i;
    for (; j > 0 && pairs[j - 1] > pair; --j) {
      order[j] = order[j - 1];
      pairs[j] = pairs[j - 1];
    }
    order[j] = position;
    pairs[j] = pair;
  }
  previousCursor_ = 0;
  previousIndexed_ = true;
}

std::span<const std::uint32_t> Simulator::previousContactsOf(std::uint32_t shapeA,
                                                             std::uint32_t shapeB) {
  if (!previousIndexed_) indexPreviousContacts();
  const std::uint64_t pair = pairKey(shapeA, shapeB);
  const std::uint64_t* const pairs = previousPairs_.data();
  const std::size_t count = previousPairs_.size();
  // Pairs come in nearly the last step's order (a border's with the shapes in order): the
  // pair's contacts usually begin where the last pair's ended. Else a binary search.
  std::size_t first = previousCursor_;
  if (!(first < count && pairs[first] == pair && (first == 0 || pairs[first - 1] < pair)))
    first = static_cast<std::size_t>(std::lower_bound(pairs, pairs + count, pair) - pairs);
  std::size_t last = first;
  while (last < count && pairs[last] == pair) ++last;
  previousCursor_ = last;
  return std::span(previousOrder_).subspan(first, last - first);
}

real Simulator::previousForce(const GlobalContactInfo& contact, std::size_t position,
                              std::size_t& hint) {
  const auto same = [&contact](const GlobalContactInfo& previous) {
    return previous.shapeA == contact.shapeA && previous.shapeB == contact.shapeB &&
           previous.feature == contact.feature;
  };
  // Detection lists the contacts in nearly the last step's order: the one after the last
  // found, then the one at the same place, before a search.
  for (const std::size_t guess : {hint, position}) {
    if (guess < previousContacts_.size() && same(previousContacts_[guess])) {
      hint = guess + 1;
      return previousContacts_[guess].force;
    }
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
