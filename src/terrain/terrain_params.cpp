// Parameter tables of the terrain subsystem (see core/params.hpp).
#include <cmath>

#include "core/params.hpp"
#include "terrain/midpoint.hpp"
#include "terrain/stage_filter.hpp"

namespace sansui::terrain {

const params::Table<MidpointParams>& parameter_table(const MidpointParams*) {
  using P = MidpointParams;
  static const auto table =
      params::Table<P>("midpoint", "Fractal terrain: midpoint displacement with successive random additions (Oka et al. 1997, Sec. 4.1.1)")
          .add(params::field("seed", &P::seed).doc("Random seed: the same seed gives the same terrain, byte for byte").grouped("terrain"))
          .add(params::field("hurst", &P::hurst)
                   .above(0)
                   .at_most(1)
                   .no_unit()
                   .doc("Hurst exponent H: larger is smoother (fractal dimension 3 - H)")
                   .grouped("terrain"))
          .add(params::field("sigma", &P::sigma_m)
                   .at_most(1e5)
                   .at_least(0)
                   .units("m")
                   .unset("250 m x (the world's extent / 10,240 m)^hurst")
                   .doc("Standard deviation of the corner heights, the first displacement scale. Unset, it follows the world's "
                        "extent (size x cell), so the default land has the slopes of real hill land at any cell size "
                        "(docs/terrain.md)")
                   .grouped("terrain"))
          .add(params::field("additions", &P::additions)
                   .doc("Successive random additions: existing points are displaced at every half-step too")
                   .grouped("terrain"))
          .add(params::field("land_fraction", &P::land_fraction)
                   .above(0)
                   .below(1)
                   .no_unit()
                   .doc("Share of the whole world above the world's sea level: the heights are shifted so, whatever the seed")
                   .grouped("terrain"))
          .add(params::field("paper_sea_level", &P::paper_sea_level)
                   .doc("Keep the heights as generated, sea level at the generator's zero (the paper): land from none to all by seed")
                   .grouped("terrain"));
  return table;
}

void MidpointParams::validate() const {
  params::validate(*this);
}

double MidpointParams::sigma() const {
  return sigma_m.value_or(default_sigma_m);
}

double default_sigma_for_extent(double extent_m, double hurst) {
  return default_sigma_m * std::pow(extent_m / default_sigma_extent_m, hurst);
}

const params::Table<StageFilterParams>& parameter_table(const StageFilterParams*) {
  using P = StageFilterParams;
  static const auto table =
      params::Table<P>(
          "stage", "Geomorphic stage filter (W. M. Davis's cycle of erosion, as Oka et al. 1997 use it): reshapes heights above sea level")
          .add(params::choice("stage", &P::stage, stage_choices())
                   .doc("Stage: original x^0.1, young x^0.5, mature x (no change), old, peneplain; x = height above sea level / unit")
                   .grouped("stage"))
          .add(params::field("paper_exact", &P::paper_exact)
                   .doc("Use the paper's printed old/peneplain filters, which jump at x = 1")
                   .grouped("stage"))
          .add(params::field("sea_level", &P::sea_level_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .doc("Sea level: only heights above it are reshaped")
                   .grouped("stage"))
          .add(params::field("height_unit", &P::sigma_m)
                   .at_most(1e5)
                   .above(0)
                   .units("m")
                   .unset("the midpoint source's sigma; other sources: the standard deviation of the heights")
                   .doc("x is the height above sea level in units of this")
                   .grouped("stage"));
  return table;
}

}  // namespace sansui::terrain
