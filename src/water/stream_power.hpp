// Landscape evolution by stream-power incision, dz/dt = U - K A^m S^n, solved implicitly in O(N)
// per step over the receiver stack (Braun & Willett, "A very efficient O(n), implicit and parallel
// method to solve the stream power equation governing fluvial incision and landscape
// evolution", Geomorphology 180, 2013), with sediment deposition after Yuan, Braun, Guerit,
// Rouby & Cordonnier ("A new efficient method to solve the stream power law model taking into
// account sediment deposition", JGR Earth Surface 124, 2019: deposition rate G Qs / A), lakes
// that trap all the sediment they can hold, and linear hillslope diffusion dz/dt = D laplacian(z).
//
// One step: route the flow (priority-flood + epsilon, D8), incise from the outlets upstream,
// carry the sediment downstream depositing on the way, then diffuse. Outlets (the map's edge,
// cells at or below the sea) are fixed base level: no uplift, no erosion, sediment reaching them
// leaves the map.
//
// Stages (Davis's cycle of erosion) are erosion times in units of the response time tau, the
// time a knickpoint takes to travel from the outlets to the farthest cell
// (Whipple & Tucker 1999): see stage_response_times().
#pragma once

#include <optional>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "water/flow.hpp"
#include "water/routing_scratch.hpp"

namespace sansui::water {

/// Fluvial erosion, deposition and hillslope diffusion. Table: water_params.cpp (section [erosion]).
struct StreamPowerParams {
  /// Erodibility K of dz/dt = U - K A^m S^n. [Units: m^(1-2m)/yr] [Range: >= 0] [Default: 2e-5]
  double erodibility = 2e-5;
  /// Drainage-area exponent m. [Range: 0..2] [Default: 0.45]
  double area_exponent = 0.45;
  /// Slope exponent n (1: exact linear solve; otherwise Newton per cell). [Range: 0.5..4] [Default: 1]
  double slope_exponent = 1.0;
  /// Uniform rock uplift U (a per-cell map replaces it when given). [Units: m/yr] [Range: >= 0]
  /// [Default: 0: Davis's cycle, the land wears down after its uplift has stopped; recipes of version 1: 1e-4]
  double uplift_m_per_yr = 0.0;
  /// Hillslope diffusivity D of dz/dt = D laplacian(z). [Units: m^2/yr] [Range: >= 0]
  /// [Default: unset: diffusion_per_tau cell sizes squared per response time, so hillslopes round
  /// off alike on any grid; recipes of version 1: 0.01]
  std::optional<double> diffusivity_m2_per_yr;
  /// Deposition coefficient G of Yuan et al. 2019 (0: none; 1: about as much deposition as erosion
  /// on low ground). [Range: 0..10] [Default: 1]
  double deposition = 1.0;
  /// Time step. [Units: yr] [Range: > 0] [Default: 2e4]
  double time_step_yr = 2e4;
  /// Number of steps (each routes the flow anew: about 0.1 s at 1025 x 1025). [Range: 0..100000]
  /// [Default: 8; recipes of version 1: 10]
  int steps = 8;
  /// Cells below this height are sea: fixed base level. Unset: only the edge. [Units: m]
  std::optional<double> sea_level_m;

  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<StreamPowerParams>& parameter_table(const StreamPowerParams*);

/// Volumes moved, for the mass balance: eroded - deposited = sediment_out (the fluvial part).
struct ErosionBudget {
  double eroded_m3 = 0.0;         ///< net loss of cells that lost material (uplift excluded). [Units: m^3]
  double deposited_m3 = 0.0;      ///< net gain of cells that gained material. [Units: m^3]
  double sediment_out_m3 = 0.0;   ///< fluvial sediment that reached an outlet and left. [Units: m^3]
  double hillslope_out_m3 = 0.0;  ///< volume the diffusion moved into the outlets. [Units: m^3]

