// 8-bit colours and images.
#pragma once

#include <cstdint>

#include "core/grid.hpp"

namespace sansui {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

/// A picture: row 0 is the top row.
using Image = Grid<Rgba8>;

}  // namespace sansui
