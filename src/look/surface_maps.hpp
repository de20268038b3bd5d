// Per-texel data the shaders read instead of computing it per pixel (the software rasteriser
// in CI pays for every instruction of the fragment shader): heights with their gradients, and
// a tileable noise that breaks up colour bands and patches.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"

namespace sansui::look {

/// RGBA float texels, row-major like the grid: (height m, dh/dx east, dh/dz south, curvature),
/// the gradient by central differences (one-sided at the edges), dimensionless (m per m); the
/// curvature is the mean of the eight neighbours minus the sample, per cell size (positive in
/// hollows, negative on crests).
std::vector<float> height_and_gradient_texels(const Heightfield& heights);

/// Depth below which a dry sample's signed water depth is not worked out. [Units: m]
inline constexpr float dry_water_depth_m = -10.0f;

/// Per sample, the depth of rivers and lakes, signed: over water as `depth` says; on a dry sample
/// next to water, the water's level (the lowest of its wet neighbours' `surface`: a lake's level)
/// minus the sample's height, below zero; elsewhere dry_water_depth_m. Read bilinearly, it
/// crosses zero where the interpolated ground meets the water's level, so a shoreline follows
/// the ground between the samples instead of their squares. `surface`: the drawn heights (lakes
/// filled), the same size as `depth` (otherwise only the wet samples are set).
Grid<float> signed_water_depth(const Grid<float>& depth, const Heightfield& surface);

/// A tileable fractal value noise (4 octaves) of size x size RG8 texels, in [0, 255]: two
/// independent channels. Lattice values come from rng::uniform, so it is the same everywhere.
/// [Range: size a power of two >= 16]
std::vector<std::uint8_t> tileable_noise_texels(int size, std::uint64_t seed = 0x53414E5355495244ull);

/// Two noise channels per sample of a width x height grid `spacing_m` apart whose first sample
/// stands at (origin_x_m, origin_y_m) in the world: fractal value noise (5 octaves) on an
/// unbounded lattice in world metres, so that nothing repeats and neighbouring tiles of a world
/// match. Channel 0 wanders the band borders (wavelengths 3 km down to 190 m), channel 1 makes
/// patches in the vegetation and rock (600 m down to 38 m); octaves finer than two samples are
/// left out. Baked per sample so that the fragment shader fetches them with the shadows in one
/// texture read. [Range: spacing_m > 0]
std::vector<std::uint8_t> world_noise_texels(int width, int height, double spacing_m, double origin_x_m = 0.0, double origin_y_m = 0.0,
                                             std::uint64_t seed = 0x42414E44u);

}  // namespace sansui::look
