#pragma once
/// @file ToolIcons.h
/// @brief The toolbar's icons, drawn by the program itself so they look the same whatever icon
/// theme the system has (or none, as under a bare X server).

#include <wx/bitmap.h>

namespace thyrix {

/// The icons of the simulation toolbar.
enum class ToolIcon {
  Run,         ///< a triangle: run / pause
  Step,        ///< a triangle and a bar: one step
  Reset,       ///< a circular arrow: rebuild the world
  Fit,         ///< four corners: fit the world to the window
  Contacts,    ///< a cross on a dot: contact points
  Forces,      ///< an arrow: contact forces
  Tactile,     ///< a circle with dots: tactile sensors
  Rays,        ///< a fan of rays: visual sensors
  Screenshot,  ///< a camera: save a PNG
};

/// The icon @p icon as an anti-aliased bitmap of @p size x @p size pixels with transparency.
[[nodiscard]] wxBitmap toolIcon(ToolIcon icon, int size = 24);

}  // namespace thyrix
