// "Does it look like a real mountain?" in numbers (SPEC 1.4; Misawa, Chiba, Saito 1987, seeds/000,
// Sec. 4.2: the power spectra of real and generated contours were found close). Measures one DEM,
// and compares two side by side:
//  - hypsometric curve (Strahler): relative area above each relative height; the difference is
//    the mean absolute gap between the two curves, the integral is the area under a curve;
//  - slope: histogram of slope angles in 1-degree bins; distance = earth mover's distance (deg);
//    spread = 90th / 50th percentile of the gradient;
//  - summits: peaks whose topographic prominence reaches a threshold (union-find from the top);
//  - contour length per level at common levels, and its ratio generated / real;
//  - power spectrum slope of the contour lines (P-type Fourier descriptors, log-log fit) and of
//    the DEM (radially averaged 2-D power spectrum of the Hann-windowed grid, log-log fit).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contour/geometry.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::contour {

/// Table: contour_params.cpp (section [compare]).
struct CompareParams {
  /// Only cells at or above this elevation count. [Units: m] [Default: all]
  std::optional<double> above_m;
  /// Only cells inside this ring count (e.g. the seed contour, so that the real DEM's other hills
  /// stay out). [Default: all]
  std::optional<Ring> inside;
  /// Interval of the compared contour levels. [Units: m] [Range: > 0] [Default: common relief / 20]
  std::optional<double> interval_m;
  /// A summit needs at least this prominence. [Units: m] [Range: > 0] [Default: the interval]
  std::optional<double> prominence_m;
};
const params::Table<CompareParams>& parameter_table(const CompareParams*);

struct DemMeasures {
  std::size_t cells = 0;            ///< cells counted (at or above `above`)
  double min_m = 0.0, max_m = 0.0;  ///< elevation range of those cells
  std::vector<double> hypsometry;   ///< area fraction above relative heights 0, 0.01, ..., 1
  double hypsometric_integral = 0.0;
  std::vector<double> slope_histogram;  ///< fraction of cells per 1-degree slope bin, 0..89
  double mean_slope_deg = 0.0;
  /// 50th and 90th percentile of the gradient (rise over run). Their ratio says how wide the
  /// slope distribution is: one constant contour spacing gives a narrow one (issue 17 item 2).
  double gradient_p50 = 0.0, gradient_p90 = 0.0;
  double slope_spread() const { return gradient_p50 > 0.0 ? gradient_p90 / gradient_p50 : 0.0; }
  int summits = 0;
  std::vector<double> levels_m;          ///< the compared contour levels
  std::vector<double> contour_length_m;  ///< total contour length at each level
  double contour_spectrum_slope = 0.0;   ///< log-log slope of |c(k)|^2 of the contour lines
  double dem_spectrum_slope = 0.0;       ///< log-log slope of the radially averaged power
};

struct Comparison {
  CompareParams params;  ///< with defaults resolved
  DemMeasures real, generated;
  double hypsometric_difference = 0.0;  ///< mean |a_real(h) - a_generated(h)|
  double slope_distance_deg = 0.0;      ///< earth mover's distance of the slope histograms
  double length_ratio = 0.0;            ///< mean over levels of generated / real contour length
};

/// Which cells count: at or above `above_m` and inside `inside`.
struct CellMask {
  std::optional<double> above_m;
  const Ring* inside = nullptr;
};

/// Measures one DEM at the given (resolved) levels.
DemMeasures measure_dem(const Heightfield& dem, const CellMask& mask, const std::vector<double>& levels_m, double prominence_m);

/// Compares `real` and `generated` (any sizes and cell sizes). Throws InputError if they share
/// no elevation range above `above_m`.
Comparison compare_dems(const Heightfield& real, const Heightfield& generated, const CompareParams& params,
                        const Context& context = quiet_context());

/// The comparison as an aligned text table, one metric per line.
std::string comparison_table(const Comparison& comparison);

}  // namespace sansui::contour
