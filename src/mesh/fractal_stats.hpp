// How rough the subdivided surface came out, against the h that was asked for. The detail the
// subdivision added (the final surface minus the coarse input, both rasterised on one grid) is
// a fractional Brownian surface with Hurst exponent h if the method works: its variogram grows
// as lag^(2h), its fractal dimension is 3 - h, and a profile's power spectrum falls as
// f^-(2h + 1). Subtracting the coarse input keeps the drawn mountain's own slopes out of the fit.
#pragma once

#include <optional>

#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

struct FractalMeasurement {
  double measured_h = 0.0;       ///< half the log-log slope of the detail's variogram
  double r_squared = 0.0;        ///< quality of the straight-line fit
  double cell_size_m = 0.0;      ///< grid the surfaces were rasterised on. [Units: m]
  int min_lag = 0, max_lag = 0;  ///< lags fitted, in cells
  double detail_rms_m = 0.0;     ///< root mean square of the detail. [Units: m]

  double measured_dimension() const { return 3.0 - measured_h; }
  /// Slope of a profile's power spectrum (power ~ frequency^-slope) implied by measured_h.
  double implied_spectral_slope() const { return 2.0 * measured_h + 1.0; }
};

/// Measures the detail between `coarse` and `detailed` (made from it by `steps` steps) on a
/// grid with cells coarse_edge_m / 2^steps, the finest edges' length seen from above (coarser
/// if the grid would pass `max_side` samples), over lags from 2 cells up to a sixteenth of the
/// coarse edges. nullopt when the surfaces span too few octaves for a fit (fewer than 7 steps)
/// or cover too little.
///
/// This is the roughness of the heights, what a heightfield tool sees. With displacement
/// along normals on slopes the midpoints also move sideways, by amounts as rough as the
/// heights, which roughens the height profile beyond h (towards h^2 on steep slopes); moved
/// vertically, the heights have Hurst exponent h.
std::optional<FractalMeasurement> measure_fractal(const TriangleMesh& coarse, const TriangleMesh& detailed, double coarse_edge_m, int steps,
                                                  int max_side = 2049);

}  // namespace sansui::mesh
