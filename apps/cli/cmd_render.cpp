// `sansui render`: a picture of a heightmap, drawn headless with OpenGL (SPEC 3.2): bird's-eye
// perspective (the default) or a top view, coloured by elevation and slope bands, sun-shaded
// with shadows and ambient occlusion.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "render/render_image.hpp"
#include "solid/rock_albedo.hpp"
#include "solid/texture.hpp"

namespace sansui::cli {
namespace {

struct RenderOptions {
  render::RenderParams params;
  std::string heightmap;
  std::string output;
  std::string view = "perspective";
  std::string sun;      // "AZIMUTH,ELEVATION"
  std::string target;   // "X,Y"
  std::string range;    // "MIN,MAX"
  double cell_m = 0.0;  // 0: from the file
  bool no_shadows = false;
  CLI::Option* height_option = nullptr;
  std::string rock = "none";  // a solid texture for cliffs (docs/solid.md)
  solid::RockParams rock_params;
};

void run_render(RenderOptions o) {
  render::RenderParams& params = o.params;
  // Every option first, then the output, then the (possibly long) reading and drawing.
  const auto view = render::view_from_name(o.view);
  if (!view) fail("view '{}' is unknown: allowed are perspective, top", o.view);
  params.view = *view;
  if (!o.sun.empty()) std::tie(params.sun_azimuth_deg, params.sun_elevation_deg) = parse_pair(o.sun, "--sun");
  if (!o.target.empty()) std::tie(params.camera.target_x, params.camera.target_y) = parse_pair(o.target, "--target");
  params.shadows = !o.no_shadows;
  params.validate();
  if (o.rock != "none") {
    const auto names = solid::texture_names();
    if (std::find(names.begin(), names.end(), o.rock) == names.end())
      fail("--rock '{}' is unknown: allowed are none, strata, marble, white-marble, green-marble, oak, pine", o.rock);
    o.rock_params.texture = o.rock;
    o.rock_params.validate();
  }
  io::HeightmapReadOptions read_options;
  if (o.cell_m != 0.0) {
    if (!(o.cell_m > 0.0) || !std::isfinite(o.cell_m)) fail("cell size {} m is not allowed: it must be > 0", o.cell_m);
    read_options.cell_size_m = o.cell_m;
  }
  if (!o.range.empty()) {
    const auto [low, high] = parse_pair(o.range, "--range");
    if (!(low < high)) fail("--range {} is not allowed: MIN must be below MAX", o.range);
    read_options.range = io::HeightRange{low, high};
  }
  if (extension_of(o.output) != ".png")
    fail("output {} has extension '{}': a picture is written as .png", o.output, extension_of(o.output));
  io::check_writable(o.output);

  const Heightfield heights = io::read_heightmap(o.heightmap, read_options);
  // The top view's default height keeps the terrain's aspect, so it fills the picture.
  if (params.view == render::View::top && o.height_option->count() == 0) {
    const double aspect = static_cast<double>(heights.height() - 1) / std::max(heights.width() - 1, 1);
    params.height = std::clamp(static_cast<int>(std::lround(params.width * aspect)), 16, 8192);
  }
  Image image;
  {
    ProgressBar progress;
    // Cliffs and bare rock show a solid texture evaluated at each surface point (seeds/002).
    Image rock;
    render::TerrainLayers layers;
    if (o.rock != "none") {
      rock = solid::rock_albedo(heights, o.rock_params, progress.context());
      layers.cliff_albedo = &rock;
    }
    image = render::render_image(heights, params, layers, progress.context());
  }
  io::write_png(o.output, image);
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  RenderOptions& o = *options;
  render::RenderParams& p = o.params;
  CLI::App* command = app.add_subcommand(
      "render", "Draw a heightmap as a picture (PNG), headless: bird's-eye perspective or top view, coloured by "
                "elevation and slope bands, sun-shaded with shadows.");
  command->add_option("heightmap", o.heightmap, "Heightmap to draw: .png (16-bit) .raw .r32 .tif, metres")->required();
  command->add_option("-o,--out", o.output, "Picture to write (.png).")->required();
  command->add_option("--view", o.view, "perspective (bird's-eye, with sky and fog) or top (straight down, north up). [Default: perspective]");
  command->add_option("--width", p.width, "Picture width. [Units: pixels] [Range: 16..8192] [Default: 1280]");
  o.height_option = command->add_option(
      "--height", p.height, "Picture height. [Units: pixels] [Range: 16..8192] [Default: 720; top view: width x the terrain's aspect]");
  command->add_option("--sun", o.sun, "Sun position as AZIMUTH,ELEVATION: compass bearing clockwise from north, and height above the horizon. [Units: degrees] [Range: elevation 0..90] [Default: 300,32]");
  command->add_option("--camera-azimuth", p.camera.azimuth_deg, "Compass bearing from the target to the camera (180: from the south, looking north). [Units: degrees] [Default: 200]");
  command->add_option("--camera-elevation", p.camera.elevation_deg, "Camera height as an angle above the target. [Units: degrees] [Range: 1..89] [Default: 25]");
  command->add_option("--camera-distance", p.camera.distance, "Camera distance from the target; 0 fits the whole terrain in the picture. [Units: terrain sizes] [Range: 0 or 0.05..20] [Default: 0]");
  command->add_option("--fov", p.camera.fov_deg, "Vertical field of view. [Units: degrees] [Range: 5..120] [Default: 40]");
  command->add_option("--target", o.target, "Point the camera looks at, as X,Y fractions of the terrain (x east, y south). [Range: 0..1] [Default: 0.5,0.5]");
  command->add_option("--exaggeration", p.exaggeration, "Vertical exaggeration of the drawn heights (colour bands use true heights). [Range: 0.1..20] [Default: 1.5]");
  command->add_option("--sea-level", p.sea_level_m, "Sea level: water below it, and the zero of the elevation bands. [Units: m] [Default: 0]");
  command->add_option("--tree-line", p.bands.tree_line, "Tree line as a fraction of the highest elevation above sea level. [Range: 0..1] [Default: 0.5 (temperate climate, seed 003 Table 4)]");
  command->add_option("--snow-line", p.bands.snow_line, "Snow line as a fraction of the highest elevation above sea level. [Range: 0..1] [Default: 0.75 (temperate climate, seed 003 Table 4)]");
  command->add_option("--cliff-slope", p.bands.cliff_slope_deg, "Slopes steeper than this are drawn as bare cliff. [Units: degrees] [Range: 0..90] [Default: 38]");
  command->add_option("--fog", p.fog_density, "Distance fog: exp(-FOG) of the light is kept over one terrain size of depth; 0 off. [Range: 0..10] [Default: 0.2]");
  command->add_flag("--no-shadows", o.no_shadows, "Do not cast shadows (diffuse shading and ambient occlusion stay).");
  command->add_option("--ambient-occlusion", p.ambient_occlusion, "Darkening of hollows: 0 off, 1 full. [Range: 0..1] [Default: 1]");
  command->add_option("--samples", p.samples, "Antialiasing samples per pixel (pictures over 16 megapixels use 1; software rendering costs one draw per sample). [Range: 1..16] [Default: 4]");
  command->add_option("--cell", o.cell_m, "Distance between samples, for heightmaps without a sidecar giving it. [Units: m] [Range: > 0] [Default: from the file or its sidecar]");
  command->add_option("--range", o.range, "Metres that 16-bit values 0 and 65535 stand for, as MIN,MAX. [Units: m] [Default: from the sidecar]");
  command->add_option("--rock", o.rock, "Cliffs and bare rock show a solid texture evaluated at each surface point: strata (sedimentary beds), marble, green-marble, ... or none (the palette's cliff colour). [Default: none]");
  command->add_option("--rock-seed", o.rock_params.seed, "Seed of the rock texture. [Default: 1]");
  command->add_option("--rock-scale", o.rock_params.texture_size_m, "Metres one rock texture block spans: strata beds are about 3 % of it. [Units: m] [Range: > 0] [Default: 1000]");
  command->callback([options] { run_render(*options); });
}

}  // namespace sansui::cli
