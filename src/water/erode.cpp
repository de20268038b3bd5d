// The default erosion chain (see erode.hpp).
#include "water/erode.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"
#include "water/erode_cells.hpp"
#include "water/neighbours.hpp"

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

/// Seconds of each part of model 2 in order: the response time's routing (needs_response_time),
/// the steps (each with its thermal share), then droplets and the kept detail.
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

/// Model 1: each stage over the whole heightfield in turn.
ErosionResult erode_in_sequence(const Heightfield& heights, const ErosionChainParams& params, const Context& context) {
  ErosionResult result = erode_stream_power(heights, params.fluvial, nullptr, context);
  if (params.thermal.iterations > 0) result.heights = erode_thermal(result.heights, params.thermal, context);
  if (droplet_count(params.droplets, heights.size()) > 0) result.heights = erode_droplets(result.heights, params.droplets, context);
  return result;
}

/// The map's edge follows the land inside it: an edge cell above base level is lowered to its
/// inward neighbour when that is lower (never below base level). Water leaves the map there, so
/// the edge must wear down with the land it drains; as fixed base level it would stand as a
/// wall around a worn-down plain.
void follow_inner_land(Heightfield& h, double base_level) {
  const int width = h.width(), height = h.height();
  if (width < 3 || height < 3) return;
  const auto follow = [base_level](float& edge, float inner) {
    if (static_cast<double>(edge) > base_level && inner < edge) edge = static_cast<float>(std::max<double>(inner, base_level));
  };
  for (int x = 0; x < width; ++x) follow(h(x, 0), h(x, 1)), follow(h(x, height - 1), h(x, height - 2));
  for (int y = 0; y < height; ++y) follow(h(0, y), h(1, y)), follow(h(width - 1, y), h(width - 2, y));
}

/// No cell goes below base level that was not below it `before`: droplets change the four cells
/// around them, so one on the foot of a slope would dig into the sea or the plain beside it, and
/// roughness put back on the lowest land would dip under base level.
void stay_above_base_level(Heightfield& heights, const Heightfield& before, double base_level) {
  parallel_for(0, heights.height(), [&](int y) {
    for (int x = 0; x < heights.width(); ++x) {
      const auto floor = static_cast<float>(std::min<double>(before(x, y), base_level));
      heights(x, y) = std::max(heights(x, y), floor);
    }
  });
}

/// Root mean square of `detail` over the cells of `heights` above `base_level`. An exact sum
/// (core/exact_sum.hpp): a tiled world sums the same terms in another order.
double rms_above(const Grid<float>& detail, const Heightfield& heights, double base_level) {
  std::vector<ExactSum> sums(static_cast<std::size_t>(heights.height()));
  std::vector<std::int64_t> counts(sums.size(), 0);
  parallel_for(0, heights.height(), [&](int y) {
    for (int x = 0; x < heights.width(); ++x)
      if (static_cast<double>(heights(x, y)) > base_level)
        sums[static_cast<std::size_t>(y)].add(static_cast<double>(detail(x, y)) * detail(x, y)), ++counts[static_cast<std::size_t>(y)];
  });
  ExactSum sum;
  std::int64_t count = 0;
  for (std::size_t y = 0; y < sums.size(); ++y) sum.add(sums[y]), count += counts[y];
  return root_mean_square(sum, count);
}

/// Puts `detail` back on `eroded` (model 2, see erode.hpp; the weight of a cell: erode_cells.hpp).
void keep_detail(Heightfield& eroded, const Grid<float>& incised_m, const Grid<float>& detail, double weight, double base_level) {
  const double size = rms_above(detail, eroded, base_level);
  if (size <= 0.0 || weight <= 0.0) return;
  const Heightfield before = eroded;
  parallel_for(0, eroded.height(), [&](int y) {
    for (int x = 0; x < eroded.width(); ++x) {
      const double gradient =
          gradient_at([&](int gx, int gy) { return before(gx, gy); }, x, y, before.width(), before.height(), before.cell_size_m);
      eroded(x, y) += kept_detail(weight, size, incised_m(x, y), detail(x, y), static_cast<double>(before(x, y)) - base_level, gradient);
    }
  });
}

