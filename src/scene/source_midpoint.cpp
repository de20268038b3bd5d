// The midpoint source: fractal terrain (terrain/midpoint.hpp), whole or one tile of a larger
// world, at any level of detail. The window maths live here so every front end shares them.
#include <algorithm>
#include <functional>
#include <memory>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "scene/engines.hpp"
#include "scene/evaluator.hpp"
#include "scene/output_kinds.hpp"
#include "scene/recipe_file.hpp"
#include "scene/sources.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::scene::detail {
namespace {

struct WorldPlan {
  int world_levels = 0;
  int step = 1;  ///< 2^lod world samples per output sample
  Rect window;   ///< in output samples
};

/// The 2^k+1 world a world of `samples` per side is a window of: itself, or for an Unreal
/// landscape size (505, 1009...) the 2^k+1 world just above it.
int levels_above(long long samples) {
  int levels = 1;
  while ((1ll << levels) + 1 < samples) ++levels;
  return levels;
}

WorldPlan plan(const WorldParams& world) {
  const bool tiled = world.tile.has_value() || world.tiled;
  const long long world_size = world.world_size.value_or(world.size);
  const long long max_size = tiled ? (1ll << terrain::max_world_levels) + 1 : 16385;
  const char* size_key = world.world_size ? "world_size" : "size";
  if (world_size < 3 || world_size > max_size || (terrain::levels_for_size(world_size) < 1 && !is_unreal_landscape_size(world_size)))
    fail("world.{} {} is not allowed: it must be 2^k+1 or an Unreal landscape size (505, 1009, 2017, 4033, 8129...) between 3 and {}{}",
         size_key, world_size, max_size, tiled ? "" : " (larger worlds are generated as tiles)");
  const int world_levels = levels_above(world_size);
  if (world.lod >= world_levels) fail("world.lod {} is not allowed: it must be 0..{} for this world", world.lod, world_levels - 1);
  WorldPlan p{world_levels, 1 << world.lod, {}};
  if ((world_size - 1) % p.step != 0)
    fail("world.lod {} does not fit world.{} {}: size - 1 must be a multiple of {}", world.lod, size_key, world_size, p.step);
  const int samples = static_cast<int>((world_size - 1) / p.step + 1);
  p.window = {0, 0, samples, samples};
  if (!tiled) return p;
  if (world.tile_size > world_size)
    fail("world.tile_size {} is not allowed: it must be 2^m+1 between 3 and the world size {}", world.tile_size, world_size);
  if ((world_size - 1) % (world.tile_size - 1) != 0)
    fail("world.tile_size {} does not divide the world: world size - 1 ({}) must be a multiple of tile size - 1 ({})", world.tile_size,
         world_size - 1, world.tile_size - 1);
  if ((world.tile_size - 1) % p.step != 0)
    fail("world.tile_size {} does not fit world.lod {}: tile size - 1 must be a multiple of {}", world.tile_size, world.lod, p.step);
  if (!world.tile) return p;  // a tiled world: every tile (scene/tiled_world.hpp)
  const auto [tx, ty] = *world.tile;
  const long long tiles = (world_size - 1) / (world.tile_size - 1);
  if (tx >= tiles || ty >= tiles) fail("world.tile {},{} is outside the world: tiles go from 0,0 to {},{}", tx, ty, tiles - 1, tiles - 1);
  const int span = static_cast<int>((world.tile_size - 1) / p.step);
  p.window = {tx * span, ty * span, tx * span + span + 1, ty * span + span + 1};
  return p;
}

}  // namespace

/// Index one past the recipe's last erode step (0 without one).
std::size_t end_of_erosion(const Recipe& recipe) {
  std::size_t end = 0;
  for (std::size_t k = 0; k < recipe.shape.size(); ++k)
    if (recipe.shape[k].step == StepKind::erode) end = k + 1;
  return end;
}

