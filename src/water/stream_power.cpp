// Implicit stream-power incision with deposition and hillslope diffusion (see stream_power.hpp).
#include "water/stream_power.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "water/flow.hpp"
#include "water/stream_power_cell.hpp"

namespace sansui::water {
namespace {

/// Refuses (a programmer's error) a routing given that is not of the heights' size: the caller
/// promised the routing of exactly these heights.
void check_routing_of(const FlowRouting& flow, const Heightfield& heights) {
  if (flow.receiver.width() != heights.width() || flow.receiver.height() != heights.height() || flow.stack.size() != heights.size())
    throw std::logic_error("stream power: the routing given is not of these heights (another size)");
}

/// Sum of a grid in double, each row summed in order on its own and then the rows in row order:
/// the same bytes with any number of threads. Four rows are summed side by side, so the four
/// chains of additions overlap in the processor instead of waiting on each other.
double volume_sum(const Heightfield& heights) {
  const int width = heights.width(), height = heights.height();
  std::vector<double> rows(static_cast<std::size_t>(height), 0.0);
  constexpr int together = 4;
  parallel_for_ranges<int>(0, (height + together - 1) / together, 16, [&](int groups_begin, int groups_end) {
    for (int y0 = groups_begin * together; y0 < std::min(height, groups_end * together); y0 += together) {
      std::array<double, together> sum{};
      std::array<const float*, together> row{};
      const int count = std::min(together, height - y0);
      for (int r = 0; r < together; ++r) row[static_cast<std::size_t>(r)] = heights.row(std::min(y0 + r, height - 1)).data();
      for (int x = 0; x < width; ++x)
        for (std::size_t r = 0; r < together; ++r) sum[r] += row[r][x];
      for (int r = 0; r < count; ++r) rows[static_cast<std::size_t>(y0 + r)] = sum[static_cast<std::size_t>(r)];
    }
  });
  double total = 0.0;
  for (double r : rows) total += r;
  return total * heights.cell_size_m * heights.cell_size_m;
}

/// Marks the outlets (priority_flood.hpp's is_outlet) row by row: the edge, and cells at or
/// below the sea, with a comparison that vectorises.
void mark_outlets(const Heightfield& heights, const Outlets& outlets, Grid<std::uint8_t>& fixed) {
  const int width = heights.width(), height = heights.height();
  ensure_shape(fixed, width, height);
  // The highest float at or below the sea: a float compares with it as its double would with
  // the sea (and in floats the comparison vectorises).
  const double sea = outlets.sea_level_m.value_or(-std::numeric_limits<double>::infinity());
  float sea_float = static_cast<float>(sea);
  if (static_cast<double>(sea_float) > sea) sea_float = std::nextafter(sea_float, -std::numeric_limits<float>::infinity());
  parallel_for_ranges<int>(0, height, 16, [&](int rows_begin, int rows_end) {
    for (int y = rows_begin; y < rows_end; ++y) {
      // Separate grids, restricted: byte stores may otherwise alias anything.
      std::uint8_t* __restrict out = fixed.row(y).data();
      const float* __restrict z = heights.row(y).data();
      if (y == 0 || y == height - 1) {
        std::fill(out, out + width, std::uint8_t{1});
        continue;
      }
      const int end = width;  // local copies: GCC does not vectorise with the captured ones
      const float sea_here = sea_float;
      for (int x = 0; x < end; ++x) out[x] = z[x] <= sea_here ? 1 : 0;
      out[0] = out[end - 1] = 1;
    }
  });
}

}  // namespace

double diffuse_hillslopes(Heightfield& heights, double diffusivity_m2_per_yr, double years, const std::optional<double>& sea_level_m) {
  StreamPowerWorkspace workspace;
  return diffuse_hillslopes(heights, diffusivity_m2_per_yr, years, sea_level_m, workspace);
}

double diffuse_hillslopes(Heightfield& heights, double diffusivity_m2_per_yr, double years, const std::optional<double>& sea_level_m,
                          StreamPowerWorkspace& workspace) {
  const int width = heights.width(), height = heights.height();
  if (diffusivity_m2_per_yr <= 0.0 || years <= 0.0 || width < 3 || height < 3) return 0.0;
  const double alpha = diffusivity_m2_per_yr * years / (heights.cell_size_m * heights.cell_size_m);
  const double before = volume_sum(heights);
  mark_outlets(heights, Outlets{sea_level_m}, workspace.fixed);
  const std::uint8_t* fixed = workspace.fixed.data();
  ensure_shape(workspace.diffused, width, height);
  double* z = workspace.diffused.data();
  const float* start = heights.data();
  parallel_for_ranges<std::size_t>(0, heights.size(), 1 << 16, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t i = range_begin; i < range_end; ++i) z[i] = start[i];
  });
  // Rows, a block of them side by side: each row is solved on its own, in its one order (the
  // same bytes with any number of threads), and the rows' chains of divisions overlap in the
  // processor instead of waiting on each other.
  constexpr int rows_together = 8;
  parallel_for_ranges<int>(0, (height - 2 + rows_together - 1) / rows_together, 1, [&](int blocks_begin, int blocks_end) {
    std::vector<ThomasStep> steps(static_cast<std::size_t>(width) * rows_together);
    for (int b = blocks_begin; b < blocks_end; ++b) {
      const int y0 = 1 + b * rows_together, rows = std::min(rows_together, height - 1 - y0);
      std::array<double*, rows_together> line{};
      std::array<const std::uint8_t*, rows_together> fixed_line{};
      for (int r = 0; r < rows; ++r) {
        line[static_cast<std::size_t>(r)] = z + static_cast<std::ptrdiff_t>(y0 + r) * width;
        fixed_line[static_cast<std::size_t>(r)] = fixed + static_cast<std::ptrdiff_t>(y0 + r) * width;
      }
      for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) steps[r] = thomas_forward(alpha, true, line[r][0], {});
      for (int x = 1; x < width; ++x) {
        ThomasStep* at = steps.data() + static_cast<std::size_t>(x) * rows_together;
        const ThomasStep* left = at - rows_together;
        for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r)
          at[r] = thomas_forward(alpha, fixed_line[r][x] != 0, line[r][x], left[r]);
      }
      for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r)
        line[r][width - 1] = steps[static_cast<std::size_t>(width - 1) * rows_together + r].dp;
      for (int x = width - 2; x >= 0; --x) {
        const ThomasStep* at = steps.data() + static_cast<std::size_t>(x) * rows_together;
        for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) line[r][x] = thomas_back(at[r], line[r][x + 1]);
      }
    }
  });
  // Then columns, a block of neighbouring columns at a time so that every pass reads whole
  // cache lines (a column alone would touch one line per row).
  constexpr int block = 16;
  parallel_for_ranges<int>(0, (width + block - 1) / block, 1, [&](int blocks_begin, int blocks_end) {
    std::vector<ThomasStep> steps(static_cast<std::size_t>(height) * block);
    for (int b = blocks_begin; b < blocks_end; ++b) {
      const int x0 = b * block, columns = std::min(block, width - x0);
      for (int c = 0; c < columns; ++c)
        steps[static_cast<std::size_t>(c)] = thomas_forward(alpha, true, z[static_cast<std::size_t>(x0 + c)], {});
      for (int y = 1; y < height; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * width + x0;
        const std::size_t at = static_cast<std::size_t>(y) * block, above = at - block;
        for (int c = 0; c < columns; ++c) {
          const auto u = static_cast<std::size_t>(c);
          steps[at + u] = thomas_forward(alpha, fixed[row + u] != 0, z[row + u], steps[above + u]);
        }
      }
      const std::size_t last_row = static_cast<std::size_t>(height - 1) * width + x0;
      for (int c = 0; c < columns; ++c)
        z[last_row + static_cast<std::size_t>(c)] = steps[static_cast<std::size_t>(height - 1) * block + static_cast<std::size_t>(c)].dp;
      for (int y = height - 2; y >= 0; --y) {
        const std::size_t row = static_cast<std::size_t>(y) * width + x0, at = static_cast<std::size_t>(y) * block;
        for (int c = 0; c < columns; ++c) {
          const auto u = static_cast<std::size_t>(c);
          z[row + u] = thomas_back(steps[at + u], z[row + width + u]);
        }
      }
    }
  });
  float* out = heights.data();
  parallel_for_ranges<std::size_t>(0, heights.size(), 1 << 16, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t i = range_begin; i < range_end; ++i) out[i] = static_cast<float>(z[i]);
  });
  return before - volume_sum(heights);
}

