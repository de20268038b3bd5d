// The order of the default erosion chain (model 2, erode.hpp), written once. A whole grid
// (erode.cpp) and a world cut into tiles (tiled_erosion.cpp) are two surfaces it runs on. Each
// surface gives the chain's operations with the same per-cell arithmetic (erode_cells.hpp), so
// the two give the same bytes because there is one order, not two copies kept in step.
#pragma once

#include <cstddef>
#include <optional>

#include "core/context.hpp"
#include "water/erode.hpp"

namespace sansui::water {

/// The operations the chain runs on a surface, in run_erosion_chain's order. On a tiled surface
/// every call is collective.
class ErosionSurface {
 public:
  virtual ~ErosionSurface() = default;
  virtual std::size_t cells() const = 0;
  virtual double cell_size_m() const = 0;
  /// response_time_yr (stream_power.hpp) of the present heights. The routing it makes may serve
  /// the next stream-power step, whose heights are the same.
  virtual double response_time_yr(const StreamPowerParams& params, const Context& context) = 0;
  /// One stream_power_step with params' diffusivity set.
  virtual ErosionBudget stream_power_step(const StreamPowerParams& params, const Context& context) = 0;
  /// The map's edge follows the land inside it (follow_inner, erode_cells.hpp).
  virtual void follow_inner_land(double base_level) = 0;
  virtual void thermal(const ThermalParams& params, const Context& context) = 0;
  /// Keeps the present heights as the floor of stay_above_settled.
  virtual void settle() = 0;
  virtual void droplets(const DropletParams& params, std::optional<double> base_level_m, const Context& context) = 0;
  /// Puts back `weight` of the fine detail the heights had before the chain (erode.hpp): all of
  /// it (model 2), or what the chain took of it (`lost_only`, model 3).
  virtual void keep_detail(double weight, double base_level, bool lost_only) = 0;
  /// No cell below base level that was not below it when settled (settled_floor).
  virtual void stay_above_settled(double base_level) = 0;
};

/// Model 2 or 3 (`model`, erode.hpp; model 4 is model 3 on a wider surface) on `surface`: the response time where a stage or an unset
/// diffusivity needs it, the stream-power steps each with its share of the thermal iterations, then droplets and the kept detail. Returns
/// the stream power's budget. Progress: "erosion", each part in proportion to its estimated time (the parts estimated_erosion_seconds
/// sums).
ErosionBudget run_erosion_chain(ErosionSurface& surface, ErosionChainParams params, std::optional<ErosionStage> stage, int model,
                                const Context& context);

}  // namespace sansui::water
