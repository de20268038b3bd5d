// A world in tiles against the same world whole, in one process (core/tile_exchange.hpp's
// OneProcess): flow routing, and routing plus one stream-power step, on 1025^2 and 2049^2 in
// tiles of 256 and 512 cells. The ratio tiled / whole is the cost of exactness across tiles
// without MPI (goal: at most 1.2); cells per second per core compare with Barnes 2016.
#include <benchmark/benchmark.h>

#include "core/tile_halo.hpp"
#include "terrain/midpoint.hpp"
#include "water/flow.hpp"
#include "water/tiled_erosion.hpp"

namespace sansui {
namespace {

Heightfield world_of(int size) {
  terrain::MidpointParams params;
  params.seed = 3;
  params.sigma_m = 300.0;
  Heightfield h = terrain::generate_midpoint(params, size);
  h.cell_size_m = 10.0;
  return h;
}

water::StreamPowerParams step_params() {
  water::StreamPowerParams params;
  params.diffusivity_m2_per_yr = 0.5;
  params.time_step_yr = 5e4;
  return params;
}

Heightfield own_part(const Heightfield& world, const TileCut& cut, int t) {
  return copy_of(world.view(cut.owned(t)));
}

void RouteWhole(benchmark::State& state) {
  const Heightfield world = world_of(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(water::route_flow(world, {}));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.size()));
}

void RouteTiled(benchmark::State& state) {
  const Heightfield world = world_of(static_cast<int>(state.range(0)));
  const TileCut cut{world.width(), world.height(), static_cast<int>(state.range(1))};
  OneProcess exchange;
  for (auto _ : state) {
    std::vector<water::ErodingTile> tiles =
        water::eroding_tiles(cut, world.cell_size_m, exchange, [&](int t) { return own_part(world, cut, t); });
    std::vector<water::RoutedTile> routed;
    routed.reserve(tiles.size());
    for (auto& t : tiles) routed.push_back(std::move(t.flow));
    water::route_tiles(cut, routed, {}, world.cell_size_m, exchange);
    benchmark::DoNotOptimize(routed);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.size()));
  state.counters["MB_per_tile"] = static_cast<double>(exchange.bytes_sent) / 1e6 / static_cast<double>(state.iterations()) / cut.tiles();
}

void StepWhole(benchmark::State& state) {
  const Heightfield world = world_of(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Heightfield h = world;
    Grid<float> eroded(h.width(), h.height(), 0.0f), deposited(h.width(), h.height(), 0.0f);
    water::stream_power_step(h, step_params(), nullptr, eroded, deposited);
    benchmark::DoNotOptimize(h);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.size()));
}

void StepTiled(benchmark::State& state) {
  const Heightfield world = world_of(static_cast<int>(state.range(0)));
  const TileCut cut{world.width(), world.height(), static_cast<int>(state.range(1))};
  OneProcess exchange;
  for (auto _ : state) {
    std::vector<water::ErodingTile> tiles =
        water::eroding_tiles(cut, world.cell_size_m, exchange, [&](int t) { return own_part(world, cut, t); });
    water::tiled_stream_power_step(cut, tiles, step_params(), exchange);
    benchmark::DoNotOptimize(tiles);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.size()));
  state.counters["MB_per_tile"] = static_cast<double>(exchange.bytes_sent) / 1e6 / static_cast<double>(state.iterations()) / cut.tiles();
}

BENCHMARK(RouteWhole)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(RouteTiled)->Args({1025, 256})->Args({2049, 512})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(StepWhole)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(StepTiled)->Args({1025, 256})->Args({2049, 512})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace sansui

BENCHMARK_MAIN();
