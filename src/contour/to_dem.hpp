// From contours to a grid DEM (SPEC 1.3; Misawa, Chiba, Saito 1987, Sec. 5 suggest going through a
// lattice model). Every cell between a contour C and the contours directly inside it (C's
// children) is interpolated from its distances to the lower contour (C) and the upper one (the
// nearest child), z = z_C + (z_child - z_C) * d_low / (d_low + d_up), as GRASS r.surf.contour
// does; above a summit contour a smooth cap z_C + h (2t - t^2), t the distance to C over the
// largest such distance inside it, h at most dz; inside the floor contour of a depression (a
// contour below its parent: a crater) its own elevation, flat; outside the outermost contour the
// base elevation, or foothills (Surround). So no cell is ever above the contour over it or below the one under it.
//
// Distances come from linear-time Euclidean feature transforms (edt.hpp), one per class of
// contour depth modulo 8: the cells a contour's segments pass through are the sources, and each
// cell's distance is measured exactly to the segment its nearest source holds. A cell inside a
// depth-k contour takes its lower distance from class k (the nearest such contour is its own)
// and its upper distance from class k+1 (its children; contours of depth k-7, which share the
// class, lie at least six contour spacings away). Without loops over segments per cell, 2049^2
// cells take well under a second.
#pragma once

#include <cstdint>
#include <optional>

#include "contour/contour_tree.hpp"
#include "core/budget.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::contour {

/// What the DEM holds outside the outermost contour (the mountain's foot).
enum class Surround {
  flat,       ///< the base elevation everywhere
  foothills,  ///< a fractal terrain (midpoint displacement) around the base, blended in from the foot
};

/// Table: contour_params.cpp (section [contour_dem]; the grid and the generation's values are
/// set by the pipeline).
struct DemParams {
  /// Samples per side. [Range: 2..32768]
  int width = 1025, height = 1025;
  /// Distance between samples. [Units: m] [Range: > 0]
  double cell_m = 1.0;
  /// Position of sample (0, 0): east, and south (= -north; see grid_frame.hpp). [Units: m]
  double origin_x_m = 0.0, origin_y_m = 0.0;
  /// Elevation outside the outermost contour. [Units: m] [Default: the lowest root's elevation]
  std::optional<double> base_m;
  /// Height of the cap above a summit contour (reached only by caps at least 2 d wide).
  /// [Units: m] [Range: >= 0] [Default: the contour interval]
  std::optional<double> cap_m;
  /// d of the generation: a summit contour narrower than 2 d gets a proportionally lower cap.
  /// [Units: m] [Range: > 0] [Default: 10]
  double offset_m = 10.0;
  /// Standard deviation of midpoint-displacement roughness added afterwards (Fig. 11), fading to
  /// zero on the contours and kept between them. 0: none. [Units: m] [Range: >= 0] [Default: 0]
  double roughness_m = 0.0;
  /// Hurst exponent of the roughness. [Range: 0 < H <= 1] [Default: 0.7]
  double roughness_hurst = 0.7;
  /// Seed of the roughness. [Default: 1]
  std::uint64_t seed = 1;
  /// Outside the outermost contour: flat at the base, or foothills. [Default: foothills]
  Surround surround = Surround::foothills;
  /// Standard deviation of the foothills about the base. [Units: m] [Range: >= 0]
  /// [Default: unset: a tenth of the mountain's relief above the base]
  std::optional<double> foothill_relief_m;
  /// Distance from the foot over which the foothills blend in from the base (smoothstep).
  /// [Units: m] [Range: > 0] [Default: unset: a tenth of the contours' larger extent]
  std::optional<double> foothill_width_m;
  /// Hurst exponent of the foothills. [Range: 0 < H <= 1] [Default: 0.8]
  double foothill_hurst = 0.8;

  void validate() const;
};
const params::Table<DemParams>& parameter_table(const DemParams*);

/// A frame (width, height, cell, origin) that holds every contour of `tree` with a margin of
/// `margin_fraction` of the larger side, with `samples` samples along the larger side (the
/// pipeline takes 0.05 for a flat surround, 0.25 for foothills).
DemParams dem_frame_for(const ContourTree& tree, int samples, double margin_fraction = 0.05);

/// What contours_to_dem needs for `params`' grid: its working arrays (labels, depth classes, two
/// distances, the feature transform's sources and owners, the weights, foothills' and roughness'
/// noise) are about 7 times the DEM it returns (measured: 26 bytes a cell with foothills), and
/// about 0.26 microseconds a cell.
budget::Cost dem_cost(const DemParams& params);

/// Rasterises the tree (see above). Throws InputError for bad parameters or when dem_cost() does
/// not fit the budget (budget::check), before any grid is allocated.
Heightfield contours_to_dem(const ContourTree& tree, const DemParams& params, const Context& context = quiet_context());

/// Which contour each cell lies in (the innermost containing it), or -1 outside all of them.
Grid<std::int32_t> innermost_contour(const ContourTree& tree, const DemParams& params);

}  // namespace sansui::contour
