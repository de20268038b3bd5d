// `sansui compare REAL GENERATED`: how close a generated mountain is to a real one (SPEC 1.4).
#include <fstream>
#include <memory>
#include <sstream>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "contour/compare.hpp"
#include "contour/extract.hpp"
#include "contour/geojson.hpp"
#include "contour/map_drawing.hpp"
#include "contour/map_raster.hpp"
#include "contour/map_svg.hpp"
#include "io/image_io.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"


namespace sansui::cli {
namespace {

struct CompareOptions {
  std::string real, generated;
  std::optional<double> above, interval, prominence;
  std::string inside;
  std::string json;
  std::string map_real, map_generated;
};

/// A contour map of `dem` at the compared levels (index contours every 5 levels).
void write_map(const std::string& path, const Heightfield& dem, const std::vector<double>& levels, int width) {
  contour::MapStyle style;
  style.width_px = width;
  const contour::MapDrawing map = contour::layout_contour_map(contour::contours_of_dem(dem, levels), style);
  if (extension_of(path) == ".svg") {
    const std::string svg = contour::map_to_svg(map);
    io::write_atomically(path, [&](const std::filesystem::path& temporary) { std::ofstream(temporary) << svg; });
  } else {
    io::write_png(path, contour::rasterize_map(map));
  }
}

void run_compare(const CompareOptions& o) {
  if (!o.json.empty()) io::check_writable(o.json);
  for (const std::string& map : {o.map_real, o.map_generated}) {
    if (map.empty()) continue;
    if (extension_of(map) != ".svg" && extension_of(map) != ".png") fail("map {} has an unknown extension: allowed are .svg .png", map);
    io::check_writable(map);
  }
  contour::CompareParams params;
  params.above_m = o.above;
  params.interval_m = o.interval;
  params.prominence_m = o.prominence;
  if (!o.inside.empty()) {
    std::ifstream in(o.inside, std::ios::binary);
    if (!in) fail("cannot read {}: no such file or no permission", o.inside);
    std::stringstream text;
    text << in.rdbuf();
    const contour::ContourTree tree = contour::contours_from_geojson(text.str(), o.inside);
    if (tree.nodes.empty()) fail("{} holds no contour", o.inside);
    params.inside = tree.nodes[static_cast<std::size_t>(tree.seed)].ring;
  }
  const Heightfield real = io::read_heightmap(o.real);
  const Heightfield generated = io::read_heightmap(o.generated);
  contour::Comparison comparison;
  {
    ProgressBar progress;
    comparison = contour::compare_dems(real, generated, params, progress.context());
  }
  fmt::print("{}", contour::comparison_table(comparison));
  // The maps share the compared levels, z0 of the tree = the lowest of them.
  std::vector<double> levels = comparison.real.levels_m;
  if (!levels.empty()) levels.insert(levels.begin(), levels.front() - *comparison.params.interval_m);
  if (!o.map_real.empty()) write_map(o.map_real, real, levels, 900);
  if (!o.map_generated.empty()) write_map(o.map_generated, generated, levels, 900);
  if (!o.json.empty()) {
    const auto& c = comparison;
    auto measures = [](const contour::DemMeasures& m) {
      return nlohmann::json{{"cells", m.cells},
                            {"min_m", m.min_m},
                            {"max_m", m.max_m},
                            {"hypsometric_integral", m.hypsometric_integral},
                            {"hypsometry", m.hypsometry},
                            {"mean_slope_deg", m.mean_slope_deg},
                            {"slope_histogram", m.slope_histogram},
                            {"summits", m.summits},
                            {"levels_m", m.levels_m},
                            {"contour_length_m", m.contour_length_m},
                            {"contour_spectrum_slope", m.contour_spectrum_slope},
                            {"dem_spectrum_slope", m.dem_spectrum_slope}};
    };
    nlohmann::json out{{"real", measures(c.real)},
                       {"generated", measures(c.generated)},
                       {"hypsometric_difference", c.hypsometric_difference},
                       {"slope_distance_deg", c.slope_distance_deg},
                       {"length_ratio", c.length_ratio},
                       {"interval_m", *c.params.interval_m},
                       {"prominence_m", *c.params.prominence_m},
                       {"provenance", run_provenance("compare")}};
    io::write_atomically(o.json, [&](const std::filesystem::path& temporary) {
      std::ofstream file(temporary);
      file << out.dump(2) << "\n";
    });
  }
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CompareOptions& o = *options;
  CLI::App* c = app.add_subcommand("compare", "Compare a generated DEM with a real one: hypsometry, slopes, summits, contours, spectra.");
  c->add_option("real", o.real, "The real DEM (.png .r32 .tif)")->required();
  c->add_option("generated", o.generated, "The generated DEM (.png .r32 .tif)")->required();
  c->add_option("--above", o.above, "Only cells at or above this elevation, e.g. the seed's level. [Units: m] [Default: all]");
  c->add_option("--inside", o.inside, "Only cells inside the seed contour of this GeoJSON (written by sansui contour --contours)");
  c->add_option("--interval", o.interval, "Interval of the compared contour levels. [Units: m] [Default: common relief / 20]");
  c->add_option("--prominence", o.prominence, "Smallest prominence of a summit. [Units: m] [Default: the interval]");
  c->add_option("--json", o.json, "Also write every measure as JSON");
  c->add_option("--map-real", o.map_real, "Write a contour map of the real DEM at the compared levels (.svg or .png)");
  c->add_option("--map-generated", o.map_generated, "Write a contour map of the generated DEM at the compared levels (.svg or .png)");
  c->callback([options] { run_compare(*options); });
}

}  // namespace sansui::cli
