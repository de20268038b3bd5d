#include "render/render_params.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace sansui::render {

std::optional<View> view_from_name(std::string_view name) {
  if (name == "perspective") return View::perspective;
  if (name == "top") return View::top;
  return std::nullopt;
}

std::string_view view_name(View view) {
  return view == View::top ? "top" : "perspective";
}

const params::Table<Camera>& parameter_table(const Camera*) {
  using P = Camera;
  static const auto table =
      params::Table<P>("camera", "The orbiting camera of the perspective view; distances in terrain sizes (the longer side)")
          .add(params::field("azimuth", &P::azimuth_deg)
                   .units("deg")
                   .doc("Compass bearing from the target to the camera (180: from the south, looking north)"))
          .add(params::field("elevation", &P::elevation_deg).in(1, 89).units("deg").doc("Camera height as an angle above the target"))
          .add(params::field("distance", &P::distance)
                   .in(0, 20)
                   .rule(
                       [](const params::Value& v) {
                         return std::get<double>(v) == 0.0 || std::get<double>(v) >= 0.05 ? "" : "0 or 0.05..20";
                       },
                       "0 fits the whole terrain")
                   .units("terrain sizes")
                   .doc("Camera distance from the target; 0 fits the whole terrain in the picture"))
          .add(params::field("fov", &P::fov_deg).in(5, 120).units("deg").alias("--fov").doc("Vertical field of view"))
          .add(params::pair("target", &P::target_x, &P::target_y)
                   .no_unit()
                   .in(0, 1)
                   .alias("--target")
                   .doc("Point looked at, as X,Y fractions of the terrain (x east, y south)"));
  return table;
}

