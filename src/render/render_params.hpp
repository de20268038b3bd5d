// What a terrain picture looks like: image size, view and camera, sun, vertical exaggeration,
// sea level, and the elevation/slope colour bands of Oka et al. 1997 (seeds/003, Sec. 4.1.2;
// SPEC 3.2): under the sea blue, low rock, forest, then cliff to snow, linearly blended at the
// borders, with steep slopes in cliff colour. Band heights are fractions of the terrain's
// maximum elevation above sea level, as the paper's Table 4 gives them (TABLES-003.md); the
// defaults are Table 4's temperate climates (Cw, Cfa, Cfb, Cfc: tree line 50 %, snow line 75 %).
//
// Plain values only: the CLI, a scene file and the viewer all fill this struct.
#pragma once

#include <optional>
#include <string_view>

#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::render {

/// A colour in sRGB, each channel in [0, 1] (what a colour picker shows).
struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

enum class View {
  perspective,  ///< bird's-eye view from an orbiting camera, with sky and fog (seed 000, Fig. 17)
  top,          ///< orthographic, straight down, north up, the whole terrain in the picture
};

/// "perspective" or "top"; nullopt for anything else.
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
  /// Angle of the camera above the target's horizontal plane. [Units: degrees] [Range: 1..89] [Default: 25]
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
};

/// Elevation and slope bands. Elevations are fractions of the maximum elevation above sea
/// level (0 = the coast, 1 = the highest peak), as in the paper's Table 4.
/// Table: render_params.cpp (flattened into [render]).
struct Bands {
  /// Top of the low rock / beach band just above the sea. [Range: 0..1] [Default: 0.04]
  double beach_top = 0.04;
  /// Tree line: forest below, bare cliff rock above. [Range: 0..1] [Default: 0.50 (Table 4, temperate)]
  double tree_line = 0.50;
  /// Snow line: snow above (on slopes gentler than snow_max_slope_deg). [Range: 0..1] [Default: 0.75 (Table 4, temperate)]
  double snow_line = 0.75;
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
  /// Snow does not lie on slopes steeper than this. [Units: degrees] [Range: 0..90] [Default: 48]
  double snow_max_slope_deg = 48.0;
};

/// Colours of the bands, the sea and the sky, in sRGB.
/// Table: render_params.cpp (section [render.palette]).
struct Palette {
  Rgb water_shallow{0.20f, 0.52f, 0.58f};  ///< sea over the shallows, where the seabed shows through
  Rgb water_deep{0.03f, 0.13f, 0.28f};     ///< open deep sea
  Rgb seabed{0.62f, 0.58f, 0.45f};         ///< ground under water, seen through the shallows
  Rgb beach{0.72f, 0.66f, 0.52f};          ///< low rock and sand just above the sea
  Rgb forest_low{0.24f, 0.36f, 0.14f};     ///< forest at the coast end of its band
  Rgb forest_high{0.13f, 0.24f, 0.11f};    ///< forest near the tree line (conifers, darker)
  Rgb cliff{0.45f, 0.41f, 0.37f};          ///< bare rock: above the tree line and on steep slopes
  Rgb snow{0.95f, 0.96f, 0.99f};
  Rgb earth{0.50f, 0.40f, 0.30f};  ///< the cut sides of the terrain block (perspective view)
  Rgb sky_zenith{0.30f, 0.50f, 0.82f};
  Rgb sky_horizon{0.74f, 0.83f, 0.93f};  ///< also the colour of distance fog
  Rgb sun{1.00f, 0.96f, 0.88f};          ///< colour of direct sunlight
};

/// Table: render_params.cpp (section [render]).
struct RenderParams {
  /// Picture width. [Units: pixels] [Range: 16..8192] [Default: 1280]
  int width = 1280;
  /// Picture height. [Units: pixels] [Range: 16..8192] [Default: unset: 720; the top view:
  /// the width times the terrain's aspect, so the terrain fills the picture]
  std::optional<int> height;
  /// [Default: perspective]
  View view = View::perspective;
  /// Compass bearing of the sun, clockwise from north. [Units: degrees] [Range: any, modulo 360]
  /// [Default: 300 (west-north-west: from the upper left in the top view, as relief maps are
  /// lit, and from behind on the left of the default perspective camera)]
  double sun_azimuth_deg = 300.0;
  /// Sun height above the horizon. [Units: degrees] [Range: 0..90] [Default: 32]
  double sun_elevation_deg = 32.0;
  /// Perspective camera (ignored by the top view).
  Camera camera;
  /// Vertical exaggeration: heights are drawn (and shaded) multiplied by this. Colour bands
  /// and cliff slopes use the true heights. [Range: 0.1..20] [Default: 1.5]
  double exaggeration = 1.5;
  /// Sea level: below it a water plane, tinted by depth. [Units: m] [Default: 0]
  double sea_level_m = 0.0;
  /// Draw the sea. false: no water anywhere, and sea level (the zero of the bands) is taken 1 m
  /// below the lowest point, so a mountain standing on high ground is all land. [Default: true]
  bool sea = true;
  Bands bands;
  Palette palette;
  /// Strength of the distance fog (perspective view): the fraction of light kept over one
  /// terrain size of distance beyond the terrain's nearest point is exp(-fog_density).
  /// 0 turns fog off. [Range: 0..10] [Default: 0.2]
  double fog_density = 0.2;
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
const params::Table<Bands>& parameter_table(const Bands*);
const params::Table<Palette>& parameter_table(const Palette*);
const params::Table<RenderParams>& parameter_table(const RenderParams*);

/// The picture height: params.height, or its default for `heights` (see RenderParams::height).
int resolved_height(const RenderParams& params, const Heightfield& heights);

/// The sea level the picture uses: params.sea_level_m, or without a sea 1 m below the lowest
/// point of `heights`. [Units: m]
double effective_sea_level(const RenderParams& params, const Heightfield& heights);

}  // namespace sansui::render
