#pragma once
/// @file PurgeContainer.h
/// @brief Empties a container and gives its memory back.

namespace thyrix {

/// Destroys every element of @p container and releases its capacity.
///
/// `clear()` alone keeps the capacity (which is what the step loop wants); this is for
/// the moments a world is torn down or rebuilt and its memory should really go.
template <class Container>
void purgeContainer(Container& container) {
  Container empty;
  container.swap(empty);
}

}  // namespace thyrix
