#pragma once
/// @file Picking.h
/// @brief Which object lies under the mouse: point tests against circles and capsules.

#include <GUIWx/WorldSnapshot.h>

#include <optional>
#include <span>

namespace thyrix {

/// Signed distance from @p point to the outline of @p shape (m): negative inside, zero on the
/// outline, positive outside.
[[nodiscard]] real distanceToShape(const PickShape& shape, Vector2 point);

/// The object under @p point: among the shapes that contain it, the last one (the one drawn on
/// top); if none does, the one whose outline is nearest, provided it is within @p tolerance
/// metres (so a small object can be grabbed with a few pixels to spare). Returns the object's
/// index in Simulator::objects, or nothing.
[[nodiscard]] std::optional<std::uint32_t> pickObject(std::span<const PickShape> shapes,
                                                      Vector2 point, real tolerance = 0);

}  // namespace thyrix
