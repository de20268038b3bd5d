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

/// A star as the renderer draws it: a point of one pixel over the clear sky, hidden by the
/// clouds in front of it (render/shaders.cpp: star_fragment), so that it keeps the display's
/// resolution where the dome's texels are several pixels wide.
struct Star {
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  ///< drawing coordinates: x east, y up, z south
  float brightness = 0.0f;                ///< linear, the night's visibility and the air's extinction included
};

/// All directions around the viewer: texel (i, j) looks toward azimuth (i + 0.5) / width * 360
/// degrees (clockwise from north) and elevation dome_top - (j + 0.5) / height * (dome_top -
/// dome_bottom) degrees.
struct SkyDome {
  int width = 0, height = 0;
  std::vector<float> rgba;    ///< linear radiance in rgb (not clamped), cloud cover in a; row 0 is the top
  std::vector<float> clear;   ///< the same directions without clouds or stars (rgba, a = 0): the renderer draws
                              ///< the clouds over it per pixel from `clouds` (render/shaders.cpp: cloud_over())
                              ///< and the stars as points
  std::vector<Star> stars;    ///< the stars that show (none by day); `rgba` holds them too, texel-sized
  glm::vec3 sky_light{0.0f};  ///< mean linear colour of the upper hemisphere, cosine-weighted: the sky's light
  /// The cloud layer's field, as the renderer samples it for the sky, the sea's reflections and the
  /// clouds' shadows (one field, so that they agree): per sample the cover 0..1 (cloud_density(), at most 1)
  /// and the optical depth 0..1 (cloud_thickness()), interleaved. Empty for a clear sky.
  std::vector<float> clouds;
  int clouds_size = 0;             ///< samples per side of `clouds`
  float cloud_cover = 0.0f;        ///< the sky's cloud cover 0..1
  glm::vec3 cloud_sunlight{0.0f};  ///< linear sunlight on the clouds (its colour times strength, faded out below the horizon)
};

inline constexpr double dome_top_deg = 90.0;
inline constexpr double dome_bottom_deg = -10.0;
/// The haze at the horizon is the sky this far above it. [Units: degrees]
inline constexpr double haze_elevation_deg = 2.0;

/// The haze toward each azimuth (the dome's columns; linear rgb): the sky haze_elevation_deg up,
/// clouds included, averaged over 20 degrees of azimuth, so that single clouds near the horizon
/// do not show as vertical stripes in the fog and the far land and sea. The fog, the sky below
/// that elevation and the plants' fog all take it (render/shaders.cpp: haze_at()).
std::vector<glm::vec3> horizon_haze(const SkyDome& dome);
/// The highest value cloud_density() gives: the image this many soft edges above the threshold.
inline constexpr float cloud_density_max = 4.0f;

/// Cloud density per sample of a cloud image: the highest `cover` fraction of the image's values
/// become cloud, with a soft edge from 0 (clear) to 1 (cloud). Inside a cloud the value goes on
/// rising with the image, up to cloud_density_max, so that the optical depth (cloud_thickness())
/// varies within large clouds; read min(value, 1) for the cover. [Range: cover 0..1]
Grid<float> cloud_density(const Grid<float>& image, double cover);

/// Optical depth 0..1 of a cloud density grid (cloud_density()): the density averaged over
/// `radius` samples around (a separable box filter run twice, mirrored at the borders as the
/// renderer repeats the image) over cloud_density_max, times the cover there. The middle of a
/// large, tall cloud is thick and dark underneath, small wisps and edges are thin. [Range: radius >= 1]
Grid<float> cloud_thickness(const Grid<float>& density, int radius);

/// Bakes the sky for `params` (resolved: every optional set, see with_fallbacks()). `clouds` is
/// a density grid (cloud_density()) or null for a clear sky. Deterministic; rows in parallel.
SkyDome bake_sky_dome(const RenderParams& params, const Grid<float>* clouds, int width = 1024, int height = 256,
                      const Context& context = quiet_context());

/// The direction of azimuth and elevation (degrees) in drawing coordinates: x east, y up, z south.
glm::vec3 direction_of(double azimuth_deg, double elevation_deg);

}  // namespace sansui::look
