// What the picture tests share: a render with no display server in sight, as CI does, and the
// fractal island most of them draw.
#pragma once

#include <cstdlib>

#include "render/render_image.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::test {

/// Renders with no display server in sight (Mesa's EGL surfaceless context), as CI does.
inline Image render_headless(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers = {}) {
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  return render::render_image(heights, params, layers);
}

/// A fractal island: midpoint terrain (seed 1 has sea on two sides and a peak, 71 % land),
/// 257 x 257 samples 40 m apart.
inline Heightfield island() {
  terrain::MidpointParams midpoint;
  midpoint.seed = 1;
  Heightfield heights = terrain::generate_midpoint(midpoint, 257);
  heights.cell_size_m = 40.0;
  return heights;
}

}  // namespace sansui::test
