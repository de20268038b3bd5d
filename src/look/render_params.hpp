// What a terrain picture looks like: image size, view and camera, sun, vertical exaggeration,
// sea level, the land's elevation/slope colour bands of Oka et al. 1997 (seeds/003, Sec. 4.1.2;
// SPEC 3.2: under the sea blue, low rock, forest, then cliff to snow, linearly blended at the
// borders, steep slopes in cliff colour), the sea, the sky and the atmosphere (SPEC 3.4). Values
// a scene derives from climate, season, weather and time are optional here: unset means
// "derived" (or, without a scene, the renderer's temperate fallback, with_fallbacks()).
//
// Plain values only: the CLI, a scene file and the viewer all fill this struct.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/budget.hpp"
#include "core/color.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "look/sky_model.hpp"
#include "look/surroundings.hpp"

namespace sansui::look {

using sansui::Rgb;

enum class View {
  perspective,  ///< the terrain inside its world, land or sea out to the horizon, with sky and fog
  block,        ///< the terrain alone as a block cut out of the ground, floating in the sky (seed 000, Fig. 17)
  top,          ///< orthographic, straight down, north up, the whole terrain in the picture
  front,        ///< orthographic, level, from the south looking north (an elevation drawing)
  side,         ///< orthographic, level, from the east looking west
};

/// "perspective", "block", "top", "front" or "side"; nullopt for anything else.
std::optional<View> view_from_name(std::string_view name);
std::string_view view_name(View view);

/// The orbiting camera of the perspective view. Distances are in terrain sizes (the longer
/// horizontal side of the terrain), so the same values frame a 1 km and a 100 km terrain alike.
/// Table: render_params.cpp (section [render.camera]).
struct Camera {
  /// Compass bearing from the target to the camera, clockwise from north (180: the camera
  /// stands south of the target and looks north, so north is at the top as in the top view).
  /// [Units: degrees] [Range: any, taken modulo 360] [Default: 200]
  double azimuth_deg = 200.0;
  /// Angle of the camera above the target's horizontal plane; a walkthrough camera's pitch.
  /// [Units: degrees] [Range: 1..89; walkthrough -89..89] [Default: 25]
  double elevation_deg = 25.0;
  /// Distance from the target; 0 fits the whole terrain in the picture, centred across it and
  /// with the top part left for the sky (the target then sets the direction of view, not the
  /// picture's centre). [Units: terrain sizes] [Range: 0 or 0.05..20] [Default: 0 (fit)]
  double distance = 0.0;
  /// Vertical field of view. [Units: degrees] [Range: 5..120] [Default: 40]
  double fov_deg = 40.0;
  /// The point looked at, as fractions of the terrain's extent: x east from the west edge,
  /// y south from the north edge; its height is the terrain's mean height above sea level
  /// (or sea level where that is higher). [Range: 0..1 each] [Default: 0.5, 0.5]
  double target_x = 0.5;
  double target_y = 0.5;
  /// Walkthrough: the eye stands this high above the ground (or the sea, where it is higher)
  /// at `target`, looks toward the bearing `azimuth_deg` and `elevation_deg` above the horizon
  /// (negative: down); `distance` is then ignored. Unset: the orbiting camera.
  /// [Units: m] [Range: 0.1..10000] [Default: unset]
  std::optional<double> eye_height_m;
  /// A scene's cameras are told apart by name: a render output picks one with `camera = NAME`.
  /// [Default: "" (the first camera needs none)]
  std::string name;

