// A world built tile by tile (see tiled_world.hpp).
#include "scene/tiled_world.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/extension.hpp"
#include "io/geojson_crs.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "io/png_georeference.hpp"
#include "io/text_file.hpp"
#include "io/vrt_mosaic.hpp"
#include "look/surface_layers.hpp"
#include "scene/georeference.hpp"
#include "scene/look.hpp"
#include "scene/output_kinds.hpp"
#include "scene/output_plan.hpp"
#include "scene/sources.hpp"
#include "scene/tiled_water.hpp"
#include "scene/water_layers.hpp"
#include "terrain/midpoint.hpp"
#include "water/tiled_erosion.hpp"

namespace sansui::scene {
namespace {

/// The output kinds a tiled world writes, and how: grids as tiles under a VRT.
bool is_tiled_grid(OutputKind kind) {
  return kind == OutputKind::heightmap || kind == OutputKind::erosion_map || kind == OutputKind::deposition_map ||
         kind == OutputKind::flow_map;
}

/// Most tiles a tiled world may have: 2048 x 2048 (a 526337² world in tiles of 257). Each tile
/// costs a few hundred bytes of lists on every rank, and two files per output.
constexpr std::int64_t most_tiles = std::int64_t{1} << 22;

long long tiled_world_samples(const WorldParams& world) {
  return world.world_size.value_or(world.size);
}

TileCut tiled_cut_of(const Recipe& recipe) {
  const auto side = static_cast<int>(tiled_world_samples(recipe.world));
  return TileCut{side, side, static_cast<int>(recipe.world.tile_size - 1)};
}

void check_tiled_world_params(const WorldParams& world) {
  const long long samples = tiled_world_samples(world);
  const char* size_key = world.world_size ? "world_size" : "size";
  const int levels = terrain::levels_for_size(samples);
  if (levels < 1 || levels > terrain::max_world_levels)
    fail("world.{} {} is not allowed for a tiled world: it must be 2^k+1 between 3 and {}", size_key, samples,
         (1ll << terrain::max_world_levels) + 1);
  if (terrain::levels_for_size(world.tile_size) < 1 || world.tile_size > samples)
    fail("world.tile_size {} is not allowed: it must be 2^m+1 between 3 and the world size {}", world.tile_size, samples);
  if ((samples - 1) % (world.tile_size - 1) != 0)
    fail("world.tile_size {} does not divide the world: world size - 1 ({}) must be a multiple of tile size - 1 ({})", world.tile_size,
         samples - 1, world.tile_size - 1);
  // Counted in 64 bits before any list of tiles is made (an int wraps at 2^31 tiles).
  const std::int64_t per_side = (samples - 1) / (world.tile_size - 1), tiles = per_side * per_side;
  if (tiles > most_tiles)
    fail(
        "world.tile_size {} cuts the {}-sample world into {} tiles: at most {} are allowed; give larger tiles (2^m+1, up to the world "
        "size)",
        world.tile_size, samples, tiles, most_tiles);
  if (world.tile) fail("world.tile is not allowed with world.tiled: a tiled world builds every tile (leave tile unset)");
  if (world.lod != 0) fail("world.lod {} is not allowed with world.tiled: a tiled world is built at full resolution (lod 0)", world.lod);
}

void check_tiled_steps(const Recipe& recipe) {
  int erode_steps = 0;
  for (const ShapeStep& step : recipe.shape) {
    if (step.step != StepKind::erode) fail("a tiled world takes erode steps only: remove its stage filter step");
    ++erode_steps;
  }
  if (erode_steps > 1) fail("a tiled world takes one erode step at most; the recipe has {}", erode_steps);
  if (erode_steps == 1 && detail::plan_erosion(recipe.shape.front(), recipe.version, std::nullopt).model < 2)
    fail("a tiled world erodes with model 2 or later: give the recipe sansui_recipe = 2 or later");
}

void check_tiled_outputs(const Recipe& recipe) {
  for (const Output& output : recipe.outputs) {
    const std::optional<OutputKind> kind = resolved_kind(output);
    const std::string extension = std::filesystem::path(output.file).extension().string();
    if (kind && is_tiled_grid(*kind)) {
      if (extension != ".vrt")
        fail("output {}: a tiled world writes grids as GeoTIFF tiles under a GDAL VRT: name it NAME.vrt (kind = \"{}\")", output.file,
             output_kind_name(*kind));
      continue;
    }
    if (kind == OutputKind::rivers || kind == OutputKind::lakes) continue;  // one GeoJSON, joined across tiles
    if (kind == OutputKind::splat_map) continue;                            // a PNG per tile, under NAME.vrt
    if (!kind && io::lower_extension(output.file) == ".vrt")
      fail(
          "output {}: give its kind: a tiled world's NAME.vrt gathers the GeoTIFF tiles of one grid, kind = \"heightmap\", "
          "\"erosion_map\", \"deposition_map\" or \"flow_map\"",
          output.file);
    fail(
        "output {} is not allowed in a tiled world: it writes heightmap, erosion_map, deposition_map and flow_map grids (NAME.vrt), "
        "splat maps (a PNG per tile), and rivers and lakes (GeoJSON)",
        output.file);
  }
}

/// The erode step's plan, or none.
std::optional<detail::ErosionPlan> tiled_erosion_of(const Recipe& recipe) {
  if (recipe.shape.empty()) return std::nullopt;
  return detail::plan_erosion(recipe.shape.front(), recipe.version, std::nullopt);
}

/// The grid of one output on tile k's own cells.
Grid<float> tile_grid(OutputKind kind, const water::ErodingTile& tile, const water::RoutedTile& flow, const TileCut& cut) {
  const Rect own = cut.owned(tile.tile), halo = cut.haloed(tile.tile);
  Grid<float> grid(own.width(), own.height(), 0.0f, tile.flow.heights.cell_size_m);
  for (int y = 0; y < own.height(); ++y)
    for (int x = 0; x < own.width(); ++x) switch (kind) {
        case OutputKind::heightmap:
          grid(x, y) = tile.flow.heights(x + own.x0 - halo.x0, y + own.y0 - halo.y0);
          break;
        case OutputKind::erosion_map:
          grid(x, y) = tile.eroded_m(x, y);
          break;
        case OutputKind::deposition_map:
          grid(x, y) = tile.deposited_m(x, y);
          break;
        default:  // flow_map: as water_layers.cpp's flow_map()
          grid(x, y) = static_cast<float>(std::log10(std::max(flow.area_m2(x, y), 1.0)));
          break;
      }
  return grid;
}

/// Tile t's picture of a splat map output NAME.png (or NAME.vrt): NAME_tx_ty.png beside it.
std::filesystem::path splat_tile_path(const std::filesystem::path& output, const TileCut& cut, int t) {
  return output.parent_path() / fmt::format("{}_{}_{}.png", output.stem().string(), t % cut.tiles_x(), t / cut.tiles_x());
}

/// Tile (tx, ty)'s file of an output NAME.vrt: NAME_tx_ty.tif beside it.
std::filesystem::path tile_path(const std::filesystem::path& vrt, const TileCut& cut, int t) {
  return vrt.parent_path() / fmt::format("{}_{}_{}.tif", vrt.stem().string(), t % cut.tiles_x(), t / cut.tiles_x());
}

/// FNV-1a of a grid's samples: a finished tile's sidecar records it, and a rerun skips the tile
/// when the file still holds those samples.
std::uint64_t fnv1a(const void* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  return hash;
}
std::uint64_t samples_hash(const Grid<float>& grid) {
  return fnv1a(grid.data(), grid.size() * sizeof(float));
}

/// A tile file finished by a run of the same world: its sidecar names the world's key and the
/// hash of the samples the file holds. Its samples, or nothing.
std::optional<Grid<float>> finished_tile(const std::filesystem::path& path, const std::string& world_key, const TileCut& cut, int t) {
  try {
    if (!std::filesystem::is_regular_file(path)) return std::nullopt;
    // Read as any input is (a regular file, of bounded size): a FIFO planted there would hang.
    const std::optional<nlohmann::json> sidecar =
        nlohmann::json::parse(io::read_text_file(path.string() + ".json", 1 << 20), nullptr, false);
    if (!sidecar->is_object() || sidecar->value("/provenance/world_key"_json_pointer, std::string()) != world_key) return std::nullopt;
    // The tile of this position (a tile file copied from another position has that one's).
    const Rect own = cut.owned(t);
    if (sidecar->value("/provenance/tile"_json_pointer, nlohmann::json()) != nlohmann::json{own.x0 / cut.tile, own.y0 / cut.tile})
      return std::nullopt;
    Grid<float> grid = io::read_heightmap(path);
    if (grid.width() != own.width() || grid.height() != own.height()) return std::nullopt;
    if (fmt::format("{:016x}", samples_hash(grid)) != sidecar->value("/provenance/samples_hash"_json_pointer, std::string()))
      return std::nullopt;
    return grid;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable: made again
  }
}

/// A rivers or lakes output, joined across tiles: written by rank 0, as the whole world's are.
void write_geojson(const Recipe& recipe, std::size_t index, const std::string& text, const std::optional<io::Crs>& crs,
                   const RunOptions& options, TileExchange& exchange, RunReport& report) {
  const std::filesystem::path path = detail::resolve(recipe, recipe.outputs[index].file);
  report.written.push_back(path);
  if (exchange.rank() != 0) return;
  nlohmann::json provenance = output_provenance(recipe, index, options);
  if (crs) provenance["crs"] = io::crs_to_sidecar(*crs);
  const std::optional<io::Crs> named = detail::named_crs(crs, recipe.version, true);
  const std::string with_crs = named ? io::with_geojson_crs(text, *named) : text;
  const OutputKind kind = *resolved_kind(recipe.outputs[index]);
  io::write_text_file(path, with_crs, output_kind_name(kind), provenance);
  report.lines.push_back(fmt::format("{} of the whole world, joined across tiles -> {}", output_kind_name(kind), path.string()));
}

/// A splat map output as one PNG per tile, NAME_X_Y.png: each tile's weights from its samples and
/// the ring around them (the slopes across its borders) and the whole world's lowest and highest
/// heights, so the tiles are the whole world's splat map cut up. Collective.
void write_splat_tiles(const Recipe& recipe, std::size_t index, const TileCut& cut, const std::vector<water::ErodingTile>& tiles,
                       const RunOptions& options, TileExchange& exchange, RunReport& report) {
  float lowest = std::numeric_limits<float>::infinity(), highest = -lowest;
  for (const water::ErodingTile& t : tiles) {
    const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const float h = t.flow.heights(x - halo.x0, y - halo.y0);
        lowest = std::min(lowest, h), highest = std::max(highest, h);
      }
  }
  const look::HeightSpan world{static_cast<float>(-exchange.max(-static_cast<double>(lowest))),
                               static_cast<float>(exchange.max(static_cast<double>(highest)))};
  Recipe looked = recipe;
  resolve_look(looked);
  const look::RenderParams resolved = look::with_fallbacks(looked.render);
  const std::filesystem::path png = detail::resolve(recipe, recipe.outputs[index].file);
  const auto [east_m, south_m] = world_sample_origin(recipe.world);
  for (const water::ErodingTile& t : tiles) {
    const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
    Heightfield apron = t.flow.heights;
    apron.origin_x_m = east_m + halo.x0 * recipe.world.cell_m, apron.origin_y_m = south_m + halo.y0 * recipe.world.cell_m;
    const look::SurfaceWeights ring = look::surface_weights(apron, resolved, world);
    const auto cropped = [&](const Grid<float>& g) {
      Grid<float> c(own.width(), own.height(), 0.0f);
      for (int y = own.y0; y < own.y1; ++y)
        for (int x = own.x0; x < own.x1; ++x) c(x - own.x0, y - own.y0) = g(x - halo.x0, y - halo.y0);
      return c;
    };
    const look::SurfaceWeights weights{cropped(ring.sand), cropped(ring.grass), cropped(ring.rock), cropped(ring.snow)};
    nlohmann::json provenance = output_provenance(recipe, index, options);
    provenance["tile"] = {own.x0 / cut.tile, own.y0 / cut.tile};
    const nlohmann::json grid = {
        {"kind", "splat_map"},
        {"cell_size_m", recipe.world.cell_m},
        {"origin", {{"east_m", east_m + own.x0 * recipe.world.cell_m}, {"south_m", south_m + own.y0 * recipe.world.cell_m}}},
        {"encoding", "r sand, g grass, b rock, a snow: weights 0..1 as 0..255 that sum to 255"}};
    const std::filesystem::path path = splat_tile_path(png, cut, t.tile);
    io::write_png(path, look::splat_weights_image(weights), provenance, grid);
    // A world file places the tile, so that GIS tools (and the VRT over them) read it in place.
    io::write_text_file(
        io::png_world_file_path(path),
        io::png_world_file_text(recipe.world.cell_m, east_m + own.x0 * recipe.world.cell_m, south_m + own.y0 * recipe.world.cell_m),
        "world file");
  }
  // Every rank's tiles are written before the mosaic names them: no partial VRT.
  exchange.sum(0);
  const std::filesystem::path vrt = std::filesystem::path(png).replace_extension(".vrt");
  if (exchange.rank() == 0) {
    std::vector<std::filesystem::path> all;
    all.reserve(static_cast<std::size_t>(cut.tiles()));
    for (int t = 0; t < cut.tiles(); ++t) all.push_back(splat_tile_path(png, cut, t));
    io::write_vrt_mosaic(vrt, all, output_provenance(recipe, index, options), "splat_map");
    report.lines.push_back(
        fmt::format("splat map in {} tiles -> {}_X_Y.png, under {}", cut.tiles(), (png.parent_path() / png.stem()).string(), vrt.string()));
  }
  report.written.push_back(vrt);
}

/// Every rank makes the outputs' folders and writes a probe there; if any rank cannot, every
/// rank stops with the same line before any work. Collective.
void check_writable(const Recipe& recipe, TileExchange& exchange) {
  std::int64_t cannot = 0;
  for (const Output& output : recipe.outputs) {
    const std::filesystem::path folder = detail::resolve(recipe, output.file).parent_path();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error || !io::can_create_file_in(folder)) ++cannot;
  }
  if (const std::int64_t failed = exchange.sum(cannot > 0 ? 1 : 0); failed > 0) {
    exchange.failed_together = true;
    fail(
        "the output folder of {} is not writable by every rank ({} of {} ranks cannot write it): give --out-dir a folder all ranks share "
        "and may write",
        recipe.outputs.front().file, failed, exchange.ranks());
  }
}

}  // namespace

