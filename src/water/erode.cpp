// The default erosion chain (see erode.hpp).
#include "water/erode.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/parallel.hpp"
#include "water/edge_margin.hpp"
#include "water/erode_cells.hpp"
#include "water/erosion_chain.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

/// Model 1: each stage over the whole heightfield in turn.
ErosionResult erode_in_sequence(const Heightfield& heights, const ErosionChainParams& params, const Context& context) {
  ErosionResult result = erode_stream_power(heights, params.fluvial, nullptr, context);
  if (params.thermal.iterations > 0) result.heights = erode_thermal(result.heights, params.thermal, context);
  if (droplet_count(params.droplets, heights.size()) > 0) result.heights = erode_droplets(result.heights, params.droplets, context);
  return result;
}

/// The map's edge follows the land inside it (follow_inner, erode_cells.hpp): the top and bottom
/// rows, then the left and right columns.
void follow_inner_land(Heightfield& h, double base_level) {
  const int width = h.width(), height = h.height();
  if (width < 3 || height < 3) return;
  for (int x = 0; x < width; ++x) follow_inner(h(x, 0), h(x, 1), base_level), follow_inner(h(x, height - 1), h(x, height - 2), base_level);
  for (int y = 0; y < height; ++y) follow_inner(h(0, y), h(1, y), base_level), follow_inner(h(width - 1, y), h(width - 2, y), base_level);
}

/// No cell goes below its settled_floor (erode_cells.hpp).
void stay_above_base_level(Heightfield& heights, const Heightfield& settled, double base_level) {
  parallel_for(0, heights.height(), [&](int y) {
    for (int x = 0; x < heights.width(); ++x) heights(x, y) = std::max(heights(x, y), settled_floor(settled(x, y), base_level));
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

/// `detail` less the fine detail `heights` have now: what an erosion took of it.
void subtract_fine_detail(Grid<float>& detail, const Heightfield& heights) {
  const Grid<float> left = fine_detail(heights, detail_levels);
  for (std::size_t i = 0; i < detail.size(); ++i) detail.values()[i] -= left.values()[i];
}

/// Puts `detail`, the fine detail of the heights before the erosion, back on `eroded`: all of it
/// (model 2), or what is gone of it (`lost_only`, model 3; see erode.hpp). The weight of a cell:
/// erode_cells.hpp, whose fades scale with the detail's size before.
void put_back_detail(Heightfield& eroded, const Grid<float>& incised_m, Grid<float> detail, double weight, double base_level,
                     bool lost_only) {
  const double size = rms_above(detail, eroded, base_level);
  if (lost_only) subtract_fine_detail(detail, eroded);
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

/// The whole grid as the chain's surface (erosion_chain.hpp): `result`'s heights and maps,
/// eroded in place from `before`.
class WholeSurface final : public ErosionSurface {
 public:
  WholeSurface(const Heightfield& before, ErosionResult& result, const FlowRouting* routing_of_heights)
      : before_(before), result_(result), routing_(routing_of_heights) {}

  std::size_t cells() const override { return before_.size(); }
  double cell_size_m() const override { return before_.cell_size_m; }

  double response_time_yr(const StreamPowerParams& params, const Context& context) override {
    const double tau = water::response_time_yr(result_.heights, params, context, &workspace_, routing_);
    // It routes into the workspace unless it was given a routing (or nothing erodes).
    if (routing_ == nullptr && workspace_.flow.stack.size() == result_.heights.size()) routing_ = &workspace_.flow;
    return tau;
  }
  ErosionBudget stream_power_step(const StreamPowerParams& params, const Context& context) override {
    const FlowRouting* routing = std::exchange(routing_, nullptr);  // of these heights until the step changes them
    return water::stream_power_step(result_.heights, params, nullptr, result_.eroded_m, result_.deposited_m, workspace_, context, routing);
  }
  void follow_inner_land(double base_level) override { water::follow_inner_land(result_.heights, base_level); }
  void thermal(const ThermalParams& params, const Context& context) override {
    result_.heights = erode_thermal(result_.heights, params, context);
  }
  void settle() override { settled_ = result_.heights; }
  void droplets(const DropletParams& params, std::optional<double> base_level_m, const Context& context) override {
    result_.heights = erode_droplets(result_.heights, params, context, base_level_m);
  }
  void keep_detail(double weight, double base_level, bool lost_only) override {
    put_back_detail(result_.heights, result_.eroded_m, fine_detail(before_, detail_levels), weight, base_level, lost_only);
  }
  void stay_above_settled(double base_level) override { stay_above_base_level(result_.heights, settled_, base_level); }

 private:
  const Heightfield& before_;
  ErosionResult& result_;
  const FlowRouting* routing_;  // the routing of the present heights, while known
  StreamPowerWorkspace workspace_;
  Heightfield settled_;
};

/// Model 4 (see erode.hpp): model 3 on the map with a margin of land past its edges
/// (edge_margin.hpp), cut back to the map. Its budget counts the margin's volumes too.
ErosionResult erode_past_edges(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage,
                               const Context& context);

/// Models 2 and 3 (see erode.hpp).
ErosionResult erode_as_landscape(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage, int model,
                                 const FlowRouting* routing_of_heights, const Context& context) {
  if (model >= 4) return erode_past_edges(heights, params, stage, context);
  ErosionResult result{
      heights, Grid<float>(heights.width(), heights.height(), 0.0f), Grid<float>(heights.width(), heights.height(), 0.0f), {}};
  copy_placement(result.eroded_m, heights);
  copy_placement(result.deposited_m, heights);
  WholeSurface surface(heights, result, routing_of_heights);
  result.budget = run_erosion_chain(surface, params, stage, model, context);
  return result;
}

ErosionResult erode_past_edges(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage,
                               const Context& context) {
  // One margin on every side, as a tiled world's (TileCut::margin).
  const int m = edge_margin(std::min(heights.width(), heights.height()));
  // The routing of the map alone is not the routing of the wider land: it routes anew.
  const ErosionResult wide = erode_as_landscape(extended_past_edges(heights, {m, m, m, m}), params, stage, 3, nullptr, context);
  return {inside_margins(wide.heights, m, m), inside_margins(wide.eroded_m, m, m), inside_margins(wide.deposited_m, m, m), wide.budget};
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

ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage, const Context& context,
                    int model, const FlowRouting* routing_of_heights) {
  params.fluvial.validate();
  params.thermal.validate();
  params.droplets.validate();
  if (model != 1) return erode_as_landscape(heights, params, stage, model, routing_of_heights, context);
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
