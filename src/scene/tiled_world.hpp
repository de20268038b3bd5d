// A world built tile by tile ([world] tiled = true): a midpoint world generated in tiles of
// tile_size samples, eroded with drainage exact across tiles (water/tiled_erosion.hpp), and its
// outputs written per tile: grids as GeoTIFF tiles under a GDAL VRT, rivers and lakes as one
// GeoJSON each. The tiles are spread over the ranks of an MPI run, or worked through in turn by
// one process; either way the bytes are those of the same world built untiled.
#pragma once

#include "scene/pipeline.hpp"

namespace sansui::scene {

/// Throws InputError unless `recipe` is a tiled world Sansui can build, naming what is allowed.
void check_tiled_world(const Recipe& recipe);

/// Builds the tiled world of `recipe` (check_tiled_world first) with options.exchange's ranks
/// (null: this process alone). Every rank returns its own report; rank 0's names the mosaics.
RunReport run_tiled_world(const Recipe& recipe, const RunOptions& options, const Context& context);

/// Bytes one rank holds per cell of its tiles while it erodes them (heights, maps, routing,
/// the wavefronts' values and the diffusion's sweeps). [Units: bytes]
inline constexpr double tiled_bytes_per_cell = 120.0;

}  // namespace sansui::scene