void check_tiled_world(const Recipe& recipe) {
  if (recipe.source != SourceKind::midpoint) fail("a tiled world is generated by the midpoint source: set source = \"midpoint\"");
  if (!recipe.nodes.empty()) fail("a tiled world is a recipe of a source and shape steps, not yet a graph ([[node]])");
  check_tiled_world_params(recipe.world);
  check_tiled_steps(recipe);
  check_tiled_outputs(recipe);
  plan_outputs(recipe);  // every file of the run, the tiles too, before any work
}

/// Runs `check` on every rank; if it fails on any, every rank throws the same InputError (the
/// first failing rank's line is not known to the others, so each names its own or the count).
/// Collective.
template <class Check>
void check_on_every_rank(TileExchange& exchange, Check&& check) {
  std::string problem;
  try {
    check();
  } catch (const InputError& e) {
    problem = e.what();
  }
  const std::int64_t failed = exchange.sum(problem.empty() ? 0 : 1);
  if (failed == 0) return;
  exchange.failed_together = true;
  if (problem.empty())
    problem = fmt::format("{} of {} ranks found a problem with this run (their lines say which)", failed, exchange.ranks());
  throw InputError(problem);
}

namespace {

/// The largest share of tiles a rank holds must fit its memory: checked on every rank alike
/// before any work. Collective.
void check_rank_share(const Recipe& recipe, const TileCut& cut, TileExchange& exchange) {
  const int busiest_share = (cut.tiles() + exchange.ranks() - 1) / exchange.ranks();  // whole tiles
  const auto tiles_per_rank = static_cast<double>(busiest_share);
  const double tile_cells = static_cast<double>(cut.tile + 1) * static_cast<double>(cut.tile + 1);
  check_on_every_rank(exchange, [&] {
    check_memory(tiles_per_rank * tile_cells * tiled_bytes_per_cell,
                 fmt::format("a tiled world's share per rank ({} tiles of {} x {} samples)", tiles_per_rank, recipe.world.tile_size,
                             recipe.world.tile_size));
  });
}

/// The tile files of this rank that a run of the same world finished (a rerun after a rank
/// died), per output and per tile of this rank, and whether the world is not made again.
struct FinishedTiles {
  std::vector<std::vector<std::optional<Grid<float>>>> of_output;  // [output index][k], k in this rank's tiles
  bool resume = false;                                             // every rank has every tile of the heights and of the erosion's maps

