// Contour lines of a heightfield by marching squares (Lorensen & Cline's 2-D case): closed rings
// at one elevation, with the higher ground on their left (counter-clockwise around hills,
// clockwise around pits). The grid is surrounded by a virtual border lower than everything, so
// every contour closes (along the border, half a cell outside it). Saddle cells are resolved by
// the mean of their four corners.
#pragma once

#include <optional>
#include <vector>

#include "contour/contour_tree.hpp"
#include "contour/geometry.hpp"
#include "core/grid.hpp"

namespace sansui::contour {

/// All closed contours at `level` (metres), in the plane of the grid (see grid_frame.hpp).
std::vector<Ring> extract_contours(const Heightfield& heights, double level);

/// The contours of a DEM around higher ground at the given levels (ascending), as a tree: each
/// ring's parent is the smallest ring of the level below that contains it. Level k of the tree is
/// levels[k]. Pits (clockwise rings) are left out.
ContourTree contours_of_dem(const Heightfield& heights, const std::vector<double>& levels);

/// The seed contour for `--from-dem`: the largest counter-clockwise contour at `level`, or, with
/// `pick`, the smallest one around that point. Throws InputError if the level lies outside the
/// grid's range or no contour qualifies.
Ring pick_contour(const Heightfield& heights, double level, std::optional<Point> pick);

}  // namespace sansui::contour
