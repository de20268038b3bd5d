// Land past the map's edge for the erosion to run on (erosion model 4, erode.hpp).
//
// A map is a window on land that goes on. Eroded inside its edge alone, each edge is a divide:
// no water comes in across it, so a strip along it erodes less than the land inside and stands as
// a rim that ends in a scarp (2049^2, seed 1: slopes of 34 degrees within 5 cells of the north
// edge against 29 just inside). Eroded with a margin of land past the edge, water crosses the
// edge both ways, and the map's edge strip erodes as the land inside does.
#pragma once

#include "core/grid.hpp"

namespace sansui::water {

/// Cells of land past each edge. 16 take the rim away at 1025^2 to 4097^2 (the edge strip's
/// slopes then differ from the land inside as the raw terrain's do); the erosion takes 7-8 %
/// longer at 1025^2 (bench_water DefaultErosion, models 3 and 4).
inline constexpr int edge_margin_cells = 16;

/// The margin of a grid whose shorter side has `samples` samples: edge_margin_cells, or fewer on a
/// grid too small to reflect that many (a margin reflects the cells inside it).
int edge_margin(int samples);

/// Columns or rows of land added past each side of a grid.
struct Margins {
  int left = 0, top = 0, right = 0, bottom = 0;
};

/// `heights` with the margins added, each the point reflection of the land inside through its
/// edge sample: h(-k) = 2 h(0) - h(k). The land's slope goes on across the edge, where a mirror
/// would make every edge a ridge or a valley. The left and right margins come first, then the top
/// and bottom ones from the widened rows, so corners reflect both ways: a tile of a world given
/// the margins on the world's edges it touches gets the very values of the whole world's. The
/// origin moves with the margins. Each margin is less than the grid's side.
Heightfield extended_past_edges(const Heightfield& heights, Margins margins);

/// The part of `grid` inside margins of `margin_x` columns left and right and `margin_y` rows
/// above and below: the map that extended_past_edges was given, origin included.
Grid<float> inside_margins(const Grid<float>& grid, int margin_x, int margin_y);

}  // namespace sansui::water