void check_midpoint_source(const Recipe& recipe) {
  const WorldPlan p = plan(recipe.world);
  // Refused here, before any work, not by running out of memory half-way: the heights alone
  // take 4 bytes a sample (a tile's, or the whole world's).
  const WorldParams& world = recipe.world;
  const long long side = p.window.width();
  check_memory(4.0 * static_cast<double>(side) * static_cast<double>(p.window.height()),
               world.tile ? fmt::format("world.tile_size {} (a {} x {} tile)", world.tile_size, side, side)
                          : fmt::format("world.{} {} (a {} x {} heightmap)", world.world_size ? "world_size" : "size",
                                        world.world_size.value_or(world.size), side, side));
  // The heightmaps an engine preset is asked for must have a size its importer takes.
  for (const Output& output : recipe.outputs)
    if (resolved_kind(output) == OutputKind::heightmap) {
      const std::string allowed = engine_size_problem(recipe.heightmap_output.engine, p.window.width(), p.window.height());
      if (!allowed.empty())
        fail("heightmap_output.engine {} cannot take {}x{} samples (world.{} {}{}): allowed are {}",
             engine_name(recipe.heightmap_output.engine), p.window.width(), p.window.height(), recipe.world.tile ? "tile_size" : "size",
             recipe.world.tile ? recipe.world.tile_size : recipe.world.world_size.value_or(recipe.world.size),
             recipe.world.lod > 0 ? fmt::format(", lod {}", recipe.world.lod) : "", allowed);
      break;
    }
  if (end_of_erosion(recipe) == 0 || !(recipe.world.tile || recipe.world.lod > 0)) return;
  // An eroded world in tiles is eroded whole at a coarse level; its water is the whole world's,
  // which one tile cannot show.
  for (const Output& output : recipe.outputs) {
    const std::optional<OutputKind> kind = resolved_kind(output);
    if (kind && output_kind_info(*kind).water)
      fail(
          "the {} output is not allowed with world.tile or world.lod and an erode step: an eroded world's water is computed for the "
          "whole world (world.size up to 16385, without world.tile)",
          output_kind_name(*kind));
  }
}

double world_extent_m(const WorldParams& world) {
  // The 2^k+1 world generated (an Unreal landscape size is a window of the one above it).
  return static_cast<double>(1ll << plan(world).world_levels) * world.cell_m;
}

void resolve_midpoint_recipe(Recipe& recipe) {
  // Unset, the relief follows the world's extent (recipes before version 4 always give one).
  if (!recipe.midpoint.sigma_m)
    recipe.midpoint.sigma_m = terrain::default_sigma_for_extent(world_extent_m(recipe.world), recipe.midpoint.hurst);
  // The stage filters measure heights in units of the terrain's sigma.
  for (ShapeStep& step : recipe.shape)
    if (step.step == StepKind::stage && !step.stage.sigma_m && recipe.midpoint.sigma() > 0.0) step.stage.sigma_m = recipe.midpoint.sigma();
  // Every tile and preview of a world encodes 16 bits alike, so they join without seams.
  if (!recipe.heightmap_output.range_m && (recipe.world.tile || recipe.world.lod > 0)) {
    const double sea = recipe_sea_level(recipe), sigma = recipe.midpoint.sigma();
    recipe.heightmap_output.range_m = std::array<double, 2>{sea - 6.0 * sigma, sea + 6.0 * sigma};
  }
}

namespace {

/// Everything the coarse eroded world of a tiled or previewed world depends on, as text: its
/// terrain, the whole world's size, cell and erosion size, and the shaping steps up to the last
/// erosion. Every tile of one world has the same key, so with a cache they share one erosion.
std::string coarse_world_key(const Recipe& recipe, std::size_t eroded_steps) {
  Recipe key = default_recipe(SourceKind::midpoint, recipe.version);
  key.midpoint = recipe.midpoint;
  key.world.size = recipe.world.world_size.value_or(recipe.world.size);
  key.world.cell_m = recipe.world.cell_m;
  key.world.erosion_size = recipe.world.erosion_size;
  key.world.sea_level_m = recipe.world.sea_level_m;  // the base level (version 3 steps carry none of their own)
  key.shape.assign(recipe.shape.begin(), recipe.shape.begin() + static_cast<std::ptrdiff_t>(eroded_steps));
  return fmt::format("coarse world {}|{}", SANSUI_VERSION, recipe_to_json(key).dump());
}

}  // namespace

bool needs_apron(const Recipe& recipe) {
  return std::ranges::any_of(recipe.outputs, [](const Output& output) { return resolved_kind(output) == OutputKind::splat_map; });
}

