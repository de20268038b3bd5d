// Measuring how rough a heightfield is: the Hurst exponent from the variogram. For fractional
// Brownian surfaces E[(h(p + r) - h(p))^2] ~ r^(2H), so H is half the slope of log variogram
// against log lag. Used by tests, `sansui compare` and the statistics of generated terrain.
#pragma once

#include "core/grid.hpp"

namespace sansui::terrain {

struct VariogramFit {
  double hurst = 0.0;      ///< half the fitted log-log slope
  double r_squared = 0.0;  ///< quality of the straight-line fit
};

/// Fits lags min_lag, 2*min_lag, ... up to max_lag (samples), along rows and columns.
VariogramFit measure_hurst(ConstGridView<float> heights, int min_lag = 2, int max_lag = 64);

}  // namespace sansui::terrain
