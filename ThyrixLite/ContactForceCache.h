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
    if (entries_ > 0) reset(0);
  }
  /// Stores @p force under @p key (keys are unique within a step).
  void insert(std::uint64_t key, real force);
  /// The force stored under @p key, or 0.
  [[nodiscard]] real find(std::uint64_t key) const;

 private:
  [[nodiscard]] std::size_t slot(std::uint64_t key) const;

  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  /// Key and force side by side: a lookup touches one cache line, not two.
  struct Entry {
    std::uint64_t key;
    real force;
  };
  std::vector<Entry> table_;
  std::size_t mask_ = 0;
  std::size_t entries_ = 0;
};

}  // namespace thyrix
