// Per-texel data the shaders read instead of computing it per pixel (the software rasteriser
// in CI pays for every instruction of the fragment shader): heights with their gradients, and
// a tileable noise that breaks up colour bands and patches.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"

namespace sansui::look {

/// RGBA float texels, row-major like the grid: (height m, dh/dx east, dh/dz south, 0), the
/// gradient by central differences (one-sided at the edges), dimensionless (m per m).
std::vector<float> height_and_gradient_texels(const Heightfield& heights);

/// A tileable fractal value noise (4 octaves) of size x size RG8 texels, in [0, 255]: two
/// independent channels. Lattice values come from rng::uniform, so it is the same everywhere.
/// [Range: size a power of two >= 16]
std::vector<std::uint8_t> tileable_noise_texels(int size, std::uint64_t seed = 0x53414E5355495244ull);

/// Two noise channels per sample of a width x height grid spanning fractions (u, v) of a
/// terrain whose extent is (extent_x, extent_y) over its longer side (so 1 on that side):
/// channel 0 wanders the band borders (about one bump per terrain), channel 1 makes patches in
/// forest and rock (about seven per terrain), both sampled from the tile above. Baked per
/// sample so that the fragment shader fetches them with the shadows in one texture read.
std::vector<std::uint8_t> band_noise_texels(int width, int height, double extent_x, double extent_y);

}  // namespace sansui::look
