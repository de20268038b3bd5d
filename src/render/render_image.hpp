// One call for the CLI and tests: a picture of a heightfield with no display (EGL surfaceless
// context, offscreen framebuffer, read back).
#pragma once

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/render_params.hpp"
#include "look/terrain_layers.hpp"

namespace sansui::render {

/// Renders `heights` (metres) as params say, headless. Throws InputError for bad params or
/// heights (naming the value), render::GlError (render/gl_error.hpp) when no OpenGL is available. Reports progress as the
/// stages "render: context", "render: upload", "render: plants" (with layers.plants), "render: draw".
Image render_image(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers = {},
                   const Context& context = quiet_context());

}  // namespace sansui::render
