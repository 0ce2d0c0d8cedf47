#pragma once
/// @file PurgeContainer.h
/// @brief Deletes the objects a container owns, empties it and gives its memory back.

#include <type_traits>

namespace thyrix {

/// Deletes the objects of @p container, empties it and releases its capacity, as the
/// original users' guide describes it ("by deleting these objects, and emptying the
/// container"; docs/PortingFromThyrix.md).
///
/// - A container of raw pointers (`std::vector<Circle*>`, `std::list<Agent*>`, ...) owns
///   what they point to: each is deleted with `delete` (null pointers are skipped), then the
///   container is emptied. Every pointer must come from `new` of a single object, and no
///   object may be listed twice.
/// - A container of values or of smart pointers (`std::vector<std::unique_ptr<T>>`,
///   `std::vector<std::shared_ptr<T>>`) is emptied: the elements' destructors do the deleting
///   (a `shared_ptr`'s object goes once its last owner does).
///
/// `clear()` alone keeps the capacity (which is what the step loop wants); this is for the
/// moments a world is torn down or rebuilt and its memory should really go.
template <class Container>
void purgeContainer(Container& container) {
  using Element = typename Container::value_type;
  if constexpr (std::is_pointer_v<Element>) {
    static_assert(sizeof(std::remove_pointer_t<Element>) > 0,
                  "purgeContainer: the pointed-to type must be complete to be deleted");
    for (Element pointer : container) delete pointer;  // NOLINT(cppcoreguidelines-owning-memory)
  }
  Container empty;
  container.swap(empty);
}

}  // namespace thyrix
