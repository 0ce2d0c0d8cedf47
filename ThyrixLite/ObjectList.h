#pragma once
/// @file ObjectList.h
/// @brief Read-only views of the objects and contacts a simulator owns.

#include <ThyrixLite/GlobalContactInfo.h>
#include <ThyrixLite/PhysicalObject.h>

#include <cstddef>
#include <iterator>
#include <memory>
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
    using iterator_category = std::forward_iterator_tag;
    using value_type = PhysicalObject;
    using difference_type = std::ptrdiff_t;
    using pointer = PhysicalObject*;
    using reference = PhysicalObject&;

    iterator() = default;
    explicit iterator(Storage::const_iterator it) : it_(it) {}
    reference operator*() const { return **it_; }
    pointer operator->() const { return it_->get(); }
    iterator& operator++() {
      ++it_;
      return *this;
    }
    iterator operator++(int) { return iterator(it_++); }
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
  [[nodiscard]] iterator begin() const { return iterator(items_.begin()); }
  [[nodiscard]] iterator end() const { return iterator(items_.end()); }

 private:
  friend class World;
  Storage items_;
};

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
  [[nodiscard]] auto begin() const { return items_.cbegin(); }
  [[nodiscard]] auto end() const { return items_.cend(); }

 private:
  friend class Simulator;
  std::vector<GlobalContactInfo> items_;
};

}  // namespace thyrix
