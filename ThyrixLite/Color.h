#pragma once
/// @file Color.h
/// @brief An RGBA colour for drawing.

#include <cstdint>

namespace thyrix {

/// An 8-bit-per-channel colour with opacity.
struct Color {
  std::uint8_t red = 0;      ///< red channel
  std::uint8_t green = 0;    ///< green channel
  std::uint8_t blue = 0;     ///< blue channel
  std::uint8_t alpha = 255;  ///< opacity, 255 = opaque

  /// Same channels.
  constexpr bool operator==(const Color&) const = default;
};

}  // namespace thyrix
