// `sansui contour`: a mountain from one contour line (SPEC 1; Misawa, Chiba, Saito 1987):
// seed contour (file or from a DEM) -> contours -> GeoJSON, contour map, DEM, bird's-eye render.
#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "contour/elevations.hpp"
#include "contour/extract.hpp"
#include "contour/generate.hpp"
#include "contour/geojson.hpp"
#include "contour/grid_frame.hpp"
#include "contour/map_drawing.hpp"
#include "contour/map_raster.hpp"
#include "contour/map_svg.hpp"
#include "contour/seed_input.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "render/render_image.hpp"
#include "solid/rock_albedo.hpp"

namespace sansui::cli {
namespace {

struct ContourOptions {
  std::string seed_file;
  std::string from_dem;
  std::optional<double> level;
  std::string pick;
  double svg_scale = 1.0;
  std::optional<double> z0;
  std::string method = "revised";
  std::string join;
  std::optional<double> clip_factor, d2;
  std::optional<double> offset;
  double interval = 10.0;
  std::string theta;
  int samples = 1024;
  int f0 = 256;
  double long_fraction = 0.2;
  std::uint64_t seed = 1;
  int loop_removal = 2;
  int loop_threshold = 16;
  int outward = 0;
  std::optional<double> base;
  std::optional<double> min_area;
  std::string offset_schedule;
  std::string hypsometry;
  std::optional<double> relief;
  std::string contours_out;
  std::vector<std::string> maps;
  std::string dem_out;
  std::string render_out;
  std::optional<double> cell;
  std::optional<int> dem_size;
  double roughness = 0.0;
  int map_width = 1200;
  bool verbose = false;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read {}: no such file or no permission", path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const std::string& path, const std::string& text) {
  io::write_atomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) fail("cannot write {}", path);
  });
}

/// Every output checked before any work: extension and directory.
void check_outputs(const ContourOptions& o) {
  if (o.contours_out.empty() && o.maps.empty() && o.dem_out.empty() && o.render_out.empty())
    fail("no output: give --contours OUT.geojson, --map OUT.svg|OUT.png, --dem OUT.png|.r32|.raw|.tif or --render OUT.png");
  if (!o.render_out.empty()) {
    if (extension_of(o.render_out) != ".png")
      fail("--render {} has extension '{}': a picture is written as .png", o.render_out, extension_of(o.render_out));
    io::check_writable(o.render_out);
  }
  if (!o.contours_out.empty()) {
    const std::string e = extension_of(o.contours_out);
    if (e != ".geojson" && e != ".json") fail("--contours {} must end in .geojson or .json", o.contours_out);
    io::check_writable(o.contours_out);
  }
  for (const auto& map : o.maps) {
    const std::string e = extension_of(map);
    if (e != ".svg" && e != ".png") fail("--map {} has an unknown extension '{}': allowed are .svg .png", map, e);
    io::check_writable(map);
  }
  if (!o.dem_out.empty()) {
    if (!io::heightmap_format_for(o.dem_out))
      fail("--dem {} has an unknown extension '{}': allowed are .png .raw .r32 .tif .tiff", o.dem_out, extension_of(o.dem_out));
    io::check_writable(o.dem_out);
  }
}

std::vector<double> parse_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(part, &used));
      if (used != part.size()) throw std::invalid_argument(part);
    } catch (const std::exception&) {
      fail("{} '{}' is not allowed: give numbers separated by commas", option, text);
    }
  }
  return values;
}

/// d for a seed taken from a DEM: the spacing the real slope gives at this interval, dz / mean
/// gradient of the cells inside the seed.
double offset_from_dem(const Heightfield& dem, const contour::Ring& seed, double interval) {
  const contour::GridFrame frame = contour::GridFrame::of(dem);
  double sum = 0.0;
  int count = 0;
  for (int j = 1; j + 1 < dem.height(); ++j)
    for (int i = 1; i + 1 < dem.width(); ++i) {
      if (!contour::contains(seed, frame.at(i, j))) continue;
      const double gx = (dem(i + 1, j) - dem(i - 1, j)) / (2.0 * dem.cell_size_m);
      const double gy = (dem(i, j + 1) - dem(i, j - 1)) / (2.0 * dem.cell_size_m);
      sum += std::sqrt(gx * gx + gy * gy);
      ++count;
    }
  const double gradient = count > 0 ? sum / count : 0.0;
  return gradient > 1e-6 ? interval / gradient : 10.0 * dem.cell_size_m;
}

