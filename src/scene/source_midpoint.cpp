// The midpoint source: fractal terrain (terrain/midpoint.hpp), whole or one tile of a larger
// world, at any level of detail. The window maths live here so every front end shares them.
#include <algorithm>

#include "core/error.hpp"
#include "scene/sources.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::scene::detail {
namespace {

struct WorldPlan {
  int world_levels = 0;
  int step = 1;  ///< 2^lod world samples per output sample
  Rect window;   ///< in output samples
};

WorldPlan plan(const WorldParams& world) {
  const bool tiled = world.tile.has_value();
  const long long world_size = world.world_size.value_or(world.size);
  const int world_levels = terrain::levels_for_size(world_size);
  const long long max_size = tiled ? (1ll << terrain::max_world_levels) + 1 : 16385;
  if (world_levels < 1 || world_size > max_size)
    fail("world.{} {} is not allowed: it must be 2^k+1 between 3 and {}{}", world.world_size ? "world_size" : "size", world_size, max_size,
         tiled ? "" : " (larger worlds are generated as tiles)");
  if (world.lod >= world_levels) fail("world.lod {} is not allowed: it must be 0..{} for this world", world.lod, world_levels - 1);
  WorldPlan p{world_levels, 1 << world.lod, {}};
  const int samples = static_cast<int>((world_size - 1) / p.step + 1);
  p.window = {0, 0, samples, samples};
  if (!tiled) return p;
  if (world.tile_size > world_size)
    fail("world.tile_size {} is not allowed: it must be 2^m+1 between 3 and the world size {}", world.tile_size, world_size);
  if ((world.tile_size - 1) % p.step != 0)
    fail("world.tile_size {} does not fit world.lod {}: tile size - 1 must be a multiple of {}", world.tile_size, world.lod, p.step);
  const auto [tx, ty] = *world.tile;
  const long long tiles = (world_size - 1) / (world.tile_size - 1);
  if (tx >= tiles || ty >= tiles) fail("world.tile {},{} is outside the world: tiles go from 0,0 to {},{}", tx, ty, tiles - 1, tiles - 1);
  const int span = static_cast<int>((world.tile_size - 1) / p.step);
  p.window = {tx * span, ty * span, tx * span + span + 1, ty * span + span + 1};
  return p;
}

}  // namespace

void check_midpoint_source(const Recipe& recipe) {
  (void)plan(recipe.world);
  // Water crosses tile borders: a tile eroded on its own would not join its neighbours (each
  // treats its edge as the base level). Until worlds are eroded coarse and refined per tile,
  // an eroded world is made whole.
  const bool erodes = std::any_of(recipe.shape.begin(), recipe.shape.end(), [](const ShapeStep& s) { return s.step == StepKind::erode; });
  if (erodes && (recipe.world.tile || recipe.world.lod > 0))
    fail(
        "--erode (a [[shape]] erode step) is not allowed with world.tile or world.lod: drainage crosses tile borders, so an eroded "
        "world is generated whole (world.size up to 16385)");
}

Produced run_midpoint_source(Recipe& recipe, const Context& context) {
  const WorldPlan p = plan(recipe.world);
  Produced produced;
  produced.heights = terrain::generate_midpoint(recipe.midpoint, terrain::WorldWindow{p.world_levels, recipe.world.lod, p.window}, context);
  Heightfield& heights = *produced.heights;
  heights.cell_size_m = recipe.world.cell_m * p.step;
  heights.origin_x_m = p.window.x0 * heights.cell_size_m;
  heights.origin_y_m = p.window.y0 * heights.cell_size_m;
  // Every tile and preview of a world encodes 16 bits alike, so they join without seams.
  if (!recipe.heightmap_output.range_m && (recipe.world.tile || recipe.world.lod > 0)) {
    const double sea = recipe_sea_level(recipe), sigma = recipe.midpoint.sigma_m;
    recipe.heightmap_output.range_m = std::array<double, 2>{sea - 6.0 * sigma, sea + 6.0 * sigma};
  }
  // The stage filters measure heights in units of the terrain's sigma.
  for (ShapeStep& step : recipe.shape)
    if (step.step == StepKind::stage && !step.stage.sigma_m && recipe.midpoint.sigma_m > 0.0) step.stage.sigma_m = recipe.midpoint.sigma_m;
  return produced;
}

}  // namespace sansui::scene::detail
