// Optional per-sample inputs drawn on the terrain besides its heights.
#pragma once

#include "core/color.hpp"
#include "core/grid.hpp"
#include "look/plant_models.hpp"

namespace sansui::look {

struct SkyDome;

/// Not owned: read while the terrain is uploaded (TerrainRenderer::set_terrain) only.
struct TerrainLayers {
  /// Colour of bare rock per sample (e.g. rock strata evaluated from a solid texture at the
  /// surface, a later issue), shown instead of palette.cliff on cliffs and above the tree line.
  /// Any size: it is stretched over the terrain's extent (sample (0, 0) at the north-west
  /// corner) and thinned to max_texture_samples per side. sRGB; alpha is ignored.
  /// [Default: none, the palette's cliff colour]
  const Image* cliff_albedo = nullptr;
  /// Rivers and lakes standing on the land (water/: flow routing, lakes): metres of water over
  /// the ground per sample, and how wet the ground is, 0..1 (banks and flood plains are drawn
  /// darker). Any size, stretched over the terrain's extent like cliff_albedo; thinned to
  /// max_texture_samples per side keeping each block's deepest and wettest value, so a river
  /// one sample wide stays. Both or neither, the same size. The sea is drawn as before.
  /// [Default: none]
  const Grid<float>* water_depth = nullptr;
  const Grid<float>* wetness = nullptr;
  /// Cloud density 0..1 of the sky's cloud layer (look/sky_dome.hpp: cloud_density()), seen
  /// from below with the viewer at its centre. [Default: none, a clear sky]
  const Grid<float>* clouds = nullptr;
  /// The sky, baked already (render_image() bakes it from the params and clouds when null).
  const SkyDome* sky = nullptr;
  /// Trees and ground plants standing on the terrain (world coordinates) and their kinds' models
  /// (look::PlantKindCache makes them from a placement), drawn as instanced meshes and impostors
  /// (render/plant_renderer.hpp). [Default: none]
  PlantsToDraw plants;
};

}  // namespace sansui::look
