// The sky around the viewer (Oka et al. 1997, seeds/003, Sec. 4.2; SPEC 3.4), baked on the CPU
// into one picture of all directions that the shaders look up for the backdrop, the sea's
// reflections and the colour of the haze: the sky's colour from its model (look/sky_model.hpp),
// stars when the sky is dark, and clouds. The sun's disc is drawn by the shader over it, where
// the clouds (their cover is the picture's alpha) let it through.
//
// Clouds are the paper's 2-D midpoint-displacement image (its fineness is the Hurst exponent,
// made by the scene with terrain/midpoint.hpp) laid on a flat layer high above the viewer: a
// direction at elevation e meets the layer 1 / tan(e) layer-heights away, so the image is
// compressed toward the horizon as perspective compresses real clouds.
#pragma once

#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/render_params.hpp"

namespace sansui::look {

/// All directions around the viewer: texel (i, j) looks toward azimuth (i + 0.5) / width * 360
/// degrees (clockwise from north) and elevation dome_top - (j + 0.5) / height * (dome_top -
/// dome_bottom) degrees.
struct SkyDome {
  int width = 0, height = 0;
  std::vector<float> rgba;    ///< linear radiance in rgb (not clamped), cloud cover in a; row 0 is the top
  glm::vec3 sky_light{0.0f};  ///< mean linear colour of the upper hemisphere, cosine-weighted: the sky's light
};

inline constexpr double dome_top_deg = 90.0;
inline constexpr double dome_bottom_deg = -10.0;

/// Cloud density 0..1 per sample of a cloud image: the highest `cover` fraction of the image's
/// values become cloud, with a soft edge. [Range: cover 0..1]
Grid<float> cloud_density(const Grid<float>& image, double cover);

/// Bakes the sky for `params` (resolved: every optional set, see with_fallbacks()). `clouds` is
/// a density grid (cloud_density()) or null for a clear sky. Deterministic; rows in parallel.
SkyDome bake_sky_dome(const RenderParams& params, const Grid<float>* clouds, int width = 1024, int height = 256,
                      const Context& context = quiet_context());

/// The direction of azimuth and elevation (degrees) in drawing coordinates: x east, y up, z south.
glm::vec3 direction_of(double azimuth_deg, double elevation_deg);

}  // namespace sansui::look
