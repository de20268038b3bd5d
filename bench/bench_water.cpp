// Water and erosion speed (issue 13): flow routing of a 4097x4097 DEM (priority-flood + D8
// receivers + stack + drainage area), one implicit stream-power step at 4097x4097, the default
// erosion chain of a 1025x1025 terrain, droplets per second, with the midpoint terrain generated
// in the same run as the reference. Run: build/bench/bench_water --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "reference_fastscape.hpp"
#include "terrain/midpoint.hpp"
#include "water/droplets.hpp"
#include "water/erode.hpp"
#include "water/flow.hpp"
#include "water/stream_power.hpp"
#include "water/thermal.hpp"

namespace {

using namespace sansui;

Heightfield terrain_of(int size) {
  terrain::MidpointParams p;
  p.seed = 1;
  Heightfield h = terrain::generate_midpoint(p, size);
  h.cell_size_m = 10.0;
  return h;
}

const Heightfield& terrain_4097() {
  static const Heightfield h = terrain_of(4097);
  return h;
}
const Heightfield& terrain_1025() {
  static const Heightfield h = terrain_of(1025);
  return h;
}

void set_rate(benchmark::State& state, double items, const char* name = "Mcells/s") {
  state.counters[name] = benchmark::Counter(items * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// The reference: generating the midpoint terrain itself.
void Reference_Midpoint(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(terrain_of(size));
  set_rate(state, double(size) * size);
}

void PriorityFlood(benchmark::State& state) {
  const Heightfield& h = terrain_4097();
  for (auto _ : state) benchmark::DoNotOptimize(water::fill_depressions_epsilon(h, {0.0}));
  set_rate(state, double(h.size()));
}

/// The in-tree reference for a step: a plain serial FastScape step (bench/reference_fastscape.cpp,
/// no depressions, deposition or diffusion) on the same terrain.
void Reference_FastScapeStep(benchmark::State& state) {
  const Heightfield& start = terrain_4097();
  const double k_dt = water::StreamPowerParams{}.erodibility * water::StreamPowerParams{}.time_step_yr;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<float> z(start.values().begin(), start.values().end());
    state.ResumeTiming();
    reference::fastscape_step(z, start.width(), start.height(), start.cell_size_m, k_dt, 0.45, 0.0);
    benchmark::DoNotOptimize(z.data());
  }
  set_rate(state, double(start.size()));
}

/// Routing as the steps of an erosion run do it: into the same memory each time.
void FlowRouting(benchmark::State& state) {
  const Heightfield& h = terrain_4097();
  water::FlowRouting flow;
  water::RoutingScratch scratch;
  water::route_flow(h, {0.0}, flow, scratch);  // the memory, as the steps before would have left it
  for (auto _ : state) {
    water::route_flow(h, {0.0}, flow, scratch);
    benchmark::DoNotOptimize(flow.area_m2.data());
  }
  set_rate(state, double(h.size()));
}

/// One step of an erosion run (its working memory kept from the step before) on the raw midpoint
/// terrain: the first step, the one with the most depressions to route.
void StreamPowerStep(benchmark::State& state) {
  const Heightfield& start = terrain_4097();
  water::StreamPowerParams p;
  p.sea_level_m = 0.0;
  p.diffusivity_m2_per_yr = 0.01;  // set: the step alone, without the response time an unset one needs
  Grid<float> eroded(start.width(), start.height(), 0.0f), deposited(start.width(), start.height(), 0.0f);
  water::StreamPowerWorkspace workspace;
  Heightfield h = start;
  water::stream_power_step(h, p, nullptr, eroded, deposited, workspace);  // the memory, as the steps before would have left it
  for (auto _ : state) {
    state.PauseTiming();
    std::copy(start.values().begin(), start.values().end(), h.values().begin());
    state.ResumeTiming();
    benchmark::DoNotOptimize(water::stream_power_step(h, p, nullptr, eroded, deposited, workspace));
  }
  set_rate(state, double(start.size()));
}

/// The hillslope diffusion of one step alone (its implicit solve along rows, then columns), with
/// its working memory kept, at 4097x4097.
void HillslopeDiffusion(benchmark::State& state) {
  const Heightfield& start = terrain_4097();
  water::StreamPowerWorkspace workspace;
  Heightfield h = start;
  water::diffuse_hillslopes(h, 0.01, 20000.0, 0.0, workspace);
  for (auto _ : state) {
    state.PauseTiming();
    std::copy(start.values().begin(), start.values().end(), h.values().begin());
    state.ResumeTiming();
    benchmark::DoNotOptimize(water::diffuse_hillslopes(h, 0.01, 20000.0, 0.0, workspace));
  }
  set_rate(state, double(start.size()));
}

/// The default chain with erosion model state.range(0): 3 (version 6) against 4 (version 7, with
/// land past the map's edges), in the same run.
void DefaultErosion(benchmark::State& state) {
  const Heightfield& h = terrain_1025();
  water::ErosionChainParams p;
  p.fluvial.sea_level_m = 0.0;
  const int model = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(water::erode(h, p, quiet_context(), model));
  set_rate(state, double(h.size()));
}

void Thermal(benchmark::State& state) {
  const Heightfield& h = terrain_1025();
  water::ThermalParams p;
  for (auto _ : state) benchmark::DoNotOptimize(water::erode_thermal(h, p));
  set_rate(state, double(h.size()) * p.iterations, "Mcell-iterations/s");
}

void Droplets(benchmark::State& state) {
  const Heightfield& h = terrain_1025();
  water::DropletParams p;
  p.droplets = 1000000;
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(water::erode_droplets(h, p)); });
  set_rate(state, double(*p.droplets), "Mdroplets/s");
}

BENCHMARK(Reference_Midpoint)->Arg(1025)->Arg(4097)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(PriorityFlood)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Reference_FastScapeStep)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(FlowRouting)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(StreamPowerStep)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(HillslopeDiffusion)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(DefaultErosion)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Thermal)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Droplets)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