  /// Throws InputError naming the first bad value and what is allowed.
  void validate() const;
};

/// Where the land's tree and snow lines come from.
enum class LandLines {
  /// In metres above sea level, from the climate, latitude, season and weather (published
  /// figures, docs/climate.md), the same on every tile of a world. The band widths (beach_top,
  /// band_blend, band_noise) are fractions of climate_band_scale_m.
  climate,
  /// Oka et al. 1997, Table 4 read literally: fractions of the highest point above sea level (at
  /// least min_band_relief_m), so each tile and each hill has its own lines.
  paper,
};
std::optional<LandLines> land_lines_from_name(std::string_view name);

/// The land's colour bands (Oka et al. 1997, Sec. 4.1.2): under the sea, low rock and sand, forest
/// up to the tree line, bare rock above it and on steep slopes, snow above the snow line. With
/// `lines = "climate"` (the default) the lines are heights in metres; with `lines = "paper"` they
/// are fractions of the maximum elevation above sea level as in the paper's Table 4 (band_scale_m()).
/// Unset values come from the climate, season and weather (scene/climate.hpp), or, without a
/// scene, from the temperate daytime fallbacks (with_fallbacks()).
/// Table: render_params.cpp (section [land]).
struct Land {
  /// Where the tree and snow lines come from. [Default: climate (recipes before version 4: paper)]
  LandLines lines = LandLines::climate;
  /// Tree line in metres above sea level (lines = "climate"). [Units: m] [Default: unset: the
  /// climate's at the latitude]
  std::optional<double> tree_line_m;
  /// Snow line in metres above sea level (lines = "climate"). [Units: m] [Default: unset: the
  /// climate's at the latitude, season and weather]
  std::optional<double> snow_line_m;
  /// Tree line (lines = "paper"): forest below, bare cliff rock above. [Range: 0..1] [Default: unset: Table 4]
  std::optional<double> tree_line;
  /// Snow line (lines = "paper"): snow above (on slopes gentler than snow_max_slope_deg).
  /// [Range: 0..1] [Default: unset: Table 4]
  std::optional<double> snow_line;
  /// Top of the sand on the shore: a fraction of the band scale (lines = "climate": 1,000 m, so the
  /// default is 5 m above sea level). [Range: 0..1] [Default: 0.005]
  double beach_top = 0.005;
  /// Width of the linear blend across each band border. [Range: 0..0.5] [Default: 0.06]
  double blend = 0.06;
  /// Irregularity of the band borders: each border moves up or down by up to this much,
  /// following a smooth noise over the ground, so they do not look like contour lines.
  /// [Range: 0..0.5] [Default: 0.05]
  double border_noise = 0.05;
  /// Slopes steeper than this are bare cliff rock, whatever the elevation (true slope, before
  /// vertical exaggeration). [Units: degrees] [Range: 0..90] [Default: 38]
  double cliff_slope_deg = 38.0;
  /// Width of the blend into cliff colour around cliff_slope_deg. [Units: degrees] [Range: 0..45] [Default: 10]
  double cliff_blend_deg = 10.0;
  /// Pictures: slopes up to this hold a closed plant cover; steeper ones turn to bare soil, and to
  /// rock from cliff_slope_deg or 4 degrees above this, whichever is steeper (a rainforest is green
  /// to its ridges, a desert bare on gentle slopes). [Units: degrees] [Range: 0..90] [Default:
  /// unset: the climate's (data/climate.toml); cliff_slope_deg - 4 without a climate]
  std::optional<double> cover_slope_deg;
  /// Snow does not lie on slopes steeper than this. [Units: degrees] [Range: 0..90] [Default: 48]
  double snow_max_slope_deg = 48.0;
  /// Compass bearing the sunny slopes face (drier, yellower ground; snow lies lower on the faces
  /// turned away). [Units: degrees] [Range: 0..360] [Default: unset: toward the equator from the
  /// scene's latitude, 180 north of it and 0 south of it; 180 without a scene]
  std::optional<double> sunny_azimuth_deg;
  /// Colours in sRGB. [Default: unset: the climate's palette]
  std::optional<Rgb> beach;        ///< low rock and sand just above the sea
  std::optional<Rgb> forest_low;   ///< forest at the coast end of its band
  std::optional<Rgb> forest_high;  ///< forest near the tree line (conifers, darker)
  std::optional<Rgb> cliff;        ///< bare rock: above the tree line and on steep slopes
  std::optional<Rgb> snow;
  std::optional<Rgb> earth;  ///< the cut sides of the terrain block (perspective view)
};

/// The sea's look (SPEC 3.4): colours by depth, ripples, foam on the shallows.
/// Table: render_params.cpp (section [sea]).
struct Sea {
  std::optional<Rgb> shallow;  ///< sea over the shallows, where the seabed shows through. [Default: unset: the climate's]
  std::optional<Rgb> deep;     ///< open deep sea. [Default: unset: the climate's]
  std::optional<Rgb> seabed;   ///< ground under water, seen through the shallows. [Default: unset: the climate's]
  /// Strength of the white-noise ripples on the surface; 0 a mirror. [Range: 0..4] [Default: 1]
  double ripple = 1.0;
  /// Water shallower than this foams. 0: no foam. [Units: m] [Range: >= 0] [Default: 0.6]
  double foam_depth_m = 0.6;
};

/// The sky on a sphere around the viewer, in four layers (SPEC 3.4): colour (a model), stars
/// (at night), the sun (a disc coloured by its elevation, Table 3) and clouds.
/// Table: render_params.cpp (section [sky]).
struct Sky {
  /// The sky's colour model. [Default: preetham]
  SkyModel model = SkyModel::preetham;
  /// Haze of the air (Preetham's T): 2 very clear, 10 hazy. [Range: 2..10] [Default: unset: the weather's]
  std::optional<double> turbidity;
  /// Colour of direct sunlight. [Default: unset: by the sun's elevation, Table 3]
  std::optional<Rgb> sunlight;
  /// Strength of direct sunlight, 0 (overcast) to 1. [Range: 0..1] [Default: unset: the weather's]
  std::optional<double> sun_strength;
  /// Draw stars when the sky is dark. [Default: true]
  bool stars = true;
  /// Stars on the whole sphere. [Range: 0..100000] [Default: 6000]
  int star_count = 6000;
  /// Seed of the stars (and of the clouds). [Default: 1]
  std::uint64_t seed = 1;
  /// Fraction of the sky covered by clouds. [Range: 0..1] [Default: unset: the weather's]
  std::optional<double> cloud_cover;
  /// Hurst exponent of the cloud image: larger is smoother, smaller more broken and fine.
  /// [Range: 0.05..1] [Default: unset: the weather's]
  std::optional<double> cloud_fineness;
};

/// Distance fog and aerial perspective, coloured by the sky near the horizon.
/// Table: render_params.cpp (section [atmosphere]).
struct Atmosphere {
  /// Strength of the distance fog (perspective view): the fraction of light kept over one
  /// terrain size of distance beyond the terrain's nearest point is exp(-fog). 0 turns fog off.
  /// [Range: 0..10] [Default: unset: the weather's]
  std::optional<double> fog;
};

struct RenderParams {
  /// Picture width. [Units: pixels] [Range: 16..8192] [Default: 1280]
  int width = 1280;
  /// Picture height. [Units: pixels] [Range: 16..8192] [Default: unset: 720; the top view:
  /// the width times the terrain's aspect, so the terrain fills the picture]
  std::optional<int> height;
  /// [Default: perspective]
  View view = View::perspective;
  /// What the perspective view shows beyond the terrain: its land going on to the horizon, or
  /// open sea (look/surroundings.hpp). [Default: land]
  Beyond beyond = Beyond::land;
  /// Where the sun stands: compass bearing clockwise from north, and height above the horizon
  /// (negative below it). [Units: degrees] [Range: elevation -90..90] [Default: unset: from the
  /// scene's date, time and latitude; without a scene 300, 32 (from the upper left of the top
  /// view, as relief maps are lit)]
  std::optional<double> sun_azimuth_deg, sun_elevation_deg;
  /// Perspective camera (ignored by the top view).
  Camera camera;
  /// Vertical exaggeration: heights are drawn (and shaded) multiplied by this. Colour bands
  /// and cliff slopes use the true heights. [Range: 0.1..20] [Default: 1.5]
  double exaggeration = 1.5;
  /// Sea level: below it a water plane, tinted by depth. [Units: m] [Default: 0]
  double sea_level_m = 0.0;
  /// Draw rivers and lakes (flow routing over the terrain, [flow]). [Default: unset: when the
  /// heightfield went through an erode step]
  std::optional<bool> rivers;
  /// Draw the sea. false: no water anywhere, and sea level (the zero of the bands) is taken 1 m
  /// below the lowest point, so a mountain standing on high ground is all land. [Default: true]
  bool sea = true;
  Land land;
  Sea water;
  Sky sky;
  Atmosphere atmosphere;
  /// Seconds since midnight, for the motion of the ripples. [Units: s] [Range: >= 0] [Default: 0]
  double time_s = 0.0;
  /// Cast shadows (a horizon mask traced from the sun over the heightfield). [Default: true]
  bool shadows = true;
  /// Darkening of hollows by ambient occlusion, 0 off, 1 full. [Range: 0..1] [Default: 1]
  double ambient_occlusion = 1.0;
  /// Antialiasing samples per pixel (clamped to what the driver offers; headless pictures over
  /// 16 megapixels use 1). [Range: 1..16] [Default: 4]
  int samples = 4;
  /// Heightfields with more samples per side are averaged down to at most this for the GPU
  /// mesh, and to at most a quarter of the picture's longer side (but not below 129): the mesh
  /// only shapes silhouettes, since per-pixel normals and colours come from the finer texture
  /// below, and a software rasteriser pays dearly for triangles smaller than 4x4 pixels.
  /// [Range: 65..4097] [Default: 1025]
  int max_mesh_samples = 1025;
  /// ... and to at most this for the height texture that per-pixel normals and colours come
  /// from (shadows and ambient occlusion are traced on at most 1025 per side). [Range: 65..8193] [Default: 2049]
  int max_texture_samples = 2049;

