#include "render/render_image.hpp"

#include "render/headless_context.hpp"
#include "render/offscreen_target.hpp"
#include "render/terrain_renderer.hpp"

namespace sansui::render {
namespace {

constexpr long long max_multisampled_pixels = 16'000'000;

}  // namespace

Image render_image(const Heightfield& heights, const RenderParams& params, const TerrainLayers& layers, const Context& context) {
  params.validate();
  if (!params.sea || !params.height) {
    RenderParams resolved = params;
    resolved.sea = true;
    resolved.sea_level_m = effective_sea_level(params, heights);
    resolved.height = resolved_height(params, heights);
    return render_image(heights, resolved, layers, context);
  }
  context.report("render: context", 0.0);
  const HeadlessContext gl;
  // Declared after the context, so they are destroyed while it is still current.
  // Multisampled colour and depth take 8 bytes per sample: past 16 megapixels (a 4-sample
  // 8192^2 target would need 2 GB) the picture is drawn with one sample per pixel.
  const long long pixels = static_cast<long long>(params.width) * *params.height;
  const OffscreenTarget target(params.width, *params.height, pixels > max_multisampled_pixels ? 1 : params.samples);
  TerrainRenderer renderer;
  context.check_cancelled();
  context.report("render: upload", 0.2);
  renderer.set_terrain(heights, params, layers);
  context.check_cancelled();
  context.report("render: draw", 0.5);
  target.bind();
  renderer.draw(params, params.width, *params.height);
  Image image = target.read_pixels();
  context.report("render: draw", 1.0);
  return image;
}

}  // namespace sansui::render
