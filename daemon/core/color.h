// Colour helpers. Linear Rec. 709 / sRGB primaries, D65 white.
// Luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (ITU-R BT.709-6, item 3.2).
#pragma once

#include <glm/vec3.hpp>

namespace vem {

inline constexpr double kRec709R = 0.2126;
inline constexpr double kRec709G = 0.7152;
inline constexpr double kRec709B = 0.0722;

[[nodiscard]] constexpr double luminance(double r, double g, double b) {
  return kRec709R * r + kRec709G * g + kRec709B * b;
}
[[nodiscard]] constexpr double luminance(glm::dvec3 rgb) { return luminance(rgb.x, rgb.y, rgb.z); }
[[nodiscard]] constexpr double luminance(glm::vec3 rgb) {
  return luminance(double(rgb.x), double(rgb.y), double(rgb.z));
}

}  // namespace vem
