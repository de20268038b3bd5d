// Plant placement speed (issue 11: a million instances on a 4097 x 4097 terrain in under 1 s).
// The terrain is the default midpoint world at 4 m cells (16 km across), sea level 0 m, tree line
// 900 m; the Cfb (oceanic beech forest) species; trees on a 10 m grid (2.7 million cells) at
// density 0.5 give about a million trees. With 1 and 2 threads; the bytes are the same. Wall time (UseRealTime).
// Run: build/bench/bench_vegetation --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "terrain/midpoint.hpp"
#include "vegetation/placement.hpp"

namespace {

using namespace sansui;

const Heightfield& terrain_4097() {
  static const Heightfield heights = [] {
    Heightfield h = terrain::generate_midpoint(terrain::MidpointParams{}, 4097);
    h.cell_size_m = 4.0;
    return h;
  }();
  return heights;
}

vegetation::PlacementRules forest_rules(double ground_density) {
  vegetation::PlacementRules rules;
  rules.tree_density = 0.5;
  rules.ground_density = ground_density;
  rules.sea_level_m = 0.0;
  rules.tree_line_m = 900.0;
  rules.species = vegetation::species_of_climate("Cfb");
  rules.species.push_back({"meadow_grass"});
  return rules;
}

void set_counters(benchmark::State& state, std::size_t instances, double cells) {
  state.counters["instances"] = double(instances);
  state.counters["Minstances/s"] = benchmark::Counter(double(instances) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["Mcells/s"] = benchmark::Counter(cells * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// About a million trees, no ground layer: the figure.
void PlaceTrees_4097(benchmark::State& state) {
  const Heightfield& heights = terrain_4097();
  const vegetation::PlacementRules rules = forest_rules(0.0);
  vegetation::VegetationParams params;
  params.spacing_m = 10.0;
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  vegetation::Placement placement;
  for (auto _ : state) arena.execute([&] { placement = vegetation::place_plants(heights, params, rules); });
  const double side_m = 4096.0 * heights.cell_size_m;
  set_counters(state, placement.trees.size(), (side_m / params.spacing_m) * (side_m / params.spacing_m));
}

/// Trees plus a ground layer of grass on a 5 m grid: about 3 million plants.
void PlaceTreesAndGround_4097(benchmark::State& state) {
  const Heightfield& heights = terrain_4097();
  const vegetation::PlacementRules rules = forest_rules(0.2);
  vegetation::VegetationParams params;
  params.spacing_m = 10.0;
  params.ground_spacing_m = 5.0;
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  vegetation::Placement placement;
  for (auto _ : state) arena.execute([&] { placement = vegetation::place_plants(heights, params, rules); });
  const double side_m = 4096.0 * heights.cell_size_m;
  set_counters(state, placement.trees.size() + placement.ground.size(),
               (side_m / 10.0) * (side_m / 10.0) + (side_m / 5.0) * (side_m / 5.0));
}

BENCHMARK(PlaceTrees_4097)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(PlaceTreesAndGround_4097)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
