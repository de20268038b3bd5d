// The erosion chain's one order (see erosion_chain.hpp), and its time estimates.
#include "water/erosion_chain.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "water/erode_cells.hpp"

namespace sansui::water {
namespace {

/// Rates on the reference machine (2 cores, Release), measured with bench_water and whole runs
/// at 4097 x 4097 and 8193 x 8193 (docs/erosion.md, Speed). A step on eroded land; routing the raw
/// fractal terrain (the response time's) costs 1.5 steps, the step that reuses it 0.75.
constexpr double step_cells_per_s = 13e6;
constexpr double raw_routing_steps = 1.5;
constexpr double reusing_step_steps = 0.75;
constexpr double thermal_cell_iterations_per_s = 1e8;
constexpr double droplets_per_s = 0.9e6;

/// Whether model 2 finds the response time (a stage's time step, or an unset diffusivity): it
/// routes the heights first, and the first step takes that routing.
bool needs_response_time(const ErosionChainParams& params, bool staged) {
  return params.fluvial.steps > 0 && (staged || !params.fluvial.diffusivity_m2_per_yr);
}

/// Estimated seconds of each part of model 2 on `cells` cells, in order: the response time's
/// routing, the steps (each with its thermal share), then droplets and the kept detail.
std::vector<double> landscape_parts(std::size_t cells, const ErosionChainParams& params, bool staged) {
  const auto n = static_cast<double>(cells);
  const double step_s = n / step_cells_per_s;
  std::vector<double> parts;
  const int steps = params.fluvial.steps;
  const bool response_time = needs_response_time(params, staged);
  parts.push_back(response_time ? raw_routing_steps * step_s : 0.0);
  for (int step = 0; step < steps; ++step)
    parts.push_back((step == 0 && response_time ? reusing_step_steps : 1.0) * step_s +
                    n * thermal_share(params.thermal.iterations, step, steps) / thermal_cell_iterations_per_s);
  if (steps == 0) parts.push_back(n * params.thermal.iterations / thermal_cell_iterations_per_s);
  parts.push_back(static_cast<double>(droplet_count(params.droplets, cells)) / droplets_per_s + n / 2e8);
  return parts;
}

/// Contexts for the parts of an erosion, each reporting its share of one stage, "erosion", in
/// proportion to its estimated time.
class ErosionProgress {
 public:
  ErosionProgress(const Context& whole, const std::vector<double>& seconds) : whole_(whole), before_{0.0} {
    for (double s : seconds) before_.push_back(before_.back() + s);
  }
  Context part(std::size_t k) const {
    const double total = before_.back() > 0.0 ? before_.back() : 1.0;
    return part_of(whole_, "erosion", before_[k] / total, before_[k + 1] / total);
  }

 private:
  const Context& whole_;
  std::vector<double> before_;
};

}  // namespace

double estimated_routing_seconds(std::size_t cells) {
  return raw_routing_steps * static_cast<double>(cells) / step_cells_per_s;
}

double estimated_erosion_seconds(std::size_t cells, const ErosionChainParams& params, bool staged) {
  double total = 0.0;
  for (double part : landscape_parts(cells, params, staged)) total += part;
  return total;
}

ErosionBudget run_erosion_chain(ErosionSurface& surface, ErosionChainParams params, std::optional<ErosionStage> stage, int model,
                                const Context& context) {
  const int steps = params.fluvial.steps;
  const ErosionProgress progress(context, landscape_parts(surface.cells(), params, stage.has_value()));
  StreamPowerParams& fluvial = params.fluvial;
  if (needs_response_time(params, stage.has_value()))
    fluvial = params_for_response_time(fluvial, stage, 2, surface.response_time_yr(fluvial, progress.part(0)), surface.cell_size_m());
  const double base_level = fluvial.sea_level_m.value_or(-std::numeric_limits<double>::infinity());
  ErosionBudget budget;
  ThermalParams thermal = params.thermal;
  for (int step = 0; step < steps; ++step) {
    context.check_cancelled();
    const Context part = progress.part(1 + static_cast<std::size_t>(step));
    budget += surface.stream_power_step(fluvial, part);
    surface.follow_inner_land(base_level);
    thermal.iterations = thermal_share(params.thermal.iterations, step, steps);
    if (thermal.iterations > 0) surface.thermal(thermal, quiet_context());
    part.report("step", 1.0);
  }
  if (steps == 0 && params.thermal.iterations > 0) surface.thermal(params.thermal, progress.part(1));
  const Context last = progress.part(steps == 0 ? 2 : 1 + static_cast<std::size_t>(steps));
  const bool droplets = droplet_count(params.droplets, surface.cells()) > 0;
  if (!droplets && params.keep_detail <= 0.0) return budget;
  surface.settle();
  if (droplets) surface.droplets(params.droplets, fluvial.sea_level_m, last);
  if (params.keep_detail > 0.0) surface.keep_detail(params.keep_detail, base_level, model >= 3);
  surface.stay_above_settled(base_level);
  last.report("detail", 1.0);
  return budget;
}

}  // namespace sansui::water
