// Thermal erosion: material above the angle of repose slides to lower neighbours (Musgrave,
// Kolb & Mace, "The synthesis and rendering of eroded fractal terrains", SIGGRAPH 1989; the
// talus rule of Olsen, "Realtime procedural terrain generation", 2004).
//
// Every iteration reads only the previous heights (double-buffered): each cell works out what
// it sends and what its neighbours send it, so rows split between threads give the same bytes.
#pragma once

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::water {

/// Table: water_params.cpp (section [thermal]).
struct ThermalParams {
  /// Angle of repose: steeper slopes shed material. [Units: deg] [Range: 0..89] [Default: 35]
  double talus_angle_deg = 35.0;
  /// Iterations (an erode step of model 2 spreads them over its stream-power steps). [Range:
  /// 0..10000] [Default: 0: off, since it planes hillslopes smoother than real land's (their
  /// spectral exponent rises by about 0.15); recipes of version 1: 20]
  int iterations = 0;
  /// Fraction of the excess a cell sheds per iteration (0.5 levels a pair of cells). [Range: 0 < r <= 0.5] [Default: 0.5]
  double rate = 0.5;

  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<ThermalParams>& parameter_table(const ThermalParams*);

/// params.iterations iterations of thermal erosion. Mass is conserved (up to float rounding):
/// material never leaves the map. Same bytes with any number of threads.
Heightfield erode_thermal(const Heightfield& heights, const ThermalParams& params, const Context& context = quiet_context());

}  // namespace sansui::water
