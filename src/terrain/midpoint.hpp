// Fractal terrain by midpoint displacement with successive random additions
// (Peitgen & Saupe, "The Science of Fractal Images", 1988, MidPointFM2D with addition), as
// used by Oka, Shimada, Shiono, Miyagaki, "Parametric automatic generation of natural scenery"
// (1997; seeds/003, Sec. 4.1.1; SPEC 3.1).
//
// Every random number is a pure function of (seed, stage, operation, the point's index at that
// stage), so any window of the world, at any level of detail, can be computed on its own and is
// bit for bit the same as that window of the whole world: that gives seamless tiles, previews
// that equal the final terrain, and identical results for any number of threads.
#pragma once

#include <cstdint>
#include <optional>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "core/rect.hpp"

namespace sansui::terrain {

/// Table: terrain_params.cpp (section [midpoint]).
struct MidpointParams {
  /// Random seed: the same seed gives the same terrain, byte for byte. [Default: 1]
  std::uint64_t seed = 1;
  /// Hurst exponent: larger is smoother (fractal dimension 3 - H). [Range: 0 < H <= 1]
  /// [Default: 0.7, whose eroded land has the spectral exponent of real land (water/landform.hpp;
  /// 0.8 measures 3.4-3.75 before erosion and up to 3.9 after); recipes of version 1: 0.8]
  double hurst = 0.7;
  /// Standard deviation of the corner heights, the first displacement scale. [Units: m] [Range: >= 0]
  /// [Default: unset: default_sigma_m here; a recipe's world scales it with its extent
  /// (scene::world_midpoint); recipes of version 1: 400]
  std::optional<double> sigma_m;
  /// Successive random additions: displace existing points at every half-step too. [Default: true]
  bool additions = true;
  /// Share of the whole world above sea level (0 m): sources shift the heights by
  /// sea_level_offset(), so that every seed gives land. [Range: 0 < f < 1] [Default: 0.7]
  double land_fraction = 0.7;
  /// Keep the heights as generated: sea level at the generator's zero, as in the paper, where the
  /// share of land goes from none to all with the seed (seed 7 of 1025 x 1025 is 99.7 % sea).
  /// [Default: false; recipes of version 1: true]
  bool paper_sea_level = false;

  /// Throws InputError naming the first bad value.
  void validate() const;
  /// sigma_m, or default_sigma_m when unset.
  double sigma() const;
};
const params::Table<MidpointParams>& parameter_table(const MidpointParams*);

/// The corner heights' standard deviation of a world 10,240 m across (1025 samples 10 m apart)
/// when none is given: at H 0.7 its eroded land has the median slope of real hill land. [Units: m]
inline constexpr double default_sigma_m = 250.0;
/// The extent default_sigma_m is for. [Units: m]
inline constexpr double default_sigma_extent_m = 10240.0;

/// The relief a world `extent_m` across gets by default: default_sigma_m x (extent /
/// default_sigma_extent_m)^H, so that every world is a window of the same self-affine surface (a
/// fractal's relief grows with its extent as extent^H) and the slope at one cell falls only as
/// cell^(H - 1) with coarser cells, as real DEMs' slopes do. [Units: m]
double default_sigma_for_extent(double extent_m, double hurst);

/// Largest world: 2^20 + 1 samples per side (generated as tiles; a single grid stops at 16385).
inline constexpr int max_world_levels = 20;

/// Which samples of which world to generate. The world has 2^world_levels + 1 samples per side;
/// the output has every 2^lod-th of them, and `window` is a rectangle of the output's samples
/// (half-open, in units of 2^lod world samples). Preview equals final: a window at lod K holds
/// exactly the values the full-resolution world has at those points.
struct WorldWindow {
  int world_levels = 10;  ///< [Range: 0..20]
  int lod = 0;            ///< [Range: 0..world_levels]
  Rect window;            ///< [Range: inside 0 .. 2^(world_levels - lod) inclusive]

  int output_samples_per_side() const { return (1 << (world_levels - lod)) + 1; }
};

/// The window of the world as a heightfield in metres (cell size 1, origin 0: callers set them).
/// Uses all threads of the parallel seam (core/parallel.hpp); the bytes do not depend on how many.
Heightfield generate_midpoint(const MidpointParams& params, const WorldWindow& where, const Context& context = quiet_context());

/// The window of a world refined from a given coarse version of it instead of from level 0:
/// `coarse` holds every sample of the world at a coarser level of detail (2^k + 1 per side, k at
/// most world_levels - where.lod), with its final values, e.g. after erosion. Finer stages add
/// the same displacements as generate_midpoint, so windows and tiles refined from the same
/// coarse world join bit for bit, and at the coarse points the result equals `coarse` (up to
/// float rounding). `detail` (0..1) scales the finer stages' displacements: eroded valleys are
/// gentler than the fractal's fine relief, which would send their rivers astray at full size.
Heightfield refine_midpoint(const MidpointParams& params, const WorldWindow& where, const Heightfield& coarse, double detail = 1.0,
                            const Context& context = quiet_context());

/// A whole square world of `size` = 2^k + 1 samples per side.
Heightfield generate_midpoint(const MidpointParams& params, int size, const Context& context = quiet_context());

/// k for size = 2^k + 1, or -1 if size has not that form.
int levels_for_size(long long size);

/// The height that sea level (0 m) takes in the generator's own heights, so that
/// params.land_fraction of the world lies above it: the (1 - land_fraction) quantile of the
/// world's samples at a level of detail of at most 257 per side, which every tile, window and
/// preview of the world sees alike. Sources subtract it. 0 when params.paper_sea_level.
float sea_level_offset(const MidpointParams& params, int world_levels, const Context& context = quiet_context());

}  // namespace sansui::terrain