  /// Tile k of the first output of `kind` that has it finished, or null.
  const Grid<float>* grid(const Recipe& recipe, OutputKind kind, std::size_t k) const {
    for (std::size_t index = 0; index < recipe.outputs.size(); ++index)
      if (*resolved_kind(recipe.outputs[index]) == kind && of_output[index][k]) return &*of_output[index][k];
    return nullptr;
  }
};

/// Collective (whether every rank can resume).
FinishedTiles find_finished_tiles(const Recipe& recipe, const TileCut& cut, const std::vector<int>& mine, const std::string& world_key,
                                  TileExchange& exchange) {
  FinishedTiles finished;
  finished.of_output.resize(recipe.outputs.size());
  std::int64_t missing_shape_tiles = 0;
  for (std::size_t index = 0; index < recipe.outputs.size(); ++index) {
    const OutputKind kind = *resolved_kind(recipe.outputs[index]);
    auto& tiles = finished.of_output[index];
    for (int t : mine) {
      tiles.push_back(finished_tile(tile_path(detail::resolve(recipe, recipe.outputs[index].file), cut, t), world_key, cut, t));
      if (kind != OutputKind::flow_map && !tiles.back()) ++missing_shape_tiles;
    }
  }
  const bool has_heights = std::ranges::any_of(recipe.outputs, [](const Output& o) { return resolved_kind(o) == OutputKind::heightmap; });
  finished.resume = has_heights && exchange.sum(missing_shape_tiles) == 0;
  return finished;
}

/// This rank's tiles, their heights and erosion maps read back from the finished files. Collective.
std::vector<water::ErodingTile> read_finished_tiles(const Recipe& recipe, const TileCut& cut, const std::vector<int>& mine,
                                                    const FinishedTiles& finished, TileExchange& exchange) {
  std::vector<water::ErodingTile> tiles = water::eroding_tiles(cut, recipe.world.cell_m, exchange, [&](int t) {
    const auto k = static_cast<std::size_t>(std::ranges::find(mine, t) - mine.begin());
    return *finished.grid(recipe, OutputKind::heightmap, k);
  });
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    if (const Grid<float>* map = finished.grid(recipe, OutputKind::erosion_map, k)) tiles[k].eroded_m = *map;
    if (const Grid<float>* map = finished.grid(recipe, OutputKind::deposition_map, k)) tiles[k].deposited_m = *map;
  }
  return tiles;
}

