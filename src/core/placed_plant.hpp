// One plant standing on the terrain, as plain data: what vegetation places, look draws and io
// writes for game engines (species and variant are indices the caller's catalogue names).
#pragma once

#include <cstdint>

namespace sansui {

struct PlacedPlant {
  float x_m = 0.0f;           ///< east, world coordinates (the heightfield's origin_x_m included)
  float y_m = 0.0f;           ///< south, world coordinates
  float height_m = 0.0f;      ///< ground height at (x, y)
  float scale = 1.0f;         ///< times the species' typical size
  float rotation_rad = 0.0f;  ///< turn about the vertical, [0, 2 pi)
  std::uint16_t species = 0;  ///< index into the species catalogue (vegetation::species_library())
  std::uint16_t variant = 0;  ///< which of the species' few mesh variants (seeded shapes)
};

}  // namespace sansui
