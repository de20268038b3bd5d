// Midpoint displacement speed (issue 3): the fast generator with 1 and 2 threads beside the plain
// reference (same random numbers, whole-grid loops) in the same run, tiles against the whole
// world, and one tile of a huge world. Run: build/bench/bench_terrain --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "bench/reference_midpoint.hpp"
#include "terrain/midpoint.hpp"

namespace {

using namespace sansui;

terrain::MidpointParams params() {
  terrain::MidpointParams p;
  p.seed = 1;
  return p;
}

void set_rate(benchmark::State& state, double samples_per_iteration) {
  state.counters["Msamples/s"] = benchmark::Counter(samples_per_iteration * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void Reference_OneThread(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(reference::midpoint_displacement(params(), size));
  set_rate(state, double(size) * size);
}

void Midpoint(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(terrain::generate_midpoint(params(), size)); });
  set_rate(state, double(size) * size);
}

/// 4x4 tiles of 1025 covering a 4097 world, one after the other, 2 threads.
void Tiles4x4_Of4097(benchmark::State& state) {
  for (auto _ : state)
    for (int t = 0; t < 16; ++t) {
      const int x = (t % 4) * 1024, y = (t / 4) * 1024;
      benchmark::DoNotOptimize(terrain::generate_midpoint(params(), terrain::WorldWindow{12, 0, Rect{x, y, x + 1025, y + 1025}}));
    }
  set_rate(state, 4097.0 * 4097.0);
}

/// One 4097 tile in the middle of a 65537 world.
void Tile4097_Of65537World(benchmark::State& state) {
  const int x = 7 * 4096, y = 9 * 4096;
  for (auto _ : state)
    benchmark::DoNotOptimize(terrain::generate_midpoint(params(), terrain::WorldWindow{16, 0, Rect{x, y, x + 4097, y + 4097}}));
  set_rate(state, 4097.0 * 4097.0);
}

BENCHMARK(Reference_OneThread)->Arg(4097)->Arg(8193)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(Midpoint)
    ->Args({4097, 1})
    ->Args({4097, 2})
    ->Args({8193, 1})
    ->Args({8193, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->UseRealTime();
BENCHMARK(Tiles4x4_Of4097)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(Tile4097_Of65537World)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