/// This rank's tiles made: each generates its own cells of the one world, then the world is
/// eroded across the tiles. Collective.
std::vector<water::ErodingTile> make_tiles(const Recipe& recipe, const TileCut& cut, TileExchange& exchange, const Context& context) {
  const int levels = terrain::levels_for_size(tiled_world_samples(recipe.world));
  const float offset = terrain::sea_level_offset(recipe.midpoint, levels, context) -
                       static_cast<float>(recipe.version >= 3 ? recipe.world.sea_level_m : 0.0);
  std::vector<water::ErodingTile> tiles = water::eroding_tiles(cut, recipe.world.cell_m, exchange, [&](int t) {
    Heightfield h = terrain::generate_midpoint(recipe.midpoint, terrain::WorldWindow{levels, 0, cut.owned(t)});
    if (offset != 0.0f)
      for (float& v : h.values()) v -= offset;
    return h;
  });
  context.report("world", 0.1);  // the terrain of this rank's tiles
  if (const std::optional<detail::ErosionPlan> plan = tiled_erosion_of(recipe))
    water::tiled_erode(cut, tiles, plan->chain, plan->stage, exchange, part_of(context, "world", 0.1, 0.9), plan->model);
  return tiles;
}

/// The flow routing of this rank's tiles when an output needs it (a flow map, rivers, lakes);
/// empty routings otherwise. Collective.
std::vector<water::RoutedTile> route_for_outputs(const Recipe& recipe, const TileCut& cut, const std::vector<water::ErodingTile>& tiles,
                                                 TileExchange& exchange) {
  const bool wants_flow = std::ranges::any_of(recipe.outputs, [](const Output& o) {
    const OutputKind kind = *resolved_kind(o);
    return kind == OutputKind::flow_map || kind == OutputKind::rivers || kind == OutputKind::lakes;
  });
  std::vector<water::RoutedTile> flows(tiles.size());
  if (wants_flow) {
    for (std::size_t k = 0; k < tiles.size(); ++k) flows[k].tile = tiles[k].tile, flows[k].heights = tiles[k].flow.heights;
    water::route_tiles(cut, flows, flow_params(recipe).outlets(), recipe.world.cell_m, exchange);
  }
  return flows;
}

