/// @file SimulatorPreviousContacts.cpp
/// @brief The last step's contacts, found by shape pair: what rest skipping reuses and where
/// the warm start finds each contact's last force.
#include <ThyrixLite/Simulator.h>

#include <algorithm>

namespace thyrix {

void Simulator::indexPreviousContacts() {
  // Two stable counting sorts, by shape B and then by shape A: the contacts of each shape A
  // come in order of shape B, and a pair's points in their order of detection. A lookup is
  // then a binary search within shape A's contacts, so that a shape with many contacts (a
  // floor under a crowd) costs a logarithm, not a scan.
  const std::size_t count = previousContacts_.size();
  const auto countingSort = [this, count](auto shapeOf, std::span<const std::uint32_t> from,
                                          std::span<std::uint32_t> to) {
    previousStart_.assign(shapes_.size() + 1, 0);
    for (const GlobalContactInfo& c : previousContacts_) ++previousStart_[shapeOf(c) + 1];
    for (std::size_t s = 0; s < shapes_.size(); ++s) previousStart_[s + 1] += previousStart_[s];
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t k = from.empty() ? static_cast<std::uint32_t>(i) : from[i];
      to[previousStart_[shapeOf(previousContacts_[k])]++] = k;
    }
    // The fill advanced each start to the next shape's start: shift back.
    for (std::size_t s = shapes_.size(); s > 0; --s) previousStart_[s] = previousStart_[s - 1];
    previousStart_[0] = 0;
  };
  previousByShapeB_.resize(count);
  previousOrder_.resize(count);
  countingSort([](const GlobalContactInfo& c) { return c.shapeB; }, {}, previousByShapeB_);
  countingSort([](const GlobalContactInfo& c) { return c.shapeA; }, previousByShapeB_,
               previousOrder_);
  // The searches read shape B from a compact array, not from the contacts' records.
  previousShapeB_.resize(count);
  for (std::size_t i = 0; i < count; ++i)
    previousShapeB_[i] = previousContacts_[previousOrder_[i]].shapeB;
  previousCursor_ = 0;
  previousIndexed_ = true;
}

std::span<const std::uint32_t> Simulator::previousContactsOf(std::uint32_t shapeA,
                                                             std::uint32_t shapeB) {
  if (!previousIndexed_) indexPreviousContacts();
  const std::size_t begin = previousStart_[shapeA];
  const std::size_t end = previousStart_[shapeA + 1];
  const std::uint32_t* const keys = previousShapeB_.data();
  // Pairs come in nearly the last step's order (a border's with the shapes in order): the
  // pair's contacts usually begin where the last pair's ended. Else a binary search.
  std::size_t first = previousCursor_;
  if (!(first >= begin && first < end && keys[first] == shapeB &&
        (first == begin || keys[first - 1] < shapeB)))
    first = static_cast<std::size_t>(std::lower_bound(keys + begin, keys + end, shapeB) - keys);
  std::size_t last = first;
  while (last < end && keys[last] == shapeB) ++last;
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