/// A bird's-eye view of the generated mountain (like the paper's Fig. 17): no sea, bands over
/// the mountain's own relief, cliffs in rock strata.
void render_birds_eye(const Heightfield& dem, const std::string& output) {
  const auto [low, high] = std::ranges::minmax(dem.values());
  render::RenderParams params;
  params.sea_level_m = low - 1.0;  // the foot of the mountain is land, not sea
  params.exaggeration = 1.0;
  Image image;
  {
    ProgressBar progress;
    const Image rock = solid::rock_albedo(dem, solid::RockParams{}, progress.context());
    render::TerrainLayers layers;
    layers.cliff_albedo = &rock;
    image = render::render_image(dem, params, layers, progress.context());
  }
  io::write_png(output, image);
  fmt::print("bird's-eye view of {:.0f}..{:.0f} m -> {}\n", low, high, output);
}

void run_contour(const ContourOptions& o) {
  // Inputs and outputs first: fail before any long work.
  if (o.seed_file.empty() == o.from_dem.empty()) fail("give either a SEED_FILE or --from-dem DEM --level Z, not both");
  if (!o.from_dem.empty() && !o.level) fail("--from-dem needs --level Z: the elevation of the seed contour");
  check_outputs(o);

  contour::GenerationParams params;
  const auto method = contour::method_from_name(o.method);
  if (!method) fail("--method '{}' is unknown: allowed are simple, midpoint, fourier, revised", o.method);
  params.method = *method;
  if (!o.join.empty()) {
    params.join = contour::join_from_name(o.join);
    if (!params.join) fail("--join '{}' is unknown: allowed are extended, straight, arc, clipped", o.join);
  }
  params.clip_factor = o.clip_factor;
  params.displacement_fraction = o.d2;
  if (!o.theta.empty()) {
    const auto [low, high] = parse_pair(o.theta, "--theta");
    params.theta_min_deg = low;
    params.theta_max_deg = high;
  }
  params.interval_m = o.interval;
  params.samples = o.samples;
  params.f0 = o.f0;
  params.long_fraction = o.long_fraction;
  params.seed = o.seed;
  params.loops = {o.loop_removal, o.loop_threshold};
  params.outward_levels = o.outward;
  params.base_m = o.base;
  params.min_area_m2 = o.min_area;
  if (!o.offset_schedule.empty()) params.offset_schedule_m = parse_list(o.offset_schedule, "--offset-schedule");
  std::optional<contour::Hypsometry> hypsometry;
  if (!o.hypsometry.empty()) hypsometry = contour::parse_hypsometry(read_text(o.hypsometry), o.hypsometry);

  params.offset_m = o.offset.value_or(10.0);  // provisional when taken from a DEM's slope
  params.z0_m = o.z0.value_or(o.level.value_or(0.0));
  params.validate();
  if (!o.dem_out.empty() || !o.render_out.empty()) {
    if (o.dem_size && (*o.dem_size < 2 || *o.dem_size > 32768)) fail("--dem-size {} is not allowed: it must be 2..32768", *o.dem_size);
    if (o.cell && (!(*o.cell > 0.0) || !std::isfinite(*o.cell))) fail("--cell {} m is not allowed: it must be > 0", *o.cell);
    if (!(o.roughness >= 0.0) || !std::isfinite(o.roughness)) fail("--roughness {} m is not allowed: it must be >= 0", o.roughness);
  }
  if (o.map_width < 64 || o.map_width > 16384) fail("--map-width {} is not allowed: it must be 64..16384 px", o.map_width);
  if (o.relief && !(*o.relief > 0.0)) fail("--relief {} m is not allowed: it must be > 0", *o.relief);

  // The seed contour.
  contour::SeedContour seed;
  std::optional<Heightfield> source_dem;
  if (!o.from_dem.empty()) {
    source_dem = io::read_heightmap(o.from_dem);
    std::optional<contour::Point> pick;
    if (!o.pick.empty()) {
      const auto [x, y] = parse_pair(o.pick, "--pick");
      pick = contour::Point{x, y};
    }
    seed = contour::normalise_seed(contour::pick_contour(*source_dem, *o.level, pick), true, o.from_dem);
  } else {
    const auto format = contour::seed_format_for(o.seed_file);
    if (!format) fail("seed file {} has an unknown extension: allowed are .geojson .json .csv .svg", o.seed_file);
    seed = contour::parse_seed(read_text(o.seed_file), *format, o.seed_file, o.svg_scale);
  }
  if (!o.offset && source_dem) {
    params.offset_m = offset_from_dem(*source_dem, seed.ring, params.interval_m);
    seed.notes.push_back(fmt::format("offset d = {:.1f} m from the DEM's mean slope inside the seed (set --offset to choose)",
                                     params.offset_m));
  }
  params.validate();
  for (const auto& note : seed.notes) fmt::print(stderr, "sansui: note: {}\n", note);

  contour::ContourTree tree;
  contour::GenerationTimes times;
  {
    ProgressBar progress;
    tree = contour::generate_contours(seed.ring, params, progress.context(), &times);
  }
  if (hypsometry) {
    int top = 0;
    for (const auto& node : tree.nodes) top = std::max(top, node.level);
    contour::apply_hypsometry(tree, *hypsometry, o.relief.value_or(std::max(1, top) * params.interval_m));
  }
  double low = INFINITY, high = -INFINITY;
  int lowest = 0, highest = 0;
  for (const auto& node : tree.nodes) {
    low = std::min(low, node.elevation_m), high = std::max(high, node.elevation_m);
    lowest = std::min(lowest, node.level), highest = std::max(highest, node.level);
  }
  fmt::print("{} contours on levels {}..{} ({:.1f}..{:.1f} m), {} summit(s), method {}, d = {:.2f} m, dz = {:.2f} m\n",
             tree.nodes.size(), lowest, highest, low, high, tree.summits().size(), o.method, params.offset_m, params.interval_m);
  if (o.verbose)
    fmt::print("seconds: offset+union {:.3f}, midpoint {:.3f}, fourier {:.3f}, decimate {:.3f}, loops {:.3f}, clip {:.3f}\n",
               times.offset_s, times.midpoint_s, times.fourier_s, times.decimate_s, times.loops_s, times.clip_s);

  nlohmann::json provenance = run_provenance("contour");
  provenance["parameters"] = {{"method", o.method},
                              {"join", std::string(contour::name_of(params.resolved_join()))},
                              {"c", params.resolved_clip_factor()},
                              {"offset_m", params.offset_m},
                              {"interval_m", params.interval_m},
                              {"z0_m", params.z0_m},
                              {"d2_fraction", params.resolved_displacement_fraction()},
                              {"theta_deg", {params.resolved_theta_min_deg(), params.resolved_theta_max_deg()}},
                              {"n", params.samples},
                              {"f0", params.f0},
                              {"long_fraction", params.long_fraction},
                              {"seed", params.seed},
                              {"loop_removal", params.loops.method},
                              {"loop_threshold", params.loops.threshold},
                              {"outward", params.resolved_outward_levels()},
                              {"seed_file", o.seed_file.empty() ? o.from_dem : o.seed_file}};
  if (!o.contours_out.empty()) write_text(o.contours_out, contour::contours_to_geojson(tree, provenance));
  for (const auto& map : o.maps) {
    contour::MapStyle style;
    style.width_px = o.map_width;
    const contour::MapDrawing drawing = contour::layout_contour_map(tree, style);
    if (extension_of(map) == ".svg") {
      write_text(map, contour::map_to_svg(drawing));
    } else {
      io::write_png(map, contour::rasterize_map(drawing));
    }
  }
  if (!o.dem_out.empty() || !o.render_out.empty()) {
    contour::DemParams dem_params;
    if (source_dem && !o.dem_size && !o.cell) {
      // Regenerating a real mountain: the real DEM's own grid, so the two compare cell by cell.
      dem_params.width = source_dem->width();
      dem_params.height = source_dem->height();
      dem_params.cell_m = source_dem->cell_size_m;
      dem_params.origin_x_m = source_dem->origin_x_m;
      dem_params.origin_y_m = source_dem->origin_y_m;
    } else {
      dem_params = contour::dem_frame_for(tree, o.dem_size.value_or(1025));
    }
    if (o.cell) {
      // Same extent, the given cell size.
      const double width_m = (dem_params.width - 1) * dem_params.cell_m, height_m = (dem_params.height - 1) * dem_params.cell_m;
      const double cx = dem_params.origin_x_m + 0.5 * width_m, cy = dem_params.origin_y_m + 0.5 * height_m;
      dem_params.cell_m = *o.cell;
      dem_params.width = static_cast<int>(std::ceil(width_m / *o.cell)) + 1;
      dem_params.height = static_cast<int>(std::ceil(height_m / *o.cell)) + 1;
      dem_params.origin_x_m = cx - 0.5 * (dem_params.width - 1) * *o.cell;
      dem_params.origin_y_m = cy - 0.5 * (dem_params.height - 1) * *o.cell;
    }
    dem_params.offset_m = params.offset_m;
    dem_params.roughness_m = o.roughness;
    dem_params.seed = o.seed;
    Heightfield dem;
    {
      ProgressBar progress;
      dem = contour::contours_to_dem(tree, dem_params, progress.context());
    }
    if (!o.dem_out.empty()) {
      nlohmann::json dem_provenance = provenance;
      dem_provenance["parameters"]["roughness_m"] = o.roughness;
      io::write_heightmap(o.dem_out, dem, {std::nullopt, dem_provenance, true});
      fmt::print("DEM {}x{} samples of {:.3g} m -> {}\n", dem.width(), dem.height(), dem.cell_size_m, o.dem_out);
    }
    if (!o.render_out.empty()) render_birds_eye(dem, o.render_out);
  }
}

}  // namespace

