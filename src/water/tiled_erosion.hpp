// Erosion of a world cut into tiles, byte for byte the whole world's (stream_power.hpp,
// erode.hpp), on any tiling and any number of ranks. Every cell does the very arithmetic of the
// untiled step, in an order that gives the same bytes:
// - Routing: tiled_routing.hpp.
// - Incision (outlets first) and sediment (sources first) are wavefronts: a tile works on every
//   cell whose neighbours it depends on are done, and sends the values its neighbouring tiles
//   wait for; rounds go on while any tile has sent something. A river that crosses tile borders k
//   times takes k rounds.
// - Sediment arriving at a cell is summed over its donors in raster order, starting from zero:
//   the order the untiled receiver stack adds them in (flow.hpp's depth-first stack pushes donors
//   in raster order), so the sums are the same.
// - Hillslope diffusion solves each row, then each column, with the Thomas algorithm: its forward
//   sweep goes along the tiles of a row left to right, carrying two numbers per row, and its back
//   substitution right to left (likewise down and up the columns).
// What is not the same: the budget's volumes are summed per tile (rounding differs in the last
// bits); the heights, flow, water and maps are exact.
#pragma once

#include <functional>
#include <vector>

#include "core/tile_exchange.hpp"
#include "water/erode.hpp"
#include "water/stream_power.hpp"
#include "water/tiled_routing.hpp"

namespace sansui::water {

/// One tile of a world eroded in tiles.
struct ErodingTile {
  int tile = 0;
  /// flow.heights: the tile's haloed rectangle (cut.haloed(tile)), its own cells current; the rest
  /// of flow: the latest routing.
  RoutedTile flow;
  Grid<float> eroded_m, deposited_m;  ///< own cells: total incision and deposition. [Units: m]
};

/// Tiles of this rank (exchange.my_tiles(cut)) with their own heights taken from `heights_of`,
/// which gives tile t's own cells (cut.owned(t)), and their halo filled. Collective.
std::vector<ErodingTile> eroding_tiles(const TileCut& cut, double cell_size_m, TileExchange& exchange,
                                       const std::function<Heightfield(int tile)>& heights_of);

/// One step of stream_power_step on the tiles, with uniform uplift and params' diffusivity set.
/// The tiles' heights change in place; their maps gain the step's incision and deposition.
/// Collective.
ErosionBudget tiled_stream_power_step(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params,
                                      TileExchange& exchange);

/// erode.cpp's follow_inner_land on the tiles' own cells (tiles of at least 2 cells).
void tiled_follow_inner_land(const TileCut& cut, std::vector<ErodingTile>& tiles, double base_level);

/// response_time_yr on the tiles (the same bytes). Collective.
double tiled_response_time(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params, TileExchange& exchange);

/// erode_droplets on the tiles' own cells, base level as erode's model 2 gives it. Each tile of
/// droplets runs on the rank of the world tile its first cell lies in, with the cells within a
/// droplet's reach of it that other tiles own sent there and back. Collective.
void tiled_droplets(const TileCut& cut, std::vector<ErodingTile>& tiles, const DropletParams& params, std::optional<double> base_level_m,
                    TileExchange& exchange);

/// erode() (models 2 to 4) on the tiles: the chain's one order (erosion_chain.hpp), on the tiles as its
/// surface. `stage` as erode's, with the tiled response time. Thermal erosion is not tiled:
/// params.thermal.iterations must be 0 (its default). Heights and the two maps are the whole
/// world's bytes. Collective.
/// Progress goes to `context` as "erosion", part by part as erode's: the parts are collective, so
/// every rank's progress is also the whole world's.
ErosionBudget tiled_erode(const TileCut& cut, std::vector<ErodingTile>& tiles, ErosionChainParams params, std::optional<ErosionStage> stage,
                          TileExchange& exchange, const Context& context = quiet_context(), int model = default_erosion_model);

/// Refreshes the halo of every tile's heights. Collective.
void exchange_heights_halo(const TileCut& cut, std::vector<ErodingTile>& tiles, TileExchange& exchange);

}  // namespace sansui::water
