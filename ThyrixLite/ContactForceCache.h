#pragma once
/// @file ContactForceCache.h
/// @brief Last step's contact forces, by contact identity, to warm-start Gauss-Seidel.

#include <ThyrixLite/ThyrixParameters.h>

#include <cstdint>
#include <vector>

namespace thyrix {

/// An open-addressing hash table from a contact's identity (shape A, shape B, feature) to
/// its force. Rebuilt after each solve; lookups depend only on the keys, never on memory
/// addresses, so warm starting is reproducible. The table only grows when the contact count
/// reaches a new high: in a steady state it allocates nothing.
///
/// The entries are also kept in the order they were stored. Detection lists the contacts in
/// nearly the same order from step to step, so a lookup with a hint (where the last one
/// matched, plus one) usually finds its entry there, without hashing or probing.
class ContactForceCache {
 public:
  /// The identity of a contact.
  static std::uint64_t key(std::uint32_t shapeA, std::uint32_t shapeB, std::uint32_t feature) {
    return (static_cast<std::uint64_t>(shapeA) << 33) ^ (static_cast<std::uint64_t>(shapeB) << 1) ^
           feature;
  }

  /// Makes room for @p count entries without further allocation.
  void reserve(std::size_t count);
  /// Empties the table and sizes it for @p count entries.
  void reset(std::size_t count);
  /// Empties the table (nothing to do when it is already empty).
  void clear() {
    if (!stored_.empty()) reset(0);
  }
  /// Stores @p force under @p key (keys are unique within a step).
  void insert(std::uint64_t key, real force);
  /// The force stored under @p key, or 0.
  [[nodiscard]] real find(std::uint64_t key) const;
  /// The same, looking first at the entry stored in position @p hint, which is then moved past
  /// the entry found (unchanged when there is none). The result does not depend on the hint.
  [[nodiscard]] real find(std::uint64_t key, std::size_t& hint) const;

 private:
  [[nodiscard]] std::size_t slot(std::uint64_t key) const;

  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  /// Key and force side by side: a lookup touches one cache line, not two.
  struct Entry {
    std::uint64_t key;
    real force;
  };
  /// A hash slot: the key, and the entry's position in stored_.
  struct Slot {
    std::uint64_t key;
    std::size_t position;
  };
  /// The position of @p key in stored_, or stored_.size().
  [[nodiscard]] std::size_t position(std::uint64_t key) const;
  std::vector<Slot> table_;
  std::vector<Entry> stored_;  // in the order of insertion
  std::size_t mask_ = 0;
};

}  // namespace thyrix