double resolved_diffusivity(const StreamPowerParams& params, double cell_size_m, double tau_yr) {
  if (params.diffusivity_m2_per_yr) return *params.diffusivity_m2_per_yr;
  if (!std::isfinite(tau_yr) || tau_yr <= 0.0) return 0.0;  // no erosion to keep pace with
  return diffusion_per_tau * cell_size_m * cell_size_m / tau_yr;
}

ErosionBudget stream_power_step(Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr,
                                Grid<float>& eroded_m, Grid<float>& deposited_m, const Context& context) {
  StreamPowerWorkspace workspace;
  return stream_power_step(heights, params, uplift_m_per_yr, eroded_m, deposited_m, workspace, context);
}

ErosionBudget stream_power_step(Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr,
                                Grid<float>& eroded_m, Grid<float>& deposited_m, StreamPowerWorkspace& workspace, const Context& context,
                                const FlowRouting* routing_of_heights) {
  const double diffusivity =
      params.diffusivity_m2_per_yr
          ? *params.diffusivity_m2_per_yr
          : resolved_diffusivity(params, heights.cell_size_m, response_time_yr(heights, params, context, nullptr, routing_of_heights));
  const Outlets outlets{params.sea_level_m};
  if (routing_of_heights == nullptr)
    route_flow(heights, outlets, workspace.flow, workspace.routing, context);
  else
    check_routing_of(*routing_of_heights, heights);
  const FlowRouting& flow = routing_of_heights != nullptr ? *routing_of_heights : workspace.flow;
  context.report("routing", 0.6);  // about 60 % of a step
  const int width = heights.width();
  const double dt = params.time_step_yr;
  const double cell_area = heights.cell_size_m * heights.cell_size_m;
  const CellIndex* rec = flow.receiver.data();
  const float* surface = flow.surface.data();
  float* h = heights.data();
  const auto uplift = [&](CellIndex i) {
    return uplift_m_per_yr ? static_cast<double>(uplift_m_per_yr->data()[i]) : params.uplift_m_per_yr;
  };

  // K dt A^m / L^n of a cell that drains to r: (K dt) A^m / L^n as one expression, L^n of the
  // two lengths computed once.
  const double k_dt = params.erodibility * dt;
  const AreaPower area_power(cell_area, params.area_exponent);
  const double straight_power = std::pow(heights.cell_size_m, params.slope_exponent);
  const double diagonal_power = std::pow(heights.cell_size_m * neighbour_distance[1], params.slope_exponent);
  const double* area = flow.area_m2.data();
  const auto factor = [&](CellIndex i, CellIndex r) {
    const bool diagonal = is_diagonal(r - i, width);
    return k_dt * area_power(area[i]) / (diagonal ? diagonal_power : straight_power);
  };

  // Incision, outlets first: each cell's new height needs only its receiver's (Braun & Willett
  // eq. 8 for n = 1; Newton otherwise). A cell in a depression routes through its spill path;
  // where its receiver ends up higher than itself (a lake deeper than one step's uplift) it is
  // a lake floor and is not incised. Shallow pits (a millimetre left by diffusion in a channel)
  // are incised like the channel around them: stopping there would let the uplift of one step
  // raise a spike in the river.
  // Drainage trees are independent, so runs of whole trees go to threads; each tree is walked in
  // its one order, and the budget is summed per run and then in run order: the same bytes with
  // any number of threads.
  const std::vector<std::size_t> pieces = stack_pieces(flow.stack, flow.receiver);
  ensure_shape(workspace.incised, heights.width(), heights.height());
  double* incised = workspace.incised.data();
  const bool linear = params.slope_exponent == 1.0;
  parallel_for(std::size_t{0}, pieces.size() - 1, [&](std::size_t p) {
    for (std::size_t k = pieces[p]; k < pieces[p + 1]; ++k) {
      const CellIndex i = flow.stack[k];
      const CellIndex r = rec[i];
      if (r == i) {
        incised[i] = h[i];
        continue;
      }
      const double lifted = static_cast<double>(h[i]) + uplift(i) * dt;
      const double below = incised[r];
      if (lifted <= below) {
        incised[i] = lifted;
        continue;
      }
      const double f = factor(i, r);
      if (f == 0.0)
        incised[i] = lifted;
      else if (linear)
        incised[i] = (lifted + f * below) / (1.0 + f);
      else
        incised[i] = below + solve_incision(lifted - below, f, params.slope_exponent);
    }
  });
  context.check_cancelled();

  // Sediment, upstream first: what arrives deposits at the rate G Qs / A (Yuan et al. 2019), or
  // up to the spill level in a lake; the rest moves on. The budget is kept on the heights as
  // stored (floats), so eroded - deposited equals what leaves, up to double rounding.
  ensure_shape(workspace.incoming, heights.width(), heights.height());
  double* incoming = workspace.incoming.data();
  std::vector<ErosionBudget> piece_budget(pieces.size() - 1);
  float* eroded_map = eroded_m.data();
  float* deposited_map = deposited_m.data();
  parallel_for(std::size_t{0}, pieces.size() - 1, [&](std::size_t p) {
    ErosionBudget& budget = piece_budget[p];
    for (std::size_t k = pieces[p]; k < pieces[p + 1]; ++k) incoming[flow.stack[k]] = 0.0;  // a piece's own trees only
    for (std::size_t k = pieces[p + 1]; k-- > pieces[p];) {
      const CellIndex i = flow.stack[k];
      const CellIndex r = rec[i];
      const double supply = incoming[i];
      if (r == i) {
        budget.sediment_out_m3 += supply;
        continue;
      }
      const double lifted = static_cast<double>(h[i]) + uplift(i) * dt;
      double deposit_m3 = 0.0;
      if (surface[i] > h[i])
        deposit_m3 = std::min(supply, std::max(0.0, (static_cast<double>(surface[i]) - incised[i]) * cell_area));
      else
        deposit_m3 = std::min(supply, params.deposition * supply * cell_area / area[i]);
      const auto new_height = static_cast<float>(incised[i] + deposit_m3 / cell_area);
      const double removed_m3 = (lifted - static_cast<double>(new_height)) * cell_area;
      incoming[r] += supply + removed_m3;
      if (removed_m3 > 0.0)
        budget.eroded_m3 += removed_m3;
      else
        budget.deposited_m3 -= removed_m3;
      eroded_map[i] += static_cast<float>(lifted - incised[i]);
      deposited_map[i] += static_cast<float>(deposit_m3 / cell_area);
      h[i] = new_height;
    }
  });
  ErosionBudget budget;
  for (const ErosionBudget& part : piece_budget) budget += part;

  context.report("incision", 0.87);
  budget.hillslope_out_m3 = diffuse_hillslopes(heights, diffusivity, dt, params.sea_level_m, workspace);
  return budget;
}

