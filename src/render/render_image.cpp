#include "render/render_image.hpp"

#include "look/sky_dome.hpp"
#include "render/headless_context.hpp"
#include "render/offscreen_target.hpp"
#include "render/terrain_renderer.hpp"

namespace sansui::render {
Image render_image(const Heightfield& heights, const look::RenderParams& given, const look::TerrainLayers& layers, const Context& context) {
  given.validate();
  // Every value the scene left unset takes the renderer's fallback; the sea and the picture's
  // height are settled against the heights.
  look::RenderParams params = look::with_fallbacks(given);
  params.sea = true;
  params.sea_level_m = look::effective_sea_level(given, heights);
  params.height = look::resolved_height(given, heights);
  budget::check(look::render_cost(params, *params.height));  // before the context and its targets
  context.report("render: context", 0.0);
  const HeadlessContext gl;
  // Declared after the context, so they are destroyed while it is still current.
  // Multisampled colour and depth take 8 bytes per sample: past 16 megapixels (a 4-sample
  // 8192^2 target would need 2 GB) the picture is drawn with one sample per pixel.
  const long long pixels = static_cast<long long>(params.width) * *params.height;
  const OffscreenTarget target(params.width, *params.height, pixels > look::max_multisampled_pixels ? 1 : params.samples);
  TerrainRenderer renderer;
  context.check_cancelled();
  context.report("render: upload", 0.2);
  // Plants are set apart, so that their meshes and impostors show as a stage of their own.
  look::TerrainLayers terrain_layers = layers;
  terrain_layers.plants = {};
  renderer.set_terrain(heights, params, terrain_layers);
  if (!layers.plants.empty()) {
    context.check_cancelled();
    renderer.set_plants(layers.plants, context);
  }
  if (layers.sky != nullptr)
    renderer.set_sky(*layers.sky, params);
  else
    renderer.set_sky(look::bake_sky_dome(params, layers.clouds, 1024, 256, context), params);
  context.check_cancelled();
  context.report("render: draw", 0.5);
  target.bind();
  renderer.draw(params, params.width, *params.height);
  Image image = target.read_pixels();
  context.report("render: draw", 1.0);
  return image;
}

}  // namespace sansui::render
