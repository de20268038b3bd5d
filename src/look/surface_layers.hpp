// The land's colour bands (Oka et al. 1997, Sec. 4.1.2, as the terrain shader draws them) on the
// CPU, per sample: the weights of four surface layers for game engines' splat maps, and the band
// colours as a base-colour texture for meshes. The shader's ground_albedo() bands (the sand up to
// beach_top with its own narrow ramp, linear ramps across the tree and snow lines, cliff rock on
// steep slopes, no snow on slopes too steep to hold it), without its noises and without the
// landform rules (wet valleys, scree, soil, aspect), which need the landform maps.
#pragma once

#include <optional>

#include "core/color.hpp"
#include "core/grid.hpp"
#include "look/render_params.hpp"

namespace sansui::look {

/// Weights in [0, 1] per sample of the heightfield, summing to 1 at every sample.
struct SurfaceWeights {
  Grid<float> sand;   ///< beach and low rock above the sea, and the seabed below it
  Grid<float> grass;  ///< the forest and meadow band between the beach and the tree line
  Grid<float> rock;   ///< above the tree line, and steep slopes anywhere above the sea
  Grid<float> snow;   ///< above the snow line, on slopes gentle enough to hold it
};

/// The lowest and highest heights of a whole world. [Units: m]
struct HeightSpan {
  float lowest, highest;
};

/// The layers of `heights` with the look `resolved` (every look value set: with_fallbacks() or a
/// scene's resolve_look()); sea level and band scale as the renderer takes them. `world`: when
/// `heights` is a tile (with a ring of its neighbours' samples for the slopes) of a larger world,
/// that world's span, so that the tiles' weights are the whole world's.
SurfaceWeights surface_weights(const Heightfield& heights, const RenderParams& resolved,
                               const std::optional<HeightSpan>& world = std::nullopt);

/// The weights as 8-bit RGBA (r sand, g grass, b rock, a snow) that sum to exactly 255 at every
/// sample: each weight is rounded down and the leftover units go to the largest remainders (the
/// splat map output's pixels, row 0 the north row).
Image splat_weights_image(const SurfaceWeights& weights);

/// The band colours (sRGB) of `heights` as a picture of at most `max_side` pixels per side (the
/// samples nearest to each pixel), row 0 the north row: a mesh's base-colour texture.
/// [Range: max_side >= 2]
Image band_colour_map(const Heightfield& heights, const RenderParams& resolved, int max_side = 4096);

}  // namespace sansui::look
