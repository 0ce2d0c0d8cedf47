/// @file SimulatorPreviousContacts.cpp
/// @brief The last step's contacts, found by shape pair: what rest skipping reuses and where
/// the warm start finds each contact's last force.
#include <ThyrixLite/Simulator.h>

#include <algorithm>

namespace thyrix {

namespace {

/// A shape A with up to this many of the last step's contacts in the index has its pairs
/// found by a scan; above, they are sorted by shape B and found by a binary search.
constexpr std::size_t scannedGroup = 8;

/// A shape A with up to this many pairs in the last step's list has them found by a walk of
/// its chain; above (a floor under a crowd), by a binary search: of the list where its
/// contacts are consecutive and in order, else of the index.
constexpr std::uint32_t chainedPairs = 16;

/// PairChain::pairsAndRun's pair count.
constexpr std::uint32_t pairCountMask = (1u << 30) - 1;

}  // namespace

void Simulator::indexPreviousContacts() {
  // A counting sort by shape A (stable: a pair's points stay together, in order), then by
  // shape B within each shape A with more than scannedGroup contacts. Built only when a shape
  // with more than chainedPairs pairs is looked up (others walk their chains), from the pairs
  // noted at detection (not from the contacts: a contact is as long as a cache line and more).
  // Counts are kept one entry late, so that the fill's cursors are previousStart_ itself:
  // shape A's group is then previousStart_[A] to previousStart_[A + 1].
  const std::size_t count = previousContacts_.size();
  const std::size_t shapes = shapes_.size();
  previousStart_.assign(shapes + 2, 0);
  std::uint32_t* const start = previousStart_.data();
  const ContactPair* const list = previousPairs_.data();
  for (std::size_t k = 0; k < count; ++k) ++start[(list[k].key >> 32) + 2];
  for (std::size_t s = 0; s < shapes; ++s) start[s + 2] += start[s + 1];
  previousOrder_.resize(count);
  previousSortedKeys_.resize(count);
  std::uint64_t* const pairs = previousSortedKeys_.data();
  std::uint32_t* const order = previousOrder_.data();
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint64_t key = list[k].key;
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
  previousIndexed_ = true;
}

void Simulator::nextListStamp() {
  // A new stamp for the pairs this detection notes: a list's chains are those of its stamp.
  if (++listStamp_ != 0) return;
  // Wrapped around (after 2^32 detections): the chains of the last list are given stamp 1,
  // every other chain 0, and this detection 2, so no old chain can pass for a current one.
  for (PairChain& chain : pairChains_) chain.stamp = 0;
  for (PairChain& chain : previousChains_)
    chain.stamp = chain.stamp == previousListStamp_ && previousListStamp_ != 0 ? 1 : 0;
  previousListStamp_ = previousListStamp_ != 0 ? 1 : 0;
  listStamp_ = 2;
}

bool Simulator::sortedRun(PairChain& chain, std::uint32_t shapeA) {
  // Looked at once a step (the answer is kept in the chain): from the chain's first contact to
  // its last pair's, every contact is shape A's, and the pairs only increase.
  constexpr std::uint32_t runShift = 30;
  if (chain.pairsAndRun >> runShift == 0) {
    const ContactPair* const list = previousPairs_.data();
    bool sorted = true;
    for (std::uint32_t k = chain.first; k < chain.last && sorted; ++k)
      sorted = list[k].key <= list[k + 1].key && list[k + 1].key >> 32 == shapeA;
    chain.pairsAndRun |= (sorted ? 1u : 2u) << runShift;
  }
  return chain.pairsAndRun >> runShift == 1;
}

std::size_t Simulator::findPreviousPair(std::uint64_t key, std::uint32_t shapeA) {
  // Not where the last pair's contacts ended: a scan of a short list, else a walk of shape
  // A's chain, or a binary search for a shape with many pairs.
  const ContactPair* const list = previousPairs_.data();
  const std::size_t count = previousCount_;
  if (count <= scannedListLength) {  // a short list, not chained: a scan
    for (std::size_t k = 0; k < count; ++k)
      if (list[k].key == key) return k;
    return count;
  }
  std::size_t first = count;  // none, unless found
  PairChain& chain = previousChains_[shapeA];
  if (chain.stamp != previousListStamp_) {
    // shape A is no shape A of the last step's list
  } else if ((chain.pairsAndRun & pairCountMask) <= chainedPairs) {
    for (std::uint32_t k = chain.first; k != noPair; k = list[k].nextOfA) {
      if (list[k].key == key) {
        first = k;
        break;
      }
    }
  } else if (sortedRun(chain, shapeA)) {
    const auto byKey = [](const ContactPair& pair, std::uint64_t value) {
      return pair.key < value;
    };
    const ContactPair* const end = list + chain.last + 1;
    const ContactPair* const found = std::lower_bound(list + chain.first, end, key, byKey);
    if (found != end && found->key == key) first = static_cast<std::size_t>(found - list);
  } else {
    if (!previousIndexed_) indexPreviousContacts();
    const std::uint64_t* const pairs = previousSortedKeys_.data();
    const std::uint64_t* const end = pairs + previousStart_[shapeA + 1];
    const std::uint64_t* const found = std::lower_bound(pairs + previousStart_[shapeA], end, key);
    if (found != end && *found == key) first = previousOrder_[found - pairs];
  }
  return first;
}

real Simulator::searchPreviousForce(const GlobalContactInfo& contact, std::size_t position,
                                    std::size_t& hint) {
  // Detection lists the contacts in nearly the last step's order: after the contact at the
  // hint (the one after the last found, tried by the caller), the one after it (the one at the
  // hint has gone, or two are swapped), the one before the last found (the second of two
  // swapped: the hint stays), the one at the same place, before a search.
  const GlobalContactInfo* const previous = previousContacts_.data();
  const std::size_t count = previousContacts_.size();
  const std::size_t next = hint + 1;
  if (next < count && previous[next].sameContactAs(contact)) {
    hint = next + 1;
    return previous[next].force;
  }
  if (hint >= 2 && hint - 2 < count && previous[hint - 2].sameContactAs(contact))
    return previous[hint - 2].force;
  if (position < count && previous[position].sameContactAs(contact)) {
    hint = position + 1;
    return previous[position].force;
  }
  const PreviousRange range = previousContactsOf(contact.shapeA, contact.shapeB);
  for (std::uint32_t k = range.begin; k < range.end; ++k) {
    if (previousContacts_[k].feature == contact.feature) {
      hint = std::size_t{k} + 1;
      return previousContacts_[k].force;
    }
  }
  return 0;
}

}  // namespace thyrix
