// The one step of a scene that needs a GPU: turning a terrain and its look into a picture.
// scene/ is GL-free, so that a program making heightmaps, meshes or vector files links no GL or
// EGL library; a program that draws hands scene the renderer once at start-up:
//
//   sansui::scene::set_painter(&sansui::render::render_image);
//
// (the CLI, the viewer, the test and benchmark programs do). Until then a recipe with a
// picture output is refused before any work.
#pragma once

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/render_params.hpp"
#include "look/terrain_layers.hpp"

namespace sansui::scene {

/// render::render_image's shape: a picture of `heights` as `params` say, with `layers` over it.
using Painter = Image (*)(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers,
                          const Context& context);

/// Sets the painter of this process (not thread-safe: call it before any work).
void set_painter(Painter painter);
bool has_painter();
/// Draws with the painter; throws InputError naming what is missing when none was set.
Image paint(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers, const Context& context);

}  // namespace sansui::scene