/// What the outputs of a tiled run are written from.
struct TiledProducts {
  const std::vector<water::ErodingTile>& tiles;  // this rank's
  const std::vector<water::RoutedTile>& flows;   // their routing (empty unless an output needs it)
  const FinishedTiles& finished;
  const std::string& world_key;
  const std::optional<io::Crs>& crs;
};

/// A grid output as one GeoTIFF per tile (but those a run of the same world finished), and
/// their VRT mosaic once every rank has written its tiles. Collective.
void write_grid_tiles(const Recipe& recipe, std::size_t index, const TileCut& cut, const TiledProducts& products, const RunOptions& options,
                      TileExchange& exchange, RunReport& report) {
  const OutputKind kind = *resolved_kind(recipe.outputs[index]);
  const std::vector<water::ErodingTile>& tiles = products.tiles;
  const std::filesystem::path vrt = detail::resolve(recipe, recipe.outputs[index].file);
  const auto [east_m, south_m] = world_sample_origin(recipe.world);
  // 0 to the largest value over the world, as splat maps are (heights: their own metres).
  double high = 0.0;
  std::vector<Grid<float>> grids;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    grids.push_back(tile_grid(kind, tiles[k], products.flows[k], cut));
    for (float v : grids.back().values()) high = std::max(high, static_cast<double>(v));
  }
  high = exchange.max(high);
  std::filesystem::create_directories(vrt.parent_path());
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    if (products.finished.of_output[index][k]) continue;  // the file holds these very samples already
    const Rect own = cut.owned(tiles[k].tile);
    Grid<float>& grid = grids[k];
    grid.origin_x_m = east_m + own.x0 * recipe.world.cell_m, grid.origin_y_m = south_m + own.y0 * recipe.world.cell_m;
    io::HeightmapWriteOptions write;
    write.provenance = output_provenance(recipe, index, options);
    write.provenance["tile"] = {own.x0 / cut.tile, own.y0 / cut.tile};
    write.provenance["world_key"] = products.world_key;
    write.provenance["samples_hash"] = fmt::format("{:016x}", samples_hash(grid));
    write.crs = detail::named_crs(products.crs, recipe.version, false);
    write.compression = recipe.heightmap_output.compression;
    if (kind != OutputKind::heightmap) write.range = io::HeightRange{0.0, std::max(high, 1e-6)};
    io::write_heightmap(tile_path(vrt, cut, tiles[k].tile), grid, write);
  }
  // Every rank's tiles are written before the mosaic names them: no partial VRT.
  exchange.sum(0);
  if (exchange.rank() == 0) {
    std::vector<std::filesystem::path> all;
    all.reserve(static_cast<std::size_t>(cut.tiles()));
    for (int t = 0; t < cut.tiles(); ++t) all.push_back(tile_path(vrt, cut, t));
    io::write_vrt_mosaic(vrt, all, output_provenance(recipe, index, options), output_kind_name(kind));
    report.lines.push_back(fmt::format("{} {}x{} in {} tiles of {} samples -> {}", output_kind_name(kind), cut.width, cut.height,
                                       cut.tiles(), cut.tile, vrt.string()));
  }
  report.written.push_back(vrt);
}

