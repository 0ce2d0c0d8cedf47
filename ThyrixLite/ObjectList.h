#pragma once
/// @file ObjectList.h
/// @brief Read-only views of the objects and contacts a simulator owns.

#include <ThyrixLite/GlobalContactInfo.h>
#include <ThyrixLite/PhysicalObject.h>
#include <Tools/Inlining.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <span>
#include <vector>

namespace thyrix {

/// The objects of a World, in registration order: `size()`, `operator[]` and range-for give
/// `PhysicalObject&`. Objects are added only through World::registerObject.
class ObjectList {
  using Storage = std::vector<std::unique_ptr<PhysicalObject>>;

 public:
  /// Iterates the objects as references.
  class iterator {
   public:
    /// Forward iterator.
    using iterator_category = std::forward_iterator_tag;
    /// The objects' type.
    using value_type = PhysicalObject;
    /// Distance type.
    using difference_type = std::ptrdiff_t;
    /// Pointer to an object.
    using pointer = PhysicalObject*;
    /// Reference to an object.
    using reference = PhysicalObject&;

    /// An iterator over objects.
    iterator() = default;
    /// An iterator over objects.
    explicit iterator(Storage::const_iterator it) : it_(it) {}
    /// The object.
    reference operator*() const { return **it_; }
    /// The object.
    pointer operator->() const { return it_->get(); }
    /// Advances to the next object.
    iterator& operator++() {
      ++it_;
      return *this;
    }
    /// Advances to the next object.
    iterator operator++(int) { return iterator(it_++); }
    /// Exact equality.
    bool operator==(const iterator&) const = default;

   private:
    Storage::const_iterator it_;
  };

  /// Number of objects.
  [[nodiscard]] std::size_t size() const { return items_.size(); }
  /// True when there are none.
  [[nodiscard]] bool empty() const { return items_.empty(); }
  /// The object registered @p i-th.
  PhysicalObject& operator[](std::size_t i) const { return *items_[i]; }
  /// The first object, for range-for.
  [[nodiscard]] iterator begin() const { return iterator(items_.begin()); }
  /// Past the last object.
  [[nodiscard]] iterator end() const { return iterator(items_.end()); }

 private:
  friend class World;
  Storage items_;
};

/// Calls @p other on the objects whose indices are listed in @p listed (increasing) and
/// @p core on all the others, in index order. The runs of objects between listed ones need no
/// test per object: the simulator runs its core shapes' step hooks so, without virtual calls.
/// (By iterator, the list's end read once: by index, a call out of line made every object
/// after it read the list's size again.)
template <class Core, class Other>
THYRIX_ALWAYS_INLINE void forEachInRuns(const ObjectList& objects,
                                        std::span<const std::uint32_t> listed, Core&& core,
                                        Other&& other) {
  auto object = objects.begin();
  std::size_t index = 0;
  for (const std::uint32_t next : listed) {
    for (; index < next; ++index, ++object) core(*object);
    other(*object);
    ++index;
    ++object;
  }
  for (const auto end = objects.end(); object != end; ++object) core(*object);
}

/// This step's contacts of a Simulator: `size()`, `operator[]` and range-for give
/// `const GlobalContactInfo&`. They are kept until the next step starts, so a GUI can draw them.
class ContactList {
 public:
  /// Number of contacts.
  [[nodiscard]] std::size_t size() const { return items_.size(); }
  /// True when there are none.
  [[nodiscard]] bool empty() const { return items_.empty(); }
  /// The @p i-th contact.
  const GlobalContactInfo& operator[](std::size_t i) const { return items_[i]; }
  /// The first contact, for range-for.
  [[nodiscard]] auto begin() const { return items_.cbegin(); }
  /// Past the last contact.
  [[nodiscard]] auto end() const { return items_.cend(); }

 private:
  friend class Simulator;
  std::vector<GlobalContactInfo> items_;
};

}  // namespace thyrix
