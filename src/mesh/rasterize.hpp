// From a triangle mesh to a DEM (SPEC 4: "rasterised into a DEM so the scenery pipeline can use
// it"): every sample takes the height of the highest triangle above it, linearly interpolated,
// so overhangs made by displacing along normals resolve to the visible top surface.
#pragma once

#include <optional>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

/// Where the samples of a DEM stand: sample (i, j) at x = origin_x_m + i * cell_size_m (east),
/// z = origin_y_m + j * cell_size_m (south), as in Grid.
struct RasterFrame {
  double origin_x_m = 0.0;   ///< [Units: m]
  double origin_y_m = 0.0;   ///< south coordinate (mesh z) of row 0. [Units: m]
  double cell_size_m = 1.0;  ///< [Units: m] [Range: > 0]
  int width = 0;             ///< samples west to east. [Range: >= 1]
  int height = 0;            ///< samples north to south. [Range: >= 1]
};

/// Most samples per side a frame may have (a 64k x 64k float grid is 16 GB).
inline constexpr int max_raster_side = 65537;

/// The frame of samples `cell_size_m` apart whose first sample is the north-west corner of the
/// mesh's footprint and which covers it. Throws InputError for a bad cell size, an empty mesh or
/// a frame over max_raster_side.
RasterFrame frame_with_cell(const TriangleMesh& mesh, double cell_size_m);

/// A square frame of `samples` per side covering the mesh's footprint (its longer side exactly,
/// the shorter one centred). Throws InputError for samples < 2 or > max_raster_side.
RasterFrame square_frame(const TriangleMesh& mesh, int samples);

/// The mesh as a heightfield on `frame`: each sample holds the height (y) of the highest
/// triangle whose footprint contains it; samples no triangle covers get `fill_m`, or the
/// lowest vertex height if unset. Uses all threads; the bytes do not depend on how many.
Heightfield rasterize(const TriangleMesh& mesh, const RasterFrame& frame, std::optional<float> fill_m = std::nullopt,
                      const Context& context = quiet_context());

}  // namespace sansui::mesh