/// Every output, in the recipe's order: grids as tiles under a VRT, splat maps as a PNG per
/// tile, rivers and lakes joined across tiles. Collective.
void write_tiled_outputs(const Recipe& recipe, const TileCut& cut, const TiledProducts& products, const RunOptions& options,
                         TileExchange& exchange, RunReport& report) {
  const auto [east_m, south_m] = world_sample_origin(recipe.world);
  std::optional<TiledWaterTexts> water;
  for (std::size_t index = 0; index < recipe.outputs.size(); ++index) {
    const OutputKind kind = *resolved_kind(recipe.outputs[index]);
    if (kind == OutputKind::rivers || kind == OutputKind::lakes) {
      if (!water) {
        std::vector<const water::RoutedTile*> routed;
        routed.reserve(products.flows.size());
        for (const water::RoutedTile& flow : products.flows) routed.push_back(&flow);
        water = tiled_water_geojson(cut, routed, flow_params(recipe), contour::GridFrame{east_m, south_m, recipe.world.cell_m}, exchange);
      }
      write_geojson(recipe, index, kind == OutputKind::rivers ? water->rivers : water->lakes, products.crs, options, exchange, report);
      continue;
    }
    if (kind == OutputKind::splat_map) {
      write_splat_tiles(recipe, index, cut, products.tiles, options, exchange, report);
      continue;
    }
    write_grid_tiles(recipe, index, cut, products, options, exchange, report);
  }
}

}  // namespace

