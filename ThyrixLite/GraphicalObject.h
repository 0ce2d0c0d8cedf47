#pragma once
/// @file GraphicalObject.h
/// @brief The base of everything that can be drawn.

#include <ThyrixLite/Color.h>
#include <ThyrixLite/ColorDefinitions.h>

namespace thyrix {

class GUI;

/// Something that draws itself through a GUI. Drawing reads the object; it never changes it.
class GraphicalObject {
 public:
  GraphicalObject() = default;
  GraphicalObject(const GraphicalObject&) = delete;
  GraphicalObject& operator=(const GraphicalObject&) = delete;
  virtual ~GraphicalObject() = default;

  /// Draws the object in world coordinates.
  virtual void draw(GUI& gui) const = 0;

  Color color = colors::object;        ///< fill colour
  Color outlineColor = colors::black;  ///< outline colour
};

}  // namespace thyrix
