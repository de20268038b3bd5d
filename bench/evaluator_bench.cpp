// The evaluator's own cost (issue "Recipes as graphs": under 1 % of a run). A warm evaluate()
// runs no node: it plans the graph, makes every node's key and finds each result in memory, so
// its time is the evaluator's overhead; the cold run of the same graph is the reference.
// Recipes with a source pay one key, the recipe as JSON text (TerrainKey), against the main
// job's whole run (about 2.4 s; bench/timing.sh).
#include <benchmark/benchmark.h>

#include "bench/bench_paths.hpp"
#include "scene/evaluator.hpp"
#include "scene/graph.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::scene {
namespace {

const Recipe& terraces() {
  static const Recipe recipe =
      load_recipe(std::string(sansui::bench::source_dir) + "/examples/scenes/graphs/terraces-on-steep-slopes.toml").recipe;
  return recipe;
}

void GraphCold(benchmark::State& state) {
  for (auto _ : state) {
    Evaluator evaluator;
    benchmark::DoNotOptimize(evaluator.evaluate(terraces().nodes, graph_world(terraces()), {"terraced"}));
  }
}
BENCHMARK(GraphCold)->Unit(benchmark::kMillisecond)->UseRealTime();

void GraphWarm(benchmark::State& state) {
  Evaluator evaluator;
  (void)evaluator.evaluate(terraces().nodes, graph_world(terraces()), {"terraced"});
  for (auto _ : state) benchmark::DoNotOptimize(evaluator.evaluate(terraces().nodes, graph_world(terraces()), {"terraced"}));
}
BENCHMARK(GraphWarm)->Unit(benchmark::kMicrosecond)->UseRealTime();

/// A 1025² midpoint node run in the library, as sansui.midpoint(size=1025) runs it: the
/// reference of the Python call's overhead (bench/python_overhead.py).
void NodeMidpoint1025(benchmark::State& state) {
  const NodeKind& kind = *find_node_kind("midpoint");
  const std::any params = kind.make();
  GraphWorld world;
  world.width = world.height = 1025, world.base_dir = ".";
  for (auto _ : state) benchmark::DoNotOptimize(kind.run(params, {}, world, quiet_context()));
}
BENCHMARK(NodeMidpoint1025)->Unit(benchmark::kMillisecond)->UseRealTime();

void TerrainKey(benchmark::State& state) {
  const Recipe recipe = load_recipe(std::string(sansui::bench::source_dir) + "/examples/scenes/gallery/tropical-coast.toml").recipe;
  for (auto _ : state) benchmark::DoNotOptimize(recipe_to_json(recipe).dump());
}
BENCHMARK(TerrainKey)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace sansui::scene

BENCHMARK_MAIN();