RunReport run_tiled_world(const Recipe& given, const RunOptions& options, const Context& context) {
  OneProcess alone;
  TileExchange& exchange = options.exchange ? *options.exchange : alone;
  check_on_every_rank(exchange, [&] { check_recipe(given); });
  RunReport report;
  report.resolved = given;
  Recipe& recipe = report.resolved;
  settle_world(recipe);
  if (recipe.base_dir.empty()) recipe.base_dir = std::filesystem::current_path();
  detail::resolve_midpoint_recipe(recipe);
  const TileCut cut = tiled_cut_of(recipe);
  const std::vector<int> mine = exchange.my_tiles(cut);
  if (exchange.ranks() > cut.tiles() && exchange.rank() == 0)
    context.note(fmt::format("warning: {} ranks for {} tiles: {} ranks stay idle (use fewer ranks or a smaller world.tile_size)",
                             exchange.ranks(), cut.tiles(), exchange.ranks() - cut.tiles()));
  check_rank_share(recipe, cut, exchange);
  std::vector<std::string> notes;
  const std::optional<io::Crs> crs = detail::output_crs(recipe, notes);
  if (exchange.rank() == 0)
    for (const auto& note : notes) context.note(note);

  check_writable(recipe, exchange);

  // Tiles a run of the same world finished are kept (a rerun after a rank died): when every
  // tile of the heights and of the erosion's maps is there, the world is not made again.
  const std::string key_text = terrain_key(recipe);
  const std::string world_key = fmt::format("{:016x}", fnv1a(key_text.data(), key_text.size()));
  const FinishedTiles finished = find_finished_tiles(recipe, cut, mine, world_key, exchange);
  std::vector<water::ErodingTile> tiles;
  if (finished.resume) {
    tiles = read_finished_tiles(recipe, cut, mine, finished, exchange);
    if (exchange.rank() == 0) report.lines.push_back("every tile of the world's heights was there: the world was not made again");
  } else {
    tiles = make_tiles(recipe, cut, exchange, context);
  }

  // Outputs: each tile's GeoTIFF; the mosaics once every rank has written its tiles.
  const std::vector<water::RoutedTile> flows = route_for_outputs(recipe, cut, tiles, exchange);
  write_tiled_outputs(recipe, cut, TiledProducts{tiles, flows, finished, world_key, crs}, options, exchange, report);
  context.report("world", 1.0);
  // The whole run's traffic, said once by rank 0 (the other ranks print nothing but errors).
  const auto sent = static_cast<double>(exchange.bytes_sent);
  const auto total = static_cast<double>(exchange.sum(static_cast<std::int64_t>(exchange.bytes_sent)));
  const double most = exchange.max(sent);
  if (exchange.rank() == 0)
    report.lines.push_back(exchange.ranks() == 1
                               ? fmt::format("{} tiles, {:.3g} MB sent in {} exchanges", mine.size(), sent / 1e6, exchange.exchanges)
                               : fmt::format("{} ranks, {} tiles: {:.3g} MB sent in {} exchanges, at most {:.3g} MB by one rank",
                                             exchange.ranks(), cut.tiles(), total / 1e6, exchange.exchanges, most / 1e6));
  return report;
}

}  // namespace sansui::scene
