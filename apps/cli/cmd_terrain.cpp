// `sansui terrain`: fractal terrain by midpoint displacement (SPEC 3.1), whole or as tiles.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/mesh_io.hpp"
#include "mesh/heightfield_mesh.hpp"
#include "terrain/midpoint.hpp"
#include "terrain/stage_filter.hpp"

namespace sansui::cli {
namespace {

struct TerrainOptions {
  terrain::MidpointParams midpoint;
  long long size = 1025;
  long long world_size = 0;  // 0: same as size
  double cell_m = 10.0;
  std::string stage = "mature";
  bool paper_exact = false;
  bool no_additions = false;
  double sea_level_m = 0.0;
  std::string tile;  // "X,Y"
  long long tile_size = 1025;
  int lod = 0;
  std::string range;  // "MIN,MAX"
  bool raw_flip_y = false;
  std::vector<std::string> outputs;
};

/// Checks every output before any work: known extension, writable directory.
void check_outputs(const std::vector<std::string>& outputs) {
  if (outputs.empty()) fail("no output: give at least one -o FILE (.png .raw .r32 .tif .obj .glb)");
  for (const auto& output : outputs) {
    if (!io::heightmap_format_for(output) && !io::mesh_format_for(output))
      fail("output {} has an unknown extension '{}': allowed are .png .raw .r32 .tif .tiff .obj .glb", output,
           extension_of(output));
    io::check_writable(output);
  }
}

nlohmann::json parameters_of(const TerrainOptions& o, int world_levels, const Rect& window) {
  return {{"seed", o.midpoint.seed},
          {"hurst", o.midpoint.hurst},
          {"sigma_m", o.midpoint.sigma_m},
          {"additions", o.midpoint.additions},
          {"stage", o.stage},
          {"paper_exact", o.paper_exact},
          {"sea_level_m", o.sea_level_m},
          {"world_size", (1 << world_levels) + 1},
          {"lod", o.lod},
          {"window", {{"x0", window.x0}, {"y0", window.y0}, {"x1", window.x1}, {"y1", window.y1}}},
          {"cell_size_m", o.cell_m * (1 << o.lod)}};
}

void run_terrain(TerrainOptions o) {
  o.midpoint.additions = !o.no_additions;
  o.midpoint.validate();
  const auto stage = terrain::stage_from_name(o.stage);
  if (!stage) fail("stage '{}' is unknown: allowed are original, young, mature, old, peneplain", o.stage);
  if (!(o.cell_m > 0.0) || !std::isfinite(o.cell_m)) fail("cell size {} m is not allowed: it must be > 0", o.cell_m);
  if (!std::isfinite(o.sea_level_m)) fail("sea level {} is not a finite number of metres", o.sea_level_m);

  // The world, and which window of it (in output samples) this run writes.
  const bool tiled = !o.tile.empty();
  const long long world_size = o.world_size > 0 ? o.world_size : o.size;
  const int world_levels = terrain::levels_for_size(world_size);
  const long long max_size = tiled ? (1ll << terrain::max_world_levels) + 1 : 16385;
  if (world_levels < 1 || world_size > max_size)
    fail("{} {} is not allowed: it must be 2^k+1 between 3 and {}", o.world_size > 0 ? "world size" : "size", world_size,
         max_size);
  if (o.lod < 0 || o.lod >= world_levels) fail("--lod {} is not allowed: it must be 0..{} for this world", o.lod, world_levels - 1);
  const int step = 1 << o.lod;
  Rect window{0, 0, static_cast<int>((world_size - 1) / step + 1), static_cast<int>((world_size - 1) / step + 1)};
  if (tiled) {
    const int tile_levels = terrain::levels_for_size(o.tile_size);
    if (tile_levels < 1 || o.tile_size > world_size)
      fail("tile size {} is not allowed: it must be 2^m+1 between 3 and the world size {}", o.tile_size, world_size);
    if ((o.tile_size - 1) % step != 0) fail("tile size {} does not fit --lod {}: tile size - 1 must be a multiple of {}", o.tile_size, o.lod, step);
    const auto [tx, ty] = parse_int_pair(o.tile, "--tile");
    const long long tiles = (world_size - 1) / (o.tile_size - 1);
    if (tx < 0 || ty < 0 || tx >= tiles || ty >= tiles)
      fail("tile {},{} is outside the world: tiles go from 0,0 to {},{}", tx, ty, tiles - 1, tiles - 1);
    const int span = static_cast<int>((o.tile_size - 1) / step);
    window = {tx * span, ty * span, tx * span + span + 1, ty * span + span + 1};
  }
  std::optional<io::HeightRange> range;
  if (!o.range.empty()) {
    const auto [low, high] = parse_pair(o.range, "--range");
    if (!(low < high)) fail("--range {} is not allowed: MIN must be below MAX", o.range);
    range = io::HeightRange{low, high};
  } else if (tiled || o.lod > 0) {
    // Every tile and preview of a world encodes 16 bits alike, so they join without seams.
    range = io::HeightRange{o.sea_level_m - 6.0 * o.midpoint.sigma_m, o.sea_level_m + 6.0 * o.midpoint.sigma_m};
  }
  check_outputs(o.outputs);

  Heightfield heights;
  {
    ProgressBar progress;
    heights = terrain::generate_midpoint(o.midpoint, terrain::WorldWindow{world_levels, o.lod, window}, progress.context());
  }
  terrain::apply_stage_filter(heights, {*stage, o.paper_exact, o.sea_level_m, o.midpoint.sigma_m});
  heights.cell_size_m = o.cell_m * step;
  heights.origin_x_m = window.x0 * heights.cell_size_m;
  heights.origin_y_m = window.y0 * heights.cell_size_m;

  nlohmann::json provenance = run_provenance("terrain");
  provenance["parameters"] = parameters_of(o, world_levels, window);
  for (const auto& output : o.outputs) {
    if (io::heightmap_format_for(output)) {
      io::HeightmapWriteOptions options{range, provenance, true};
      options.raw_flip_y = o.raw_flip_y;
      io::write_heightmap(output, heights, options);
    } else {
      io::write_mesh(output, mesh::heightfield_to_mesh(heights), {provenance, true});
    }
  }
}

}  // namespace

void add_terrain_command(CLI::App& app) {
  auto options = std::make_shared<TerrainOptions>();
  CLI::App* command = app.add_subcommand("terrain", "Fractal terrain by midpoint displacement with successive random additions.");
  TerrainOptions& o = *options;
  command->add_option("--size", o.size, "Samples per side, 2^k+1 from 3 to 16385. [Default: 1025]");
  command->add_option("--seed", o.midpoint.seed, "Random seed: the same seed gives the same bytes. [Default: 1]");
  command->add_option("--hurst", o.midpoint.hurst, "Hurst exponent H, larger is smoother. [Range: 0 < H <= 1] [Default: 0.8]");
  command->add_option("--sigma", o.midpoint.sigma_m, "Standard deviation of the first displacement. [Units: m] [Range: >= 0] [Default: 400]");
  command->add_option("--cell", o.cell_m, "Distance between samples. [Units: m] [Range: > 0] [Default: 10]");
  command->add_flag("--no-additions", o.no_additions, "Plain midpoint displacement, without successive random additions.");
  command->add_option("--stage", o.stage, "Geomorphic stage filter: original, young, mature, old, peneplain. [Default: mature]");
  command->add_flag("--paper-exact", o.paper_exact, "Use the paper's printed old/peneplain filters, which jump at 1 sigma.");
  command->add_option("--sea-level", o.sea_level_m, "Sea level; filters act on the height above it. [Units: m] [Default: 0]");
  command->add_option("--world-size", o.world_size, "Samples per side of the whole world, 2^k+1 up to 1048577, for --tile or --lod. [Default: --size]");
  command->add_option("--tile", o.tile, "Write only tile X,Y of the world (tiles share their border samples). [Default: whole world]");
  command->add_option("--tile-size", o.tile_size, "Samples per side of a tile, 2^m+1. [Default: 1025]");
  command->add_option("--lod", o.lod, "Level of detail: every 2^K-th sample, exactly the full world's values there. [Default: 0]");
  command->add_option("--range", o.range, "Metres mapped to 0 and 65535 in 16-bit outputs, as MIN,MAX. [Units: m] [Default: the data's range; for tiles and --lod, sea level -/+ 6 sigma]");
  command->add_flag("--raw-flip-y", o.raw_flip_y, "Write .raw rows south first, as Unity's terrain importer reads them. [Default: north first]");
  command->add_option("-o,--out", o.outputs, "Output file, repeatable; format from the extension: .png (16-bit) .raw (16-bit LE) .r32 (float32 LE) .tif (GeoTIFF float32) .obj .glb")->required();
  command->callback([options] { run_terrain(*options); });
}

}  // namespace sansui::cli
