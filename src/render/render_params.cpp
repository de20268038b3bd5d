#include "render/render_params.hpp"

#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace sansui::render {
namespace {

/// Fails unless low <= value <= high (NaN fails too).
void check_range(std::string_view what, double value, double low, double high, std::string_view unit = "") {
  if (!(value >= low && value <= high))
    fail("{} {}{} is not allowed: it must be between {} and {}{}", what, value, unit, low, high, unit);
}

void check_finite(std::string_view what, double value) {
  if (!std::isfinite(value)) fail("{} {} is not allowed: it must be a finite number", what, value);
}

}  // namespace

std::optional<View> view_from_name(std::string_view name) {
  if (name == "perspective") return View::perspective;
  if (name == "top") return View::top;
  return std::nullopt;
}

std::string_view view_name(View view) {
  return view == View::top ? "top" : "perspective";
}

void RenderParams::validate() const {
  check_range("width", width, 16, 8192, " pixels");
  check_range("height", height, 16, 8192, " pixels");
  check_finite("sun azimuth", sun_azimuth_deg);
  check_range("sun elevation", sun_elevation_deg, 0.0, 90.0, " degrees");
  check_finite("camera azimuth", camera.azimuth_deg);
  check_range("camera elevation", camera.elevation_deg, 1.0, 89.0, " degrees");
  if (camera.distance != 0.0) check_range("camera distance", camera.distance, 0.05, 20.0, " terrain sizes (or 0 to fit)");
  check_range("camera field of view", camera.fov_deg, 5.0, 120.0, " degrees");
  check_range("camera target x", camera.target_x, 0.0, 1.0);
  check_range("camera target y", camera.target_y, 0.0, 1.0);
  check_range("vertical exaggeration", exaggeration, 0.1, 20.0);
  check_finite("sea level", sea_level_m);
  check_range("beach top", bands.beach_top, 0.0, 1.0);
  check_range("tree line", bands.tree_line, 0.0, 1.0);
  check_range("snow line", bands.snow_line, 0.0, 1.0);
  check_range("band blend", bands.blend, 0.0, 0.5);
  check_range("band border noise", bands.border_noise, 0.0, 0.5);
  check_range("cliff slope", bands.cliff_slope_deg, 0.0, 90.0, " degrees");
  check_range("cliff blend", bands.cliff_blend_deg, 0.0, 45.0, " degrees");
  check_range("snow maximum slope", bands.snow_max_slope_deg, 0.0, 90.0, " degrees");
  check_range("fog density", fog_density, 0.0, 10.0);
  check_range("ambient occlusion", ambient_occlusion, 0.0, 1.0);
  check_range("antialiasing samples", samples, 1, 16);
  check_range("maximum mesh samples", max_mesh_samples, 65, 4097);
  check_range("maximum texture samples", max_texture_samples, 65, 8193);
  for (const auto& [name, colour] : {std::pair{"water_shallow", palette.water_shallow}, {"water_deep", palette.water_deep},
                                     {"seabed", palette.seabed}, {"beach", palette.beach}, {"forest_low", palette.forest_low},
                                     {"forest_high", palette.forest_high}, {"cliff", palette.cliff}, {"snow", palette.snow},
                                     {"earth", palette.earth}, {"sky_zenith", palette.sky_zenith},
                                     {"sky_horizon", palette.sky_horizon}, {"sun", palette.sun}}) {
    for (float channel : {colour.r, colour.g, colour.b})
      if (!(channel >= 0.0f && channel <= 1.0f))
        fail("palette colour {} has channel {}: each of r, g, b must be between 0 and 1", name, channel);
  }
}

}  // namespace sansui::render
