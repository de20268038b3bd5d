#include "scene/painter.hpp"

#include "core/error.hpp"

namespace sansui::scene {
namespace {

// A registry of one: set once by main() before any work, read afterwards.
Painter the_painter = nullptr;  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)

}  // namespace

void set_painter(Painter painter) {
  the_painter = painter;
}

bool has_painter() {
  return the_painter != nullptr;
}

Image paint(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers, const Context& context) {
  if (the_painter == nullptr)
    fail(
        "this program cannot draw pictures: it was built without the renderer (link sansui_render and call "
        "scene::set_painter(&render::render_image))");
  return the_painter(heights, params, layers, context);
}

}  // namespace sansui::scene
