#pragma once
/// @file ColorDefinitions.h
/// @brief Named colours used by the default drawing of objects, contacts and sensors.

#include <ThyrixLite/Color.h>

namespace thyrix::colors {

/// Black.
inline constexpr Color black{0, 0, 0};
/// White.
inline constexpr Color white{255, 255, 255};
/// Gray.
inline constexpr Color gray{128, 128, 128};
/// Light gray.
inline constexpr Color lightGray{200, 200, 200};
/// Dark gray.
inline constexpr Color darkGray{64, 64, 64};
/// Red.
inline constexpr Color red{220, 40, 40};
/// Green.
inline constexpr Color green{40, 170, 70};
/// Blue.
inline constexpr Color blue{40, 90, 220};
/// Yellow.
inline constexpr Color yellow{240, 200, 40};
/// Orange.
inline constexpr Color orange{245, 140, 30};
/// Purple.
inline constexpr Color purple{140, 60, 180};
/// Cyan.
inline constexpr Color cyan{40, 190, 210};
/// Brown.
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