/// Model 2 (see erode.hpp).
ErosionResult erode_as_landscape(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage,
                                 const FlowRouting* routing_of_heights, const Context& context) {
  const int steps = params.fluvial.steps;
  const double base_level = params.fluvial.sea_level_m.value_or(-std::numeric_limits<double>::infinity());
  ErosionResult result{
      heights, Grid<float>(heights.width(), heights.height(), 0.0f), Grid<float>(heights.width(), heights.height(), 0.0f), {}};
  copy_placement(result.eroded_m, heights);
  copy_placement(result.deposited_m, heights);
  const ErosionProgress progress(context, landscape_parts(heights.size(), params, stage.has_value()));
  // The heights are routed once (into the workspace, unless their routing is given): the
  // response time and the first step take that routing.
  StreamPowerWorkspace workspace;
  StreamPowerParams fluvial = params.fluvial;
  const bool response_time = needs_response_time(params, stage.has_value());
  if (response_time && stage)
    fluvial = params_for_stage(heights, fluvial, *stage, progress.part(0), 2, &workspace, routing_of_heights);
  else if (response_time)
    fluvial.diffusivity_m2_per_yr = resolved_diffusivity(
        fluvial, heights.cell_size_m, response_time_yr(heights, fluvial, progress.part(0), &workspace, routing_of_heights));
  const FlowRouting* first_routing = routing_of_heights != nullptr ? routing_of_heights : response_time ? &workspace.flow : nullptr;
  ThermalParams thermal = params.thermal;
  for (int step = 0; step < steps; ++step) {
    context.check_cancelled();
    const Context part = progress.part(1 + static_cast<std::size_t>(step));
    result.budget += stream_power_step(result.heights, fluvial, nullptr, result.eroded_m, result.deposited_m, workspace, part,
                                       step == 0 ? first_routing : nullptr);
    follow_inner_land(result.heights, base_level);
    thermal.iterations = thermal_share(params.thermal.iterations, step, steps);
    if (thermal.iterations > 0) result.heights = erode_thermal(result.heights, thermal);
    part.report("step", 1.0);
  }
  if (steps == 0 && params.thermal.iterations > 0) result.heights = erode_thermal(result.heights, params.thermal, progress.part(1));
  const Context last = progress.part(steps == 0 ? 2 : 1 + static_cast<std::size_t>(steps));
  const bool droplets = droplet_count(params.droplets, heights.size()) > 0;
  if (!droplets && params.keep_detail <= 0.0) return result;
  const Heightfield settled = result.heights;
  if (droplets) result.heights = erode_droplets(result.heights, params.droplets, last, params.fluvial.sea_level_m);
  if (params.keep_detail > 0.0)
    keep_detail(result.heights, result.eroded_m, fine_detail(heights, detail_levels), params.keep_detail, base_level);
  stay_above_base_level(result.heights, settled, base_level);
  last.report("detail", 1.0);
  return result;
}

}  // namespace

Grid<float> fine_detail(const Heightfield& heights, int levels) {
  const int width = heights.width(), height = heights.height(), step = 1 << levels;
  Grid<float> detail(width, height, 0.0f);
  copy_placement(detail, heights);
  if (width <= step || height <= step) return detail;
  parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x)
      detail(x, y) = fine_detail_at([&](int fx, int fy) { return heights(fx, fy); }, x, y, width, height, levels);
  });
  return detail;
}

double estimated_routing_seconds(std::size_t cells) {
  return raw_routing_steps * static_cast<double>(cells) / step_cells_per_s;
}

double estimated_erosion_seconds(std::size_t cells, const ErosionChainParams& params, bool staged) {
  double total = 0.0;
  for (double part : landscape_parts(cells, params, staged)) total += part;
  return total;
}

ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage, const Context& context,
                    int model, const FlowRouting* routing_of_heights) {
  params.fluvial.validate();
  params.thermal.validate();
  params.droplets.validate();
  if (model != 1) return erode_as_landscape(heights, params, stage, routing_of_heights, context);
  if (!stage) return erode_in_sequence(heights, params, context);
  // Model 1 routes anew in its first step: the response time's routing is a part of its own.
  const double routing_part =
      estimated_routing_seconds(heights.size()) / std::max(estimated_erosion_seconds(heights.size(), params, true), 1e-9);
  ErosionChainParams staged = params;
  staged.fluvial = params_for_stage(heights, params.fluvial, *stage, part_of(context, "erosion", 0.0, routing_part), 1);
  return erode_in_sequence(heights, staged, part_of(context, "erosion", routing_part, 1.0));
}

ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, const Context& context, int model) {
  return erode(heights, params, std::nullopt, context, model);
}

}  // namespace sansui::water
