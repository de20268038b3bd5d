#include "look/render_params.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/error.hpp"

namespace sansui::look {

std::optional<View> view_from_name(std::string_view name) {
  if (name == "perspective") return View::perspective;
  if (name == "block") return View::block;
  if (name == "top") return View::top;
  if (name == "front") return View::front;
  if (name == "side") return View::side;
  return std::nullopt;
}

std::optional<LandLines> land_lines_from_name(std::string_view name) {
  if (name == "climate") return LandLines::climate;
  if (name == "paper") return LandLines::paper;
  return std::nullopt;
}

double tree_line_fraction(const Land& land) {
  if (!lines_resolved(land)) fail("the land's tree and snow lines are not resolved");
  return land.lines == LandLines::climate ? *land.tree_line_m / climate_band_scale_m : *land.tree_line;
}

double snow_line_fraction(const Land& land) {
  if (!lines_resolved(land)) fail("the land's tree and snow lines are not resolved");
  return land.lines == LandLines::climate ? *land.snow_line_m / climate_band_scale_m : *land.snow_line;
}

bool lines_resolved(const Land& land) {
  return land.lines == LandLines::climate ? land.tree_line_m && land.snow_line_m : land.tree_line && land.snow_line;
}

std::string mixed_lines_problem(const Land& land) {
  if (land.lines == LandLines::climate && (land.tree_line || land.snow_line))
    return fmt::format(
        "land.{} is a fraction of the highest point, read with land.lines = \"paper\" only; with lines = \"climate\" give "
        "land.{}_m in metres",
        land.tree_line ? "tree_line" : "snow_line", land.tree_line ? "tree_line" : "snow_line");
  if (land.lines == LandLines::paper && (land.tree_line_m || land.snow_line_m))
    return fmt::format(
        "land.{}_m is in metres, read with land.lines = \"climate\" only; with lines = \"paper\" give land.{} as a "
        "fraction of the highest point",
        land.tree_line_m ? "tree_line" : "snow_line", land.tree_line_m ? "tree_line" : "snow_line");
  return "";
}

std::string_view view_name(View view) {
  switch (view) {
    case View::top:
      return "top";
    case View::front:
      return "front";
    case View::side:
      return "side";
    case View::block:
      return "block";
    case View::perspective:
      break;
  }
  return "perspective";
}

const params::Table<Camera>& parameter_table(const Camera*) {
  using P = Camera;
  static const auto table =
      params::Table<P>("camera", "The orbiting camera of the perspective view; distances in terrain sizes (the longer side)")
          .add(params::field("azimuth", &P::azimuth_deg)
                   .in(-360, 360)
                   .units("deg")
                   .doc("Compass bearing from the target to the camera (180: from the south, looking north)"))
          .add(params::field("elevation", &P::elevation_deg)
                   .in(-89, 89)
                   .units("deg")
                   .doc("Camera height as an angle above the target (1..89); a walkthrough camera's pitch (-89..89)"))
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
                   .doc("Point looked at, as X,Y fractions of the terrain (x east, y south)"))
          .add(params::field("eye_height", &P::eye_height_m)
                   .in(0.1, 10000)
                   .units("m")
                   .unset("the orbiting camera")
                   .doc("Walkthrough: the eye this high above the ground at `target`, looking toward `azimuth` (distance ignored)"))
          .add(params::field("name", &P::name).doc("The camera's name, for render outputs of a scene with several [[camera]] tables"));
  return table;
}