void add_contour_command(CLI::App& app) {
  auto options = std::make_shared<ContourOptions>();
  ContourOptions& o = *options;
  CLI::App* c = app.add_subcommand("contour", "A mountain from one contour line (Misawa, Chiba, Saito): contours, map, DEM.");
  c->add_option("seed_file", o.seed_file, "Seed contour: .geojson (Polygon or closed LineString, metres), .csv (x,y per line) or .svg");
  c->add_option("--from-dem", o.from_dem, "Take the seed contour from a DEM (.png .r32 .tif) at --level, instead of SEED_FILE");
  c->add_option("--level", o.level, "Elevation of the seed contour in the DEM. [Units: m]");
  c->add_option("--pick", o.pick, "X,Y: the contour around this point (DEM plane, metres). [Default: the largest]");
  c->add_option("--scale", o.svg_scale, "Metres per SVG unit for .svg seeds. [Units: m] [Default: 1]");
  c->add_option("--z0", o.z0, "Elevation of the seed contour. [Units: m] [Default: 0, or --level]");
  c->add_option("--method", o.method, "simple, midpoint, fourier or revised (the paper's best). [Default: revised]");
  c->add_option("--join", o.join, "Offset join: extended, straight, arc, clipped (Fig. 7). [Default: clipped]");
  c->add_option("--c", o.clip_factor, "c of the clipped join, d' = c d. [Range: >= 1] [Default: 1.4; revised 3]");
  c->add_option("--offset", o.offset, "d: horizontal offset between contours. [Units: m] [Range: > 0] [Default: 10; from a DEM: its slope]");
  c->add_option("--interval", o.interval, "dz: contour interval. [Units: m] [Range: > 0] [Default: 10]");
  c->add_option("--d2", o.d2, "d'' as a fraction of d: largest midpoint displacement. [Default: 0.3; revised 0.5]");
  c->add_option("--theta", o.theta, "MIN,MAX: range of theta of the midpoint displacement. [Units: deg] [Range: 0..90) [Default: 0,20; revised 20,40]");
  c->add_option("--n", o.samples, "Fourier samples n, a power of two. [Default: 1024]");
  c->add_option("--f0", o.f0, "Lowest randomised frequency; n/2 turns it off. [Range: 0..n/2] [Default: 256]");
  c->add_option("--long-fraction", o.long_fraction, "Revised: fraction of segments longer than 2 d0 kept. [Default: 0.2]");
  c->add_option("--seed", o.seed, "Random seed: the same seed gives the same bytes. [Default: 1]");
  c->add_option("--loop-removal", o.loop_removal, "Loop removal method 1 (faces) or 2 (walk). [Default: 2]");
  c->add_option("--loop-threshold", o.loop_threshold, "Loops have fewer segments than this. [Range: >= 3] [Default: 16]");
  c->add_option("--outward", o.outward, "Levels generated outward, toward the foot. [Default: 0]");
  c->add_option("--base", o.base, "Generate outward down to this elevation. [Units: m]");
  c->add_option("--min-area", o.min_area, "Smaller contours end a summit. [Units: m^2] [Default: d^2/4]");
  c->add_option("--offset-schedule", o.offset_schedule, "D1,D2,...: d for inward levels 1, 2, ...; the last repeats. [Units: m]");
  c->add_option("--hypsometry", o.hypsometry, "CSV of area,height fractions: reassigns elevations (altitude-area curve)");
  c->add_option("--relief", o.relief, "Height of the hypsometric curve's top above z0. [Units: m] [Default: levels x dz]");
  c->add_option("--contours", o.contours_out, "Write the contours as GeoJSON (.geojson)");
  c->add_option("--map", o.maps, "Write a contour map (.svg or .png); repeatable");
  c->add_option("--map-width", o.map_width, "Width of the map. [Units: px] [Default: 1200]");
  c->add_option("--dem", o.dem_out, "Write a DEM: .png (16-bit) .raw .r32 .tif");
  c->add_option("--render", o.render_out, "Write a bird's-eye picture of the DEM (.png), as sansui render draws it");
  c->add_option("--dem-size", o.dem_size, "Samples along the DEM's longer side. [Default: 1025; with --from-dem: that DEM's grid]");
  c->add_option("--cell", o.cell, "DEM cell size instead of --dem-size. [Units: m]");
  c->add_option("--roughness", o.roughness, "Midpoint-displacement roughness on the DEM (Fig. 11). [Units: m] [Default: 0]");
  c->add_flag("-v,--verbose", o.verbose, "Print the time of each step");
  c->callback([options] { run_contour(*options); });
}

}  // namespace sansui::cli