const params::Table<Bands>& parameter_table(const Bands*) {
  using P = Bands;
  static const auto table =
      params::Table<P>(
          "bands",
          "Elevation and slope colour bands (seed 003 Sec. 4.1.2, Table 4); elevations are fractions of the highest point above sea level")
          .add(params::field("beach_top", &P::beach_top).in(0, 1).no_unit().doc("Top of the low rock / beach band just above the sea"))
          .add(params::field("tree_line", &P::tree_line)
                   .in(0, 1)
                   .no_unit()
                   .doc("Tree line: forest below, bare cliff rock above (Table 4, temperate: 0.5)"))
          .add(params::field("snow_line", &P::snow_line)
                   .in(0, 1)
                   .no_unit()
                   .doc("Snow line: snow above, on gentle slopes (Table 4, temperate: 0.75)"))
          .add(params::field("band_blend", &P::blend).in(0, 0.5).no_unit().doc("Width of the linear blend across each band border"))
          .add(params::field("band_noise", &P::border_noise)
                   .in(0, 0.5)
                   .no_unit()
                   .doc("Band borders move up or down by up to this much, so they do not follow contours"))
          .add(params::field("cliff_slope", &P::cliff_slope_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Slopes steeper than this are bare cliff (true slope, before exaggeration)"))
          .add(params::field("cliff_blend", &P::cliff_blend_deg)
                   .in(0, 45)
                   .units("deg")
                   .doc("Width of the blend into cliff colour around cliff_slope"))
          .add(params::field("snow_max_slope", &P::snow_max_slope_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Snow does not lie on slopes steeper than this"));
  return table;
}

const params::Table<Palette>& parameter_table(const Palette*) {
  using P = Palette;
  static const auto table =
      params::Table<P>("palette", "Colours of the bands, the sea and the sky: R,G,B in sRGB, each 0..1")
          .add(params::field("water_shallow", &P::water_shallow).doc("Sea over the shallows, where the seabed shows through"))
          .add(params::field("water_deep", &P::water_deep).doc("Open deep sea"))
          .add(params::field("seabed", &P::seabed).doc("Ground under water, seen through the shallows"))
          .add(params::field("beach", &P::beach).doc("Low rock and sand just above the sea"))
          .add(params::field("forest_low", &P::forest_low).doc("Forest at the coast end of its band"))
          .add(params::field("forest_high", &P::forest_high).doc("Forest near the tree line (conifers, darker)"))
          .add(params::field("cliff", &P::cliff).doc("Bare rock: above the tree line and on steep slopes"))
          .add(params::field("snow", &P::snow).doc("Snow"))
          .add(params::field("earth", &P::earth).doc("The cut sides of the terrain block (perspective view)"))
          .add(params::field("sky_zenith", &P::sky_zenith).doc("Sky straight up"))
          .add(params::field("sky_horizon", &P::sky_horizon).doc("Sky at the horizon; also the colour of distance fog"))
          .add(params::field("sunlight", &P::sun).doc("Colour of direct sunlight"));
  return table;
}

const params::Table<RenderParams>& parameter_table(const RenderParams*) {
  using P = RenderParams;
  static const auto table =
      params::Table<P>("render", "A picture of the terrain, drawn with OpenGL (headless or in the viewer): bands, sun, shadows, sky, fog")
          .add(params::field("width", &P::width).in(16, 8192).units("px").doc("Picture width"))
          .add(params::field("height", &P::height)
                   .in(16, 8192)
                   .units("px")
                   .unset("720; top view: the width times the terrain's aspect")
                   .doc("Picture height"))
          .add(params::choice("view", &P::view, {{"perspective", View::perspective}, {"top", View::top}})
                   .doc("perspective (bird's-eye, with sky and fog) or top (straight down, north up)"))
          .add(params::pair("sun", &P::sun_azimuth_deg, &P::sun_elevation_deg)
                   .rule(
                       [](const params::Value& v) {
                         const double elevation = std::get<std::vector<double>>(v)[1];
                         return elevation >= 0.0 && elevation <= 90.0 ? "" : "AZIMUTH,ELEVATION with the elevation 0..90";
                       },
                       "AZIMUTH,ELEVATION with the elevation 0..90")
                   .units("deg")
                   .doc("Sun position: compass bearing clockwise from north, and height above the horizon"))
          .nest("camera.", "camera-", &P::camera, parameter_table(static_cast<const Camera*>(nullptr)))
          .add(params::field("exaggeration", &P::exaggeration)
                   .in(0.1, 20)
                   .no_unit()
                   .doc("Vertical exaggeration of the drawn heights (colour bands use true heights)"))
          .add(params::field("sea_level", &P::sea_level_m).units("m").doc("Sea level: water below it, and the zero of the elevation bands"))
          .add(params::field("sea", &P::sea).doc("Draw the sea; false: all land, bands measured from 1 m below the lowest point"))
          .nest("", "", &P::bands, parameter_table(static_cast<const Bands*>(nullptr)))
          .nest("palette.", "palette-", &P::palette, parameter_table(static_cast<const Palette*>(nullptr)))
          .add(params::field("fog", &P::fog_density)
                   .in(0, 10)
                   .no_unit()
                   .doc("Distance fog: exp(-fog) of the light is kept over one terrain size of depth; 0 off"))
          .add(params::field("shadows", &P::shadows).doc("Cast shadows (diffuse shading and ambient occlusion stay without)"))
          .add(params::field("ambient_occlusion", &P::ambient_occlusion).in(0, 1).no_unit().doc("Darkening of hollows: 0 off, 1 full"))
          .add(params::field("samples", &P::samples).in(1, 16).doc("Antialiasing samples per pixel (pictures over 16 megapixels use 1)"))
          .add(params::field("max_mesh_samples", &P::max_mesh_samples)
                   .in(65, 4097)
                   .doc("Heightfields are averaged down to at most this per side for the GPU mesh"))
          .add(params::field("max_texture_samples", &P::max_texture_samples)
                   .in(65, 8193)
                   .doc("... and to at most this for the height texture of per-pixel normals and colours"));
  return table;
}

void RenderParams::validate() const {
  params::validate(*this);
}

int resolved_height(const RenderParams& params, const Heightfield& heights) {
  if (params.height) return *params.height;
  if (params.view != View::top || heights.empty()) return 720;
  const double aspect = static_cast<double>(heights.height() - 1) / std::max(heights.width() - 1, 1);
  return std::clamp(static_cast<int>(std::lround(params.width * aspect)), 16, 8192);
}

double effective_sea_level(const RenderParams& params, const Heightfield& heights) {
  if (params.sea || heights.empty()) return params.sea_level_m;
  float low = heights.values()[0];
  for (float h : heights.values()) low = std::min(low, h);
  return static_cast<double>(low) - 1.0;
}

}  // namespace sansui::render