  ErosionBudget& operator+=(const ErosionBudget& other) {
    eroded_m3 += other.eroded_m3, deposited_m3 += other.deposited_m3;
    sediment_out_m3 += other.sediment_out_m3, hillslope_out_m3 += other.hillslope_out_m3;
    return *this;
  }
};

struct ErosionResult {
  Heightfield heights;      ///< the eroded heights. [Units: m]
  Grid<float> eroded_m;     ///< total fluvial incision per cell (splat map). [Units: m]
  Grid<float> deposited_m;  ///< total deposition per cell, lakes filled by sediment included. [Units: m]
  ErosionBudget budget;
};

/// Cell sizes squared of hillslope diffusion per response time, when params leave the
/// diffusivity unset: D = diffusion_per_tau x cell^2 / tau. 3 keeps the valleys' sides rough
/// (the diffusion length at maturity is about 1.4 cells) while it rounds off single-cell spikes.
inline constexpr double diffusion_per_tau = 3.0;

/// The diffusivity of `params`, or (unset) diffusion_per_tau x cell^2 / tau_yr. [Units: m^2/yr]
double resolved_diffusivity(const StreamPowerParams& params, double cell_size_m, double tau_yr);

/// Working memory of stream_power_step, kept across the steps of one run so that a run at one
/// size allocates it once. Its contents mean nothing between calls.
struct StreamPowerWorkspace {
  FlowRouting flow;
  RoutingScratch routing;
  Grid<double> incised;      ///< heights after incision
  Grid<double> incoming;     ///< sediment arriving at each cell. [Units: m^3]
  Grid<double> diffused;     ///< heights during the diffusion
  Grid<std::uint8_t> fixed;  ///< outlets, held by the diffusion
};

/// One step on `heights` in place; adds the step's incision and deposition to the two maps
/// (which must have the heights' size). `uplift_m_per_yr`: null for the uniform uplift. An unset
/// diffusivity is resolved from the heights' response time (one more routing).
ErosionBudget stream_power_step(Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr,
                                Grid<float>& eroded_m, Grid<float>& deposited_m, const Context& context = quiet_context());
/// The same with its working memory in `workspace` (the same bytes). `routing_of_heights`:
/// route_flow's routing of exactly these heights under params.sea_level_m, made before (the
/// response time's, or a graph's flow node's), which the step takes; null: the step routes them
/// into the workspace.
ErosionBudget stream_power_step(Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr,
                                Grid<float>& eroded_m, Grid<float>& deposited_m, StreamPowerWorkspace& workspace,
                                const Context& context = quiet_context(), const FlowRouting* routing_of_heights = nullptr);

/// params.steps steps of params.time_step_yr. `uplift_m_per_yr`: a per-cell uplift map of the
/// heights' size, or null for params.uplift_m_per_yr everywhere. Throws InputError on bad params
/// or a map of the wrong size. Same bytes with any number of threads.
ErosionResult erode_stream_power(const Heightfield& heights, const StreamPowerParams& params, const Grid<float>* uplift_m_per_yr = nullptr,
                                 const Context& context = quiet_context());

/// Linear hillslope diffusion over `years`, implicit: backward Euler along rows, then along
/// columns (locally one-dimensional splitting), unconditionally stable and free of new extrema
/// at any time step, so long steps never need sub-steps. Outlets stay fixed. Returns the
/// volume moved into the outlets.
double diffuse_hillslopes(Heightfield& heights, double diffusivity_m2_per_yr, double years, const std::optional<double>& sea_level_m);
/// The same with its working memory in `workspace`.
double diffuse_hillslopes(Heightfield& heights, double diffusivity_m2_per_yr, double years, const std::optional<double>& sea_level_m,
                          StreamPowerWorkspace& workspace);

/// Davis's stages as erosion time in response times tau, without uplift (the land wears down
/// after it was raised). Young 0.05: the big rivers have cut in, the uplands keep their original
/// roughness. Mature 0.7: valleys everywhere, the land is dissected to its divides, lowlands
/// spread from the coast. Old 1.2: broad lowlands, low rounded hills. Peneplain 2.5: an almost
/// plain with a few low remnants. The highest point and the mean height fall at every stage
/// (tests/water/stages_test.cpp). Recipes of version 1 (model 1) took 0.1, 0.5, 2 and 8, with
/// uplift, which kept old and peneplain close to one steady state.
enum class ErosionStage { young, mature, old, peneplain };
double stage_response_times(ErosionStage stage, int model = 2);

/// The response time tau of `heights` under `params`: the longest time a knickpoint takes to
/// travel from an outlet up the D8 network to any cell, sum of L / (K A^m S^(n-1)) (Whipple &
/// Tucker 1999), with S the current slope (1e-3 at least) when n != 1. [Units: yr]
/// `workspace`: routes into workspace->flow, which a step on the same heights can take.
/// `routing_of_heights`: as stream_power_step's; then nothing is routed.
double response_time_yr(const Heightfield& heights, const StreamPowerParams& params, const Context& context = quiet_context(),
                        StreamPowerWorkspace* workspace = nullptr, const FlowRouting* routing_of_heights = nullptr);

/// `params` with the time step set so that params.steps steps last stage_response_times(stage,
/// model) tau (without a stage, or an infinite tau, its own), and an unset diffusivity resolved
/// from tau.
StreamPowerParams params_for_response_time(StreamPowerParams params, std::optional<ErosionStage> stage, int model, double tau_yr,
                                           double cell_size_m);

/// `params` with the time step set so that params.steps steps last stage_response_times(stage,
/// model) tau, and an unset diffusivity resolved from tau.
/// `workspace` and `routing_of_heights`: as response_time_yr's.
StreamPowerParams params_for_stage(const Heightfield& heights, StreamPowerParams params, ErosionStage stage,
                                   const Context& context = quiet_context(), int model = 2, StreamPowerWorkspace* workspace = nullptr,
                                   const FlowRouting* routing_of_heights = nullptr);

}  // namespace sansui::water