Produced run_midpoint_source(Recipe& recipe, const RunOptions& options, const Context& context) {
  const WorldPlan p = plan(recipe.world);
  resolve_midpoint_recipe(recipe);
  Produced produced;
  // Sea level where the world has land_fraction above it: the whole world's, so every tile,
  // window and preview shifts alike. From version 3 on the generator's level goes to the world's
  // sea level (before, to 0 m whatever the steps' sea level), as in graphs.
  const double datum_m = recipe.version >= 3 ? recipe.world.sea_level_m : 0.0;
  const auto sea_level_offset = static_cast<float>(terrain::sea_level_offset(recipe.midpoint, p.world_levels, context) - datum_m);
  const auto shift = [sea_level_offset](Heightfield& heights) {
    if (sea_level_offset != 0.0f)
      for (float& h : heights.values()) h -= sea_level_offset;
  };
  const std::size_t eroded_steps = end_of_erosion(recipe);
  const int full_side = (1 << (p.world_levels - recipe.world.lod)) + 1;
  const bool part_of_world = recipe.world.tile || recipe.world.lod > 0 || p.window != Rect{0, 0, full_side, full_side};
  // The heights of one window of the output's samples (the tile, or the tile and its apron).
  std::function<Heightfield(const Rect&)> window_heights;
  if (eroded_steps > 0 && part_of_world) {
    // Drainage crosses tile borders, so the world is shaped and eroded whole at a coarse level
    // (world.erosion_size), and the tile (or preview, or the window an Unreal landscape size
    // takes) is refined from it: every tile refines from the same coarse world, so neighbours
    // share their borders bit for bit.
    const int coarse_levels = std::min(p.world_levels, terrain::levels_for_size(recipe.world.erosion_size));
    const int coarse_lod = p.world_levels - coarse_levels;
    const int side = (1 << coarse_levels) + 1;
    const auto erode_coarse_world = [&] {
      Produced coarse;
      coarse.heights =
          terrain::generate_midpoint(recipe.midpoint, terrain::WorldWindow{p.world_levels, coarse_lod, Rect{0, 0, side, side}}, context);
      coarse.heights->cell_size_m = recipe.world.cell_m * (1 << coarse_lod);
      shift(*coarse.heights);
      apply_shape_steps(recipe, coarse, 0, eroded_steps, context);
      return std::move(*coarse.heights);
    };
    auto coarse = std::make_shared<const Heightfield>(
        options.evaluator ? *options.evaluator->cached("coarse world", coarse_world_key(recipe, eroded_steps), erode_coarse_world)
                          : erode_coarse_world());
    window_heights = [&, coarse, coarse_lod](const Rect& window) {
      if (recipe.world.lod >= coarse_lod) {
        const int every = 1 << (recipe.world.lod - coarse_lod);
        Heightfield cut(window.width(), window.height(), 0.0f);
        for (int y = 0; y < cut.height(); ++y)
          for (int x = 0; x < cut.width(); ++x) cut(x, y) = (*coarse)((window.x0 + x) * every, (window.y0 + y) * every);
        return cut;
      }
      return terrain::refine_midpoint(recipe.midpoint, terrain::WorldWindow{p.world_levels, recipe.world.lod, window}, *coarse,
                                      recipe.world.erosion_detail, context);
    };
    produced.shape_steps_done = eroded_steps;
    produced.lines.push_back(fmt::format("eroded the whole world at {}x{} samples ({} m cells), then refined this window from it", side,
                                         side, coarse->cell_size_m));
  } else {
    window_heights = [&](const Rect& window) {
      Heightfield h = terrain::generate_midpoint(recipe.midpoint, terrain::WorldWindow{p.world_levels, recipe.world.lod, window}, context);
      shift(h);
      return h;
    };
  }
  produced.heights = window_heights(p.window);
  // A tile's splat map weighs slopes across its borders as the whole world does: from the
  // neighbouring samples, so it is made on the tile and one more sample each side.
  if (part_of_world && needs_apron(recipe)) {
    const Rect apron{std::max(p.window.x0 - 1, 0), std::max(p.window.y0 - 1, 0), std::min(p.window.x1 + 1, full_side),
                     std::min(p.window.y1 + 1, full_side)};
    produced.apron = window_heights(apron);
    produced.apron_offset = {p.window.x0 - apron.x0, p.window.y0 - apron.y0};
  }
  Heightfield& heights = *produced.heights;
  heights.cell_size_m = recipe.world.cell_m * p.step;
  const auto [east_m, south_m] = world_sample_origin(recipe.world);
  heights.origin_x_m = east_m + p.window.x0 * heights.cell_size_m;
  heights.origin_y_m = south_m + p.window.y0 * heights.cell_size_m;
  if (produced.apron) {
    produced.apron->cell_size_m = heights.cell_size_m;
    produced.apron->origin_x_m = heights.origin_x_m - produced.apron_offset[0] * heights.cell_size_m;
    produced.apron->origin_y_m = heights.origin_y_m - produced.apron_offset[1] * heights.cell_size_m;
  }
  return produced;
}

}  // namespace sansui::scene::detail
