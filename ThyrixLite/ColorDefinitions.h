#pragma once
/// @file ColorDefinitions.h
/// @brief Named colours used by the default drawing of objects, contacts and sensors.

#include <ThyrixLite/Color.h>

namespace thyrix::colors {

inline constexpr Color black{0, 0, 0};
inline constexpr Color white{255, 255, 255};
inline constexpr Color gray{128, 128, 128};
inline constexpr Color lightGray{200, 200, 200};
inline constexpr Color darkGray{64, 64, 64};
inline constexpr Color red{220, 40, 40};
inline constexpr Color green{40, 170, 70};
inline constexpr Color blue{40, 90, 220};
inline constexpr Color yellow{240, 200, 40};
inline constexpr Color orange{245, 140, 30};
inline constexpr Color purple{140, 60, 180};
inline constexpr Color cyan{40, 190, 210};
inline constexpr Color brown{140, 90, 50};

/// Default fill of movable objects.
inline constexpr Color object = blue;
/// Default fill of fixed objects and borders.
inline constexpr Color fixedObject = darkGray;
/// Contact points and normals.
inline constexpr Color contact = red;
/// Contact-force arrows.
inline constexpr Color contactForce = orange;

}  // namespace thyrix::colors
