// The default erosion chain: stream power (valleys at the landscape scale), then thermal
// erosion (screes below steep faces), then droplets (rills and small fans). Each stage can run on
// its own; this is the order a shaping step runs them in, coarse to fine.
#pragma once

#include "core/context.hpp"
#include "core/grid.hpp"
#include "water/droplets.hpp"
#include "water/stream_power.hpp"
#include "water/thermal.hpp"

namespace sansui::water {

struct ErosionChainParams {
  StreamPowerParams fluvial;
  ThermalParams thermal;
  DropletParams droplets;
};

/// The three stages in turn; eroded_m and deposited_m are the stream-power stage's maps, and
/// the budget is its budget. A stage with zero steps, iterations or droplets is skipped.
ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, const Context& context = quiet_context());

}  // namespace sansui::water
