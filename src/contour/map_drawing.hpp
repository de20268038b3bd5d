// The contour map as a small display list in pixels, in the style of the paper's Figs. 9 and 16
// (Misawa, Chiba, Saito 1987, seeds/000) and of printed topographic maps: every contour a thin
// line, every fifth (the index contour) bold and labelled with its elevation, summits marked, a
// scale bar and a north arrow. Two back ends draw the same list: SVG text (map_svg.hpp) and an
// RGBA image (map_raster.hpp), so the two pictures always agree.
#pragma once

#include <string>
#include <vector>

#include "contour/contour_tree.hpp"
#include "core/color.hpp"
#include "core/map_drawing.hpp"
#include "core/params.hpp"

namespace sansui::contour {

// The display list is plain data in core (core/map_drawing.hpp).
using sansui::MapDrawing;
using sansui::MapFill;
using sansui::MapItem;
using sansui::MapLabel;
using sansui::MapStroke;

/// Table: contour_params.cpp (section [map]).
struct MapStyle {
  /// Width of the picture. [Units: px] [Range: 64..16384] [Default: 1200]
  int width_px = 1200;
  /// Every this many levels a bold, labelled index contour. [Range: >= 1] [Default: 5]
  int index_every = 5;
  /// Line width of ordinary and index contours. [Units: px] [Default: 0.8, 2.0]
  double line_px = 0.8;
  double index_line_px = 2.0;
  /// Height of label digits. [Units: px] [Default: 13]
  double label_px = 13.0;
  /// Contour colour (sepia, as on topographic maps) and paper colour.
  Rgba8 contour{140, 80, 30, 255};
  Rgba8 paper{255, 253, 246, 255};
  Rgba8 ink{30, 30, 30, 255};
  bool labels = true;
  bool scale_bar = true;
  bool north_arrow = true;
  bool summits = true;
};
const params::Table<MapStyle>& parameter_table(const MapStyle*);

/// Lays out the map of `tree`. The contour interval and the index contours follow each node's
/// level; elevations are printed in whole metres (or tenths when the interval needs them).
MapDrawing layout_contour_map(const ContourTree& tree, const MapStyle& style = {});

/// True when `level` is an index contour for the given z0 and interval: index contours fall on
/// elevations that are multiples of index_every * dz when z0 is a multiple of dz, else every
/// index_every levels from the seed.
bool is_index_level(int level, double z0_m, double interval_m, int index_every);

}  // namespace sansui::contour
