// 8-bit colours and images.
#pragma once

#include <cstdint>

#include "core/grid.hpp"

namespace sansui {

/// A colour in sRGB, each channel in [0, 1] (what a colour picker shows).
struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

/// A picture: row 0 is the top row.
using Image = Grid<Rgba8>;

}  // namespace sansui
