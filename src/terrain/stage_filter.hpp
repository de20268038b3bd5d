// Geomorphic cycle filters (W. M. Davis's stages of erosion), from Oka et al. 1997 (seeds/003,
// Sec. 4.1.1; SPEC 3.1). Each maps the elevation above sea level, in units of sigma, x >= 0:
//   original x^0.1, young x^0.5, mature x, old x^1.3 (x<1) | x/1.3 (x>=1),
//   peneplain x^3 (x<1) | x/3 (x>=1).
// As printed, old and peneplain jump at x = 1 (down to 1/1.3 and 1/3). The default continuous
// form keeps the paper's slope above 1 but starts it at 1: 1 + (x - 1)/1.3, 1 + (x - 1)/3.
// Points under the sea are left as they are (the filters are defined for x >= 0 and all give
// f(0) = 0, so the coast stays where it was).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::terrain {

enum class Stage { original, young, mature, old, peneplain };

/// "original", "young", "mature", "old", "peneplain"; nullopt for anything else.
std::optional<Stage> stage_from_name(std::string_view name);
std::string_view stage_name(Stage stage);
/// Every stage with its name, original to peneplain (for parameter tables).
std::vector<std::pair<std::string, Stage>> stage_choices();

/// The filter on x = height above sea level / sigma, x >= 0.
double stage_filter(Stage stage, double x, bool paper_exact);

/// Table: terrain_params.cpp (section [[shape]] with step = "stage").
struct StageFilterParams {
  Stage stage = Stage::mature;  ///< [Default: mature, the identity]
  bool paper_exact = false;     ///< the printed, discontinuous old/peneplain. [Default: false]
  double sea_level_m = 0.0;     ///< [Units: m] [Default: 0]
  /// The unit of x. [Units: m] [Range: > 0] [Default: unset: the standard deviation of the
  /// heights (a midpoint source sets its sigma)]
  std::optional<double> sigma_m;
};
const params::Table<StageFilterParams>& parameter_table(const StageFilterParams*);

/// Applies the filter in place to every sample above sea level.
void apply_stage_filter(Heightfield& heights, const StageFilterParams& params);

}  // namespace sansui::terrain
