// Droplet hydraulic erosion: water particles that run downhill with inertia, pick up sediment
// while their capacity (drop x speed x water) exceeds their load and drop it when they slow or
// climb (Beyer, "Implementation of a method for hydraulic erosion", 2015; the form popularised
// by S. Lague, 2019). Heights are handled in units of the cell size, so the same params do the
// same on any grid spacing; each step moves a droplet one cell length and erodes or deposits on
// the four cells around its position, bilinearly.
//
// Deterministic in parallel: every droplet sees the changes of those before it. The map is cut
// into tiles wider than twice a droplet's reach; the tiles of one colour of a 2x2 checkerboard
// never share a cell a droplet can touch, so they run at once, each tile's droplets in droplet
// order, the colours in turn. A droplet's start is a hash of (seed, droplet number), so the
// bytes depend on neither the thread count nor the scheduling.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

#include "core/context.hpp"
#include "core/exact_sum.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::water {

/// Table: water_params.cpp (section [droplets]).
struct DropletParams {
  /// Number of droplets. [Range: 0..1e9] [Default: unset: droplets_per_cell per cell; recipes of
  /// version 1: 200000]
  std::optional<std::int64_t> droplets;
  /// Droplets per cell when `droplets` is unset, so rills are alike on any grid size: 0.05 runs
  /// one droplet through every cell's neighbourhood about once (a droplet lives 30 steps).
  /// [Range: 0..100] [Default: 0.05]
  double droplets_per_cell = 0.05;
  /// Random seed of the droplets' starting points. [Default: 1]
  std::uint64_t seed = 1;
  /// Steps (cells travelled) before a droplet evaporates for good. [Range: 1..1000] [Default: 30]
  int lifetime = 30;
  /// How much of its direction a droplet keeps against the slope. [Range: 0..1] [Default: 0.05]
  double inertia = 0.05;
  /// Sediment capacity per unit of drop x speed x water. [Range: >= 0] [Default: 4]
  double capacity = 4.0;
  /// Capacity on flat ground, so droplets still carry something. [Range: >= 0] [Default: 0.01]
  double min_capacity = 0.01;
  /// Fraction of the free capacity taken up per step. [Range: 0..1] [Default: 0.3]
  double erosion_rate = 0.3;
  /// Fraction of the surplus load dropped per step. [Range: 0..1] [Default: 0.3]
  double deposition_rate = 0.3;
  /// Fraction of the water lost per step. [Range: 0..1] [Default: 0.01]
  double evaporation = 0.01;
  /// Acceleration per unit of drop. [Range: > 0] [Default: 4]
  double gravity = 4.0;

  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<DropletParams>& parameter_table(const DropletParams*);

/// Droplets per round: each round's droplets are sorted into tiles by where they start.
inline constexpr int droplet_round = 1 << 16;

/// The height unit droplets work in, in metres per metre of distance: about a hundred times the
/// terrain's typical slope (at least 1), so that a droplet's step drops about a hundredth of a
/// unit, as Beyer's constants assume.
double droplet_height_scale(const Heightfield& heights);
/// The same from the exact sum of the height steps |h(x + 1, y) - h(x, y)| (height_step) over
/// every 7th row (y = 0, 7, ...; x = 0 .. width - 2), and their count.
double droplet_height_scale(const ExactSum& steps, std::int64_t count, double cell_size_m);
inline double height_step(float east, float here) {
  return std::abs(static_cast<double>(east) - here);
}

/// The heights droplets run on: world cell (x, y) at z[offset(x, y)], in a world of width x
/// height samples (the whole grid, or a window of it around a tile of droplets).
struct DropletGround {
  float* z;
  std::ptrdiff_t stride;
  int x0, y0;
  int width, height;
  std::ptrdiff_t offset(int x, int y) const { return static_cast<std::ptrdiff_t>(y - y0) * stride + (x - x0); }
};

/// How erode_droplets cuts the map: square tiles wider than twice a droplet's reach (its
/// lifetime, and the cells around its last position), so that tiles of one colour of a 2x2
/// checkerboard never touch the same cell.
struct DropletTiles {
  DropletTiles(const DropletParams& params, int width, int height)
      : reach(params.lifetime + 2),
        tile(std::max(64, 2 * reach + 2)),
        tiles_x((width + tile - 1) / tile),
        tiles_y((height + tile - 1) / tile) {}
  int reach, tile, tiles_x, tiles_y;
};

/// Where droplet `index` starts: a hash of (seed, index), in cells.
std::pair<float, float> droplet_start(int width, int height, const DropletParams& p, std::uint64_t index);

/// Runs one droplet from (x, y) over `ground`, eroding and depositing as it goes, until it dries
/// up, leaves the map or reaches `base_level` (in the heights' own unit). `cell_size`: the
/// height unit (droplet_height_scale) times the cell size.
void run_droplet(const DropletGround& ground, float cell_size, const DropletParams& p, float base_level, float x, float y);

/// The number of droplets `params` runs on a grid of `cells` cells.
std::int64_t droplet_count(const DropletParams& params, std::size_t cells);

/// droplet_count droplets over `heights`. A droplet that reaches `base_level_m` (the sea, a
/// plain around a mountain) is gone with its load, as water reaching base level carries its
/// sediment away. Same bytes with any number of threads.
Heightfield erode_droplets(const Heightfield& heights, const DropletParams& params, const Context& context = quiet_context(),
                           std::optional<double> base_level_m = std::nullopt);

}  // namespace sansui::water