ErosionResult erode_stream_power(const Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr,
                                 const Context& context) {
  params.validate();
  require_finite_heights(heights, "stream-power erosion");
  if (uplift_m_per_yr) {
    if (uplift_m_per_yr->width() != heights.width() || uplift_m_per_yr->height() != heights.height())
      fail("the uplift map is {}x{}; it must have the heightfield's size, {}x{}", uplift_m_per_yr->width(), uplift_m_per_yr->height(),
           heights.width(), heights.height());
    for (float u : uplift_m_per_yr->values())
      if (!std::isfinite(u) || u < 0.0f) fail("the uplift map holds {}; uplift must be a finite number >= 0 m/yr", u);
  }
  ErosionResult result{
      heights, Grid<float>(heights.width(), heights.height(), 0.0f), Grid<float>(heights.width(), heights.height(), 0.0f), {}};
  StreamPowerParams resolved = params;
  if (!resolved.diffusivity_m2_per_yr && params.steps > 0)
    resolved.diffusivity_m2_per_yr = resolved_diffusivity(params, heights.cell_size_m, response_time_yr(heights, params, context));
  copy_placement(result.eroded_m, heights);
  copy_placement(result.deposited_m, heights);
  StreamPowerWorkspace workspace;
  for (int step = 0; step < params.steps; ++step) {
    context.check_cancelled();
    result.budget += stream_power_step(result.heights, resolved, uplift_m_per_yr, result.eroded_m, result.deposited_m, workspace);
    context.report("stream power", static_cast<double>(step + 1) / params.steps);
  }
  return result;
}

