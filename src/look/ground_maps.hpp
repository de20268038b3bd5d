// Landform maps for the terrain shader's ground colour, baked on the CPU once per terrain at the
// shading grid's resolution and read with one texture fetch per pixel (a software rasteriser pays
// for each): where water gathers (valley floors, wetter and greener), the ground's curvature at
// two scales (concave hollows against convex ridges), and where rock debris from cliffs comes to
// rest (scree at the foot of steep faces). Plus a tileable detail texture for near views.
//
// Wetness is a topographic proxy after Beven & Kirkby 1979 (the upslope area a cell drains, on a
// log scale): D8 routing (O'Callaghan & Mark 1984, water/flow.hpp) without filling depressions,
// so pits are wet too. Curvature is the topographic position index (Weiss 2001: the mean height
// around a cell minus its own) at two radii, divided by the radius. Scree follows the D8 paths
// down from every cliff cell and fades over a run-out distance, as talus cones do.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"

namespace sansui::look {

struct GroundMapParams {
  /// Cells at or below this height are sea: water leaves the land there. [Units: m]
  double sea_level_m = 0.0;
  /// Slopes steeper than this shed scree (the land's cliff slope). [Units: degrees] [Default: 38]
  double cliff_slope_deg = 38.0;
  /// Width of the ramp into cliff around cliff_slope_deg. [Units: degrees] [Default: 10]
  double cliff_blend_deg = 10.0;
};

/// RGBA8 texels, one per sample of `heights` (row-major, x east, y south):
///   r: wetness 0..1 (log upslope area; the larger of it and `wetness`, if given),
///   g: curvature at a radius of about 40 m (or 2 samples): 128 flat, above concave, below convex,
///   b: scree 0..1 (below cliffs, not on them),
///   a: curvature at a radius of about 250 m (or 8 samples), coded as g.
/// `wetness` (optional, any size, stretched over the same extent): ground made wet by rivers and
/// lakes (scene water layers), 0..1.
std::vector<std::uint8_t> ground_map_texels(const Heightfield& heights, const GroundMapParams& params,
                                            const Grid<float>* wetness = nullptr);

/// A tileable fractal gradient noise of size x size RGBA8 texels for near-view detail: r, g the
/// height's slope east and south (128 flat; divide by 127 and multiply by the returned scale to
/// get the height's change per tile width, the coarsest octave's amplitude being 1), b the
/// height itself 0..255, a an independent value noise for colour. Octaves of 8, 16, 32 and 64
/// lattice cells per tile with amplitudes falling as cells^-hurst.
/// [Range: size a power of two >= 64] [Range: 0 < hurst <= 1]
struct DetailNoise {
  std::vector<std::uint8_t> texels;
  double gradient_scale = 1.0;
};
DetailNoise detail_noise_texels(int size, double hurst, std::uint64_t seed = 0x44455441494CULL);

}  // namespace sansui::look
