// Measures that tell land from a fractal: how a heightfield compares with real elevation models.
// They are what "real land by default" is checked against (tests, bench/landform), and what a
// user can print for any heightfield.
//
// - Channel / hillslope slope: the median slope of channel cells (D8 drainage area at least 1 % of
//   the map) over the median slope of hillslope cells (area at most 2 cells). Real land: about
//   0.26-0.54 (channels much gentler than the slopes above them); raw fractal terrain 0.6-0.9.
// - Spectral exponent beta: the slope of the radially averaged 2-D power spectrum, P(f) ~ f^-beta,
//   between 3/N and 0.25 cycles per cell (Perron, Kirchner & Dietrich, "Spectral signatures of
//   characteristic spatial scales and nonfractal structure in landscapes", JGR 113, 2008: plane
//   removed, elliptical Hann window). Real land about 1.6-3.6; a midpoint terrain of Hurst
//   exponent H about 2H + 2; erosion that only smooths pushes it above 3.6.
// - Relief and mean slope of the land above sea level, its share of the map, the spread of its
//   curvature and the number of closed depressions (pits).
#pragma once

#include <complex>
#include <optional>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"

namespace sansui::water {

struct LandformMeasures {
  double land_fraction = 0.0;     ///< share of samples above sea level (all when no sea level is given)
  double relief_m = 0.0;          ///< highest sample minus max(lowest sample, sea level). [Units: m]
  double mean_slope = 0.0;        ///< mean gradient of the land samples. [Units: m/m]
  double channel_slope = 0.0;     ///< median gradient of channel cells (drainage area >= 1 % of the map). [Units: m/m]
  double hillslope_slope = 0.0;   ///< median gradient of hillslope cells (drainage area <= 2 cells). [Units: m/m]
  double channel_ratio = 0.0;     ///< channel_slope / hillslope_slope
  double spectral_beta = 0.0;     ///< P(f) ~ f^-beta, 3/N to 0.25 cycles per cell
  double curvature_spread = 0.0;  ///< standard deviation of the Laplacian over land, times the cell size. [Units: m/m]
  long long pits = 0;             ///< interior land samples lower than all eight neighbours
  double edge_distance = 0.0;     ///< edge_slope_distance
};

/// All measures of `heights`. Cells below `sea_level_m` are sea: outlets, and not land. Needs at
/// least 17 x 17 samples (the spectrum's band is empty below).
LandformMeasures measure_landform(const Heightfield& heights, std::optional<double> sea_level_m, const Context& context = quiet_context());

/// The slope of every sample: the gradient by central differences, as the measures above take it
/// at interior samples, one-sided along the map's edge (0 across a side of one sample). Any
/// width x height. [Units: degrees]
Grid<float> slope_degrees(const Heightfield& heights);

/// Whether the map's edges look like the land inside them: the largest two-sample
/// Kolmogorov-Smirnov distance D, over the four edges, between the slopes (slope_degrees) of the
/// land within 5 samples of an edge and those of the land in the 55 samples inside that strip.
/// An edge counts when its strip is at least half land; 0 when none does. The raw default terrain
/// measures 0.01-0.08; eroded with each edge a divide, whose strip stands as a rim, 0.15-0.26.
double edge_slope_distance(const Heightfield& heights, std::optional<double> sea_level_m);

/// The spectral exponent alone (the largest power-of-two square at the grid's centre).
double spectral_exponent(const Heightfield& heights);

/// In-place 2-D FFT (inverse: Eigen's normalised inverse) of an n x n row-major array, n a power
/// of two: rows, then columns.
void fft_2d(std::vector<std::complex<double>>& data, int n, bool inverse = false);

}  // namespace sansui::water