const params::Table<Land>& parameter_table(const Land*) {
  using P = Land;
  static const auto table =
      params::Table<P>("land",
                       "The land's colour bands (Oka et al. 1997, Sec. 4.1.2): tree and snow lines in metres from the climate, or "
                       "Table 4's fractions of the highest point; colours R,G,B in sRGB 0..1")
          .add(params::choice("lines", &P::lines, {{"climate", LandLines::climate}, {"paper", LandLines::paper}})
                   .doc("Where the tree and snow lines come from: climate (metres above sea level from the climate, latitude, "
                        "season and weather, the same on every tile) or paper (Table 4: fractions of the highest point)"))
          .add(params::field("tree_line_m", &P::tree_line_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("the climate's at the latitude")
                   .doc("Tree line in metres above sea level (lines = \"climate\"): forest below, bare rock above"))
          .add(params::field("snow_line_m", &P::snow_line_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("the climate's at the latitude, season and weather")
                   .doc("Snow line in metres above sea level (lines = \"climate\"): snow above, on gentle slopes"))
          .add(params::field("tree_line", &P::tree_line)
                   .in(0, 1)
                   .no_unit()
                   .unset("the climate's (Table 4)")
                   .doc("Tree line as a fraction of the highest point (lines = \"paper\"): forest below, bare cliff rock above"))
          .add(params::field("snow_line", &P::snow_line)
                   .in(0, 1)
                   .no_unit()
                   .unset("the climate's and season's (Table 4)")
                   .doc("Snow line as a fraction of the highest point (lines = \"paper\"): snow above, on gentle slopes"))
          .add(params::field("beach_top", &P::beach_top)
                   .in(0, 1)
                   .no_unit()
                   .doc("Top of the sand on the shore, a fraction of the band scale (1,000 m, so 0.005 is 5 m above the sea; paper: "
                        "the highest point); no sand higher up"))
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
          .add(params::field("cover_slope", &P::cover_slope_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Pictures: slopes up to this hold a closed plant cover, steeper ones are bare soil, then rock from cliff_slope "
                        "or 4 degrees above this")
                   .unset("the climate's (data/climate.toml)"))
          .add(params::field("snow_max_slope", &P::snow_max_slope_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Snow does not lie on slopes steeper than this"))
          .add(params::field("sunny_side", &P::sunny_azimuth_deg)
                   .in(0, 360)
                   .units("deg")
                   .unset("toward the equator from the scene's latitude (180 north of it, 0 south of it)")
                   .doc("Compass bearing the sunny slopes face: drier, yellower ground there, snow lower on the faces turned away"))
          .add(params::field("beach", &P::beach).unset("the climate's").doc("Low rock and sand just above the sea"))
          .add(params::field("forest_low", &P::forest_low).unset("the climate's and season's").doc("Forest at the coast end of its band"))
          .add(params::field("forest_high", &P::forest_high).unset("the climate's and season's").doc("Forest near the tree line"))
          .add(params::field("cliff", &P::cliff).unset("the climate's").doc("Bare rock: above the tree line and on steep slopes"))
          .add(params::field("snow", &P::snow).unset("the climate's").doc("Snow"))
          .add(params::field("earth", &P::earth).unset("the climate's").doc("The cut sides of the terrain block (perspective view)"));
  return table;
}

const params::Table<Sea>& parameter_table(const Sea*) {
  using P = Sea;
  static const auto table =
      params::Table<P>("sea", "The sea's look: colours by depth (R,G,B in sRGB 0..1), white-noise ripples, foam on the shallows")
          .add(params::field("shallow", &P::shallow).unset("the climate's").doc("Sea over the shallows, where the seabed shows through"))
          .add(params::field("deep", &P::deep).unset("the climate's").doc("Open deep sea"))
          .add(params::field("seabed", &P::seabed).unset("the climate's").doc("Ground under water, seen through the shallows"))
          .add(params::field("ripple", &P::ripple).in(0, 4).no_unit().doc("Strength of the ripples on the surface; 0 a mirror"))
          .add(params::field("foam", &P::foam_depth_m)
                   .at_most(1e4)
                   .at_least(0)
                   .units("m")
                   .doc("Water shallower than this foams; 0: no foam"));
  return table;
}

const params::Table<Sky>& parameter_table(const Sky*) {
  using P = Sky;
  static const auto table =
      params::Table<P>(
          "sky", "The sky around the viewer: colour model, stars at night, the sun's disc and light, clouds (Oka et al. 1997, Sec. 4.2)")
          .add(
              params::choice("model", &P::model, {{"preetham", SkyModel::preetham}, {"table2", SkyModel::table2}})
                  .doc(
                      "Sky colour: preetham (Preetham, Shirley, Smits 1999, with twilight) or table2 (the paper's Table 2, reconstructed)"))
          .add(params::field("turbidity", &P::turbidity)
                   .in(2, 10)
                   .no_unit()
                   .unset("the weather's")
                   .doc("Haze of the air: 2 very clear, 10 hazy"))
          .add(params::field("sunlight", &P::sunlight).unset("by the sun's elevation (Table 3)").doc("Colour of direct sunlight"))
          .add(params::field("sun_strength", &P::sun_strength)
                   .in(0, 1)
                   .no_unit()
                   .unset("the weather's")
                   .doc("Strength of direct sunlight: 1 clear, toward 0 overcast"))
          .add(params::field("stars", &P::stars).doc("Draw stars when the sky is dark"))
          .add(params::field("star_count", &P::star_count).in(0, 100000).doc("Stars on the whole sphere"))
          .add(params::field("seed", &P::seed).doc("Seed of the stars and the clouds"))
          .add(params::field("cloud_cover", &P::cloud_cover)
                   .in(0, 1)
                   .no_unit()
                   .unset("the weather's")
                   .doc("Fraction of the sky covered by clouds"))
          .add(params::field("cloud_fineness", &P::cloud_fineness)
                   .in(0.05, 1)
                   .no_unit()
                   .unset("the weather's")
                   .doc("Hurst exponent of the cloud image: larger is smoother, smaller more broken"));
  return table;
}

const params::Table<Atmosphere>& parameter_table(const Atmosphere*) {
  using P = Atmosphere;
  static const auto table = params::Table<P>("atmosphere", "Distance fog and aerial perspective, coloured by the sky near the horizon")
                                .add(params::field("fog", &P::fog)
                                         .in(0, 10)
                                         .no_unit()
                                         .unset("the weather's")
                                         .doc("Distance fog: exp(-fog) of the light is kept over one terrain size of depth; 0 off"));
  return table;
}

const params::Table<RenderParams>& parameter_table(const RenderParams*) {
  using P = RenderParams;
  static const auto table =
      params::Table<P>("render", "A picture of the terrain, drawn with OpenGL (headless or in the viewer): view, exaggeration, shadows")
          .add(params::field("width", &P::width).in(16, 8192).units("px").doc("Picture width"))
          .add(params::field("height", &P::height)
                   .in(16, 8192)
                   .units("px")
                   .unset("720; top view: the width times the terrain's aspect")
                   .doc("Picture height"))
          .add(params::choice("view", &P::view,
                              {{"perspective", View::perspective},
                               {"block", View::block},
                               {"top", View::top},
                               {"front", View::front},
                               {"side", View::side}})
                   .doc("perspective (the terrain in its world, out to the horizon, with sky and fog), block (the terrain alone as a "
                        "block in the sky), top (straight down, north up), front (level, from the south) or side (level, from the east)"))
          .add(params::choice("beyond", &P::beyond, {{"land", Beyond::land}, {"sea", Beyond::sea}})
                   .doc("What the perspective view shows past the terrain's edge: its land going on to the horizon, or open sea"))
          .add(params::pair("sun", &P::sun_azimuth_deg, &P::sun_elevation_deg)
                   .rule(
                       [](const params::Value& v) {
                         const double elevation = std::get<std::vector<double>>(v)[1];
                         return elevation >= -90.0 && elevation <= 90.0 ? "" : "AZIMUTH,ELEVATION with the elevation -90..90";
                       },
                       "AZIMUTH,ELEVATION with the elevation -90..90")
                   .units("deg")
                   .unset("from [time]")
                   .internal())
          .add(params::opaque("camera", &P::camera))
          .add(params::field("exaggeration", &P::exaggeration)
                   .in(0.1, 20)
                   .no_unit()
                   .doc("Vertical exaggeration of the drawn heights (colour bands use true heights)"))
          .add(params::field("sea_level", &P::sea_level_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .doc("Sea level: water below it, and the zero of the elevation bands"))
          .add(params::field("sea", &P::sea).doc("Draw the sea; false: all land, bands measured from 1 m below the lowest point"))
          .add(params::field("draw_water", &P::rivers)
                   .unset("on eroded terrain (an erode step)")
                   .doc("Draw rivers and lakes, from flow routing over the terrain ([flow])"))
          .add(params::opaque("land", &P::land))
          .add(params::opaque("water", &P::water))
          .add(params::opaque("sky", &P::sky))
          .add(params::opaque("atmosphere", &P::atmosphere))
          .add(params::field("time", &P::time_s).at_least(0).units("s").unset("from [time]").internal())
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

void Camera::validate() const {
  params::validate(*this);
  if (!eye_height_m && elevation_deg < 1.0)
    fail(
        "camera.elevation {} is below 1 degree: an orbiting camera stays above its target (allowed 1..89; -89..89 with "
        "camera.eye_height, a walkthrough)",
        elevation_deg);
}

void RenderParams::validate() const {
  params::validate(*this);
  camera.validate();
  params::validate(land);
  if (const std::string problem = mixed_lines_problem(land); !problem.empty()) fail("{}", problem);
  params::validate(water);
  params::validate(sky);
  params::validate(atmosphere);
}

RenderParams with_fallbacks(RenderParams p) {
  // A temperate summer afternoon: Table 4's Cfb lines and the palette Sansui has always used.
  auto fill = [](auto& value, auto fallback) {
    if (!value) value = fallback;
  };
  fill(p.sun_azimuth_deg, 300.0);
  fill(p.sun_elevation_deg, 32.0);
  if (p.land.lines == LandLines::climate) {
    // The climate table's Cfb at 45 degrees in summer (docs/climate.md).
    fill(p.land.tree_line_m, 2200.0);
    fill(p.land.snow_line_m, 2850.0);
  } else {
    fill(p.land.tree_line, 0.50);
    fill(p.land.snow_line, 0.75);
  }
  fill(p.land.sunny_azimuth_deg, 180.0);
  fill(p.land.cover_slope_deg, p.land.cliff_slope_deg - 4.0);
  fill(p.land.beach, Rgb{0.72f, 0.66f, 0.52f});
  fill(p.land.forest_low, Rgb{0.24f, 0.36f, 0.14f});
  fill(p.land.forest_high, Rgb{0.13f, 0.24f, 0.11f});
  fill(p.land.cliff, Rgb{0.45f, 0.41f, 0.37f});
  fill(p.land.snow, Rgb{0.95f, 0.96f, 0.99f});
  fill(p.land.earth, Rgb{0.50f, 0.40f, 0.30f});
  fill(p.water.shallow, Rgb{0.20f, 0.52f, 0.58f});
  fill(p.water.deep, Rgb{0.03f, 0.13f, 0.28f});
  fill(p.water.seabed, Rgb{0.62f, 0.58f, 0.45f});
  fill(p.sky.turbidity, 3.0);
  fill(p.sky.sun_strength, 1.0);
  fill(p.sky.sunlight, sun_colour(*p.sun_elevation_deg));
  fill(p.sky.cloud_cover, 0.0);
  fill(p.sky.cloud_fineness, 0.6);
  fill(p.atmosphere.fog, 0.2);
  return p;
}

int resolved_height(const RenderParams& params, const Heightfield& heights) {
  if (params.height) return *params.height;
  if (params.view != View::top || heights.empty()) return 720;
  const double aspect = static_cast<double>(heights.height() - 1) / std::max(heights.width() - 1, 1);
  return std::clamp(static_cast<int>(std::lround(params.width * aspect)), 16, 8192);
}

budget::Cost render_cost(const RenderParams& params, int height) {
  const double pixels = static_cast<double>(params.width) * static_cast<double>(height);
  const int samples = pixels > static_cast<double>(max_multisampled_pixels) ? 1 : std::max(params.samples, 1);
  budget::Cost cost;
  // Measured (tests/cli/budget_cli_test.cpp): about 10 bytes a sample and 14 a pixel besides
  // (llvmpipe's colour and depth per sample; the resolved target, the read-back image and the
  // PNG's rows per pixel; 16 and 28 before the PNG was compressed once, with lighter settings,
  // in issue 32); 8192^2 pictures take about half of that.
  cost.bytes = pixels * (10.0 * samples + 14.0);
  cost.seconds = pixels * (0.2e-6 + 0.04e-6 * samples);
  cost.what = fmt::format("a {} x {} picture with {} sample{} a pixel", params.width, height, samples, samples > 1 ? "s" : "");
  cost.smaller = "give a smaller width and height, or fewer samples";
  return cost;
}

double effective_sea_level(const RenderParams& params, const Heightfield& heights) {
  if (params.sea || heights.empty()) return params.sea_level_m;
  float low = heights.values()[0];
  for (float h : heights.values()) low = std::min(low, h);
  return static_cast<double>(low) - 1.0;
}

}  // namespace sansui::look
