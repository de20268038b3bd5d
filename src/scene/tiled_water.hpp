// The rivers and lakes GeoJSON of a world cut into tiles, joined across tiles: a river or a lake
// that crosses tile borders is one feature, and the texts are byte for byte those that
// surface_water, rivers_to_geojson and lakes_to_geojson give for the whole world.
//
// Rivers: Strahler orders run as a wavefront from the sources down, across tiles
// (water/tiled_wave.hpp). Each tile traces the pieces of reaches inside it, from a source or a
// confluence, or from the cell where a reach enters from another tile, down to a confluence, an
// outlet or the tile's edge, and sends them to the root, which joins them into whole reaches.
// Lakes: each tile sends its flooded cells (runs along rows, with their levels and ground) to the
// root, which labels the lakes as lakes_of does and traces each shore on a window around the lake.
//
// What the root holds: the cells of the rivers and the lakes (what the texts hold), never the
// whole world's grids.
#pragma once

#include <string>
#include <vector>

#include "contour/grid_frame.hpp"
#include "core/tile_exchange.hpp"
#include "water/flow.hpp"
#include "water/tiled_routing.hpp"

namespace sansui::scene {

/// The rivers and lakes GeoJSON texts of a world (without a CRS member: the caller adds it as
/// for the whole world's texts).
struct TiledWaterTexts {
  std::string rivers, lakes;
};

/// The rivers and lakes of a tiled world as surface_water + rivers_to_geojson / lakes_to_geojson
/// give them for the whole world, byte for byte; on rank 0 (other ranks: empty texts).
/// `tiles`: this rank's tiles (exchange.my_tiles(cut), in that order), routed by route_tiles
/// with params.outlets(), their `heights` haloed. `world`: the whole world's origin and cell
/// size. Collective. Throws InputError on bad params (on every rank alike).
TiledWaterTexts tiled_water_geojson(const TileCut& cut, const std::vector<const water::RoutedTile*>& tiles, const water::FlowParams& params,
                                    const contour::GridFrame& world, TileExchange& exchange);

}  // namespace sansui::scene
