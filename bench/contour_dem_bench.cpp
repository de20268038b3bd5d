// contour-dem speed (issue 17 item 6): a DEM from a given real contour map, the 40 m contours
// gdal_contour traced on examples/dem/jacksboro_ridge.tif (117 lines, 10,000 vertices), on grids
// of 110 (the DEM's own), 880 and 1760 samples along the longer side, with 1 and 2 threads.
// Reference in the same run: one exact Euclidean feature transform of the same drawn lines
// (edt.hpp), the floor of any distance-based interpolation (the counter ratio_to_one_edt).
// ContourMapToDem_File: any contour GeoJSON on any DEM's grid, named by the environment
// (SANSUI_CONTOUR_MAP=lines.geojson SANSUI_CONTOUR_GRID=dem.tif [SANSUI_CONTOUR_CELL=m: that
// extent at this cell]): the interpolation alone, the file already parsed, the step GRASS
// r.surf.contour is timed for in bench/peers_contour_dem.sh (on the same contours and grid).
// Run: build/bench/bench_contour_dem --benchmark_counters_tabular=true
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "bench/bench_paths.hpp"
#include "contour/contours_to_dem.hpp"
#include "contour/edt.hpp"
#include "contour/grid_frame.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/heightmap_io.hpp"
#include "io/text_file.hpp"

namespace {

using namespace sansui;
using namespace sansui::contour;

const ContourMap& jacksboro() {
  static const ContourMap map = io::parse_contour_map(
      io::read_text_file(std::string(sansui::bench::source_dir) + "/examples/contours/jacksboro_40m.geojson"), "jacksboro", "", false);
  return map;
}

/// Seconds of one feature transform of the lines drawn on `grid` (the reference).
double one_edt_seconds(const ContourMapGrid& grid) {
  Grid<std::uint8_t> source(grid.width, grid.height, 0);
  const GridFrame frame{grid.origin_x_m, grid.origin_y_m, grid.cell_m};
  for (const ContourLine& line : jacksboro().lines)
    for (const Point& p : line.points) {
      const auto i = static_cast<int>(std::lround(frame.column(p.x))), j = static_cast<int>(std::lround(frame.row(p.y)));
      if (i >= 0 && j >= 0 && i < grid.width && j < grid.height) source(i, j) = 1;
    }
  Grid<std::int32_t> nearest;
  double best = INFINITY;
  for (int k = 0; k < 5; ++k) {
    const auto start = std::chrono::steady_clock::now();
    nearest_source(source, nearest);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

void ContourMapToDem(benchmark::State& state) {
  const auto samples = static_cast<int>(state.range(0));
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(1)));
  const ContourMapGrid grid = contour_map_grid(jacksboro(), samples, 0.0);
  double total = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(contour_map_to_dem(jacksboro(), grid));
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const double edt = one_edt_seconds(grid);
  state.counters["cells"] = static_cast<double>(grid.width) * grid.height;
  state.counters["Mcells_per_s"] =
      benchmark::Counter(static_cast<double>(grid.width) * grid.height * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["one_edt_s"] = edt;
  state.counters["ratio_to_one_edt"] = total / static_cast<double>(state.iterations()) / edt;
}
BENCHMARK(ContourMapToDem)
    ->ArgsProduct({{110, 880, 1760}, {1, 2}})
    ->ArgNames({"samples", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The contour map and grid named by SANSUI_CONTOUR_MAP and SANSUI_CONTOUR_GRID, if both are set.
const std::optional<std::pair<ContourMap, ContourMapGrid>>& named_case() {
  static const auto named = []() -> std::optional<std::pair<ContourMap, ContourMapGrid>> {
    const char* lines = std::getenv("SANSUI_CONTOUR_MAP");
    const char* dem = std::getenv("SANSUI_CONTOUR_GRID");
    if (lines == nullptr || dem == nullptr) return std::nullopt;
    ContourMap map = io::parse_contour_map(io::read_text_file(lines), lines, "", false);
    const Heightfield like = io::read_heightmap(dem);
    ContourMapGrid grid{like.width(), like.height(), like.cell_size_m, like.origin_x_m, like.origin_y_m};
    if (const char* cell = std::getenv("SANSUI_CONTOUR_CELL"); cell != nullptr && std::atof(cell) > 0.0) {
      // The same extent at a finer cell, as GRASS's g.region res= sets it.
      const double c = std::atof(cell);
      grid.width = static_cast<int>(std::lround((like.width() - 1) * like.cell_size_m / c)) + 1;
      grid.height = static_cast<int>(std::lround((like.height() - 1) * like.cell_size_m / c)) + 1;
      grid.cell_m = c;
    }
    return std::pair{std::move(map), grid};
  }();
  return named;
}

void ContourMapToDem_File(benchmark::State& state) {
  const auto& named = named_case();
  if (!named) {
    state.SkipWithError("set SANSUI_CONTOUR_MAP and SANSUI_CONTOUR_GRID");
    return;
  }
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(contour_map_to_dem(named->first, named->second));
  const double cells = static_cast<double>(named->second.width) * named->second.height;
  state.counters["cells"] = cells;
  state.counters["Mcells_per_s"] = benchmark::Counter(cells * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(ContourMapToDem_File)->Arg(1)->Arg(2)->ArgNames({"threads"})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
