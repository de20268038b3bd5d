// sRGB colours (what a colour picker shows, Rgb) to the linear light that shading adds and
// blends, and the angle unit the renderer's parameters come in.
#pragma once

#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include "core/color.hpp"

namespace sansui::look {

/// Radians per degree: `azimuth_deg * degrees`.
inline constexpr double degrees = std::numbers::pi / 180.0;

/// One sRGB channel in [0, 1] to linear light (the sRGB transfer curve).
inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline glm::vec3 linear(const Rgb& colour) {
  return {srgb_to_linear(colour.r), srgb_to_linear(colour.g), srgb_to_linear(colour.b)};
}

}  // namespace sansui::look
