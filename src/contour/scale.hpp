// The scale of a seed contour, for defaults and for refusing runaway work before it starts
// (issue 17 item 1):
//   inradius     the largest distance from a point inside the seed to the seed (a grid search:
//                the radius of the seed's largest inscribed disc, within 1 % of its extent);
//                shrinking the seed by d per level leaves nothing after about inradius / d levels;
//   target relief R(r) = 150 m * (r / 500 m)^0.65, at most 5000 m: a realistic relief for a
//                footprint of inradius r (150 m for a 1 km hill, about 670 m for a 10 km massif,
//                about 3 km for a 100 km island), the power law of relief against size of real
//                ranges, with a mean slope falling from 0.3 to 0.06 as they grow;
//   derived d    = r * dz / R(r): the offset whose inward levels reach R at dz per level;
//   estimate     levels inward about r / d (the summit's last contour is gone at r), outward as
//                asked; work about levels x vertices, in seconds on the project's 2-core machine.
#pragma once

#include "contour/generate.hpp"
#include "contour/geometry.hpp"
#include "core/budget.hpp"

namespace sansui::contour {

/// Radius of the largest disc inside `ring` (counter-clockwise, simple). [Units: m]
double inradius(const Ring& ring);

/// The realistic relief for a seed of inradius r (see above). [Units: m]
double target_relief_m(double inradius_m);

/// d derived from the seed's size when no offset is given: inradius * dz / target relief. [Units: m]
double derived_offset_m(const Ring& seed, double interval_m);

struct WorkEstimate {
  double inward_levels = 0.0;   ///< about inradius / d
  double outward_levels = 0.0;  ///< as asked (outward or base)
  double levels = 0.0;          ///< both
  double vertices = 0.0;        ///< vertices of one contour, about
  double seconds = 0.0;         ///< on the project's 2-core machine, about
};

/// Estimates the levels and the time of generate_contours(seed, params) without generating.
WorkEstimate estimate_work(const Ring& seed, const GenerationParams& params);

/// Refuse generations estimated above this many levels or seconds unless `force`.
inline constexpr double level_limit = 3000.0;
inline constexpr double seconds_limit = budget::work_limit_s;  // the one work limit (core/budget.hpp)

/// Throws InputError with the estimate and the way out (--offset, --interval, --force) if the
/// estimate is over a limit and params.force is not set.
void check_work(const WorkEstimate& estimate, const GenerationParams& params);

}  // namespace sansui::contour