double stage_response_times(ErosionStage stage, int model) {
  // Model 1 (recipes of version 1) and model 2, young to peneplain.
  constexpr double times[2][4] = {{0.1, 0.5, 2.0, 8.0}, {0.2, 0.7, 1.2, 2.5}};
  return times[model == 1 ? 0 : 1][static_cast<int>(stage)];
}

double response_time_yr(const Heightfield& heights, const StreamPowerParams& params, const Context& context,
                        StreamPowerWorkspace* workspace, const FlowRouting* routing_of_heights) {
  if (params.erodibility <= 0.0) return std::numeric_limits<double>::infinity();
  FlowRouting fresh;
  RoutingScratch scratch;
  if (routing_of_heights == nullptr)
    route_flow(heights, Outlets{params.sea_level_m}, workspace ? workspace->flow : fresh, workspace ? workspace->routing : scratch,
               context);
  else
    check_routing_of(*routing_of_heights, heights);
  const FlowRouting& flow = routing_of_heights != nullptr ? *routing_of_heights : workspace ? workspace->flow : fresh;
  context.report("response time", 0.8);
  const int width = heights.width();
  const CellIndex* rec = flow.receiver.data();
  const double* area = flow.area_m2.data();
  const float* surface = flow.surface.data();
  const AreaPower area_power(heights.cell_size_m * heights.cell_size_m, params.area_exponent);
  Grid<double> own_time;
  Grid<double>& time_grid = workspace ? workspace->incised : own_time;  // the step's scratch, before the step
  ensure_shape(time_grid, heights.width(), heights.height());
  double* time = time_grid.data();
  // Drainage trees are independent: the pieces in parallel, the longest time of each, then the
  // longest of those (a maximum: the same with any number of threads).
  const std::vector<std::size_t> pieces = stack_pieces(flow.stack, flow.receiver);
  std::vector<double> longest(pieces.size() - 1, 0.0);
  parallel_for(std::size_t{0}, pieces.size() - 1, [&](std::size_t p) {
    for (std::size_t k = pieces[p]; k < pieces[p + 1]; ++k) {
      const CellIndex i = flow.stack[k];
      const CellIndex r = rec[i];
      if (r == i) {
        time[static_cast<std::size_t>(i)] = 0.0;
        continue;
      }
      const bool diagonal = is_diagonal(r - i, width);
      const double length = heights.cell_size_m * (diagonal ? neighbour_distance[1] : 1.0);
      double celerity = params.erodibility * area_power(area[i]);
      if (params.slope_exponent != 1.0) {
        const double slope = std::max(1e-3, (static_cast<double>(surface[i]) - surface[r]) / length);
        celerity *= std::pow(slope, params.slope_exponent - 1.0);
      }
      time[static_cast<std::size_t>(i)] = time[static_cast<std::size_t>(r)] + length / celerity;
      longest[p] = std::max(longest[p], time[static_cast<std::size_t>(i)]);
    }
  });
  context.report("response time", 1.0);
  return longest.empty() ? 0.0 : *std::max_element(longest.begin(), longest.end());
}

StreamPowerParams params_for_stage(const Heightfield& heights, StreamPowerParams params, ErosionStage stage, const Context& context,
                                   int model, StreamPowerWorkspace* workspace, const FlowRouting* routing_of_heights) {
  if (params.steps <= 0) return params;
  return params_for_response_time(params, stage, model, response_time_yr(heights, params, context, workspace, routing_of_heights),
                                  heights.cell_size_m);
}

StreamPowerParams params_for_response_time(StreamPowerParams params, std::optional<ErosionStage> stage, int model, double tau_yr,
                                           double cell_size_m) {
  if (stage && std::isfinite(tau_yr) && tau_yr > 0.0) params.time_step_yr = stage_response_times(*stage, model) * tau_yr / params.steps;
  params.diffusivity_m2_per_yr = resolved_diffusivity(params, cell_size_m, tau_yr);
  return params;
}

}  // namespace sansui::water