  /// Throws InputError naming the first bad value and what is allowed.
  void validate() const;
};
const params::Table<Camera>& parameter_table(const Camera*);
const params::Table<Land>& parameter_table(const Land*);
const params::Table<Sea>& parameter_table(const Sea*);
const params::Table<Sky>& parameter_table(const Sky*);
const params::Table<Atmosphere>& parameter_table(const Atmosphere*);

/// `params` with every unset look value filled in by the renderer's own fallbacks: a temperate
/// summer afternoon (Table 4's Cfb lines, a green and grey palette, a clear sky, the sun at
/// 300, 32). A scene fills these from its climate first (scene/look.hpp); this is for callers
/// of the renderer without one.
RenderParams with_fallbacks(RenderParams params);
const params::Table<RenderParams>& parameter_table(const RenderParams*);

/// The picture height: params.height, or its default for `heights` (see RenderParams::height).
int resolved_height(const RenderParams& params, const Heightfield& heights);

/// Headless pictures with more pixels than this are drawn with one sample a pixel: a 4-sample
/// 8192^2 target would need 2 GB.
inline constexpr long long max_multisampled_pixels = 16'000'000;

/// What drawing a width x `height` picture takes, before any GL context or target exists: its
/// multisampled colour and depth, the resolved colour, the read-back image and the PNG's rows
/// (measured with `sansui render` at 1536^2..4096^2: 44 bytes a pixel with one sample, 92 with
/// four), and 0.2 microseconds a pixel plus 0.04 a sample on llvmpipe.
budget::Cost render_cost(const RenderParams& params, int height);

/// The sea level the picture uses: params.sea_level_m, or without a sea 1 m below the lowest
/// point of `heights`. [Units: m]
double effective_sea_level(const RenderParams& params, const Heightfield& heights);

/// The least height above sea level the land's colour bands are fractions of: Table 4's bands
/// describe mountains; land lower than this stays in the beach and forest bands. [Units: m]
inline constexpr double min_band_relief_m = 500.0;

/// With lines = "climate", the land's band widths (beach_top, blend, border_noise) are fractions
/// of this height, the same on every tile: a 40 m beach band and 60 m blends. [Units: m]
inline constexpr double climate_band_scale_m = 1000.0;

/// The height the land's colour band fractions (Land) are fractions of: with lines = "paper" the
/// highest point above the (effective) sea level, at least min_band_relief_m; with lines =
/// "climate", climate_band_scale_m. [Units: m]
inline double band_scale_m(const Land& land, double sea_level_m, double highest_m) {
  if (land.lines == LandLines::climate) return climate_band_scale_m;
  return highest_m - sea_level_m > min_band_relief_m ? highest_m - sea_level_m : min_band_relief_m;
}

/// The resolved tree and snow lines as fractions of band_scale_m(land, ...). Throws InputError
/// when they are not resolved (with_fallbacks() or a scene's look settles them).
double tree_line_fraction(const Land& land);
double snow_line_fraction(const Land& land);
/// True when the lines `land.lines` reads are set.
bool lines_resolved(const Land& land);

/// "" when `land` gives values of one kind of line only, else the problem in words: the metre
/// lines belong with lines = "climate", the fractions with lines = "paper".
std::string mixed_lines_problem(const Land& land);

}  // namespace sansui::look
