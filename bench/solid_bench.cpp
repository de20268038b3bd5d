// Solid field evaluators (seeds/002, SPEC 2): lattice points per second for each type and query
// order. Type I is the reference: the issue asks Type I >= 100 M points/s on 2 cores at 513^3,
// and Type III in a coherent order at most 50x Type I's cost per point. `sansui bench solid`
// prints the paper's tables; this program gives the per-point rates at a few sizes.
#include <vector>

#include <benchmark/benchmark.h>

#include "core/random.hpp"
#include "solid/evaluator.hpp"
#include "solid/sphere_surface.hpp"
#include "solid/type1_array.hpp"

namespace {

using namespace sansui::solid;

FieldParams params_of(int levels) {
  FieldParams params;
  params.levels = levels;
  params.seed = 1;
  return params;
}

void BM_Type1Fill(benchmark::State& state) {
  const FieldParams params = params_of(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Volume volume = generate_type1(params);
    benchmark::DoNotOptimize(volume.data());
  }
  const double side = params.side();
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * side * side * side));
}
BENCHMARK(BM_Type1Fill)->Arg(7)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One thread queries a z-slab of the lattice in raster order (x fastest).
void BM_Type3Raster(benchmark::State& state) {
  const FieldParams params = params_of(static_cast<int>(state.range(0)));
  auto evaluator = make_evaluator(EvaluatorType::type3, params, {0, state.range(1) != 0});
  const int side = params.side();
  const int planes = 4;
  for (auto _ : state) {
    float sum = 0.0f;
    for (int z = side / 2; z < side / 2 + planes; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) sum += evaluator->at(x, y, z);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * planes * side * side);
}
BENCHMARK(BM_Type3Raster)->Args({9, 1})->Args({9, 0})->Unit(benchmark::kMillisecond);

void BM_Type3Random(benchmark::State& state) {
  const FieldParams params = params_of(static_cast<int>(state.range(0)));
  auto evaluator = make_evaluator(EvaluatorType::type3, params);
  const int side = params.side();
  std::vector<std::array<int, 3>> points(100000);
  for (std::size_t q = 0; q < points.size(); ++q)
    for (int a = 0; a < 3; ++a)
      points[q][static_cast<std::size_t>(a)] = static_cast<int>(sansui::rng::uniform(1, 9, static_cast<int>(q), a) * side);
  for (auto _ : state) {
    float sum = 0.0f;
    for (const auto& p : points) sum += evaluator->at(p[0], p[1], p[2]);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points.size()));
}
BENCHMARK(BM_Type3Random)->Arg(9)->Unit(benchmark::kMillisecond);

/// The paper's Experiment 2: every voxel on the surface of the digital sphere, along the surface
/// (octree order), the evaluator's set-up included.
void BM_SphereSurface(benchmark::State& state) {
  const FieldParams params = params_of(static_cast<int>(state.range(0)));
  const auto type = static_cast<EvaluatorType>(state.range(1));
  std::vector<SurfaceVoxel> voxels = digital_sphere_surface(params.levels);
  sort_along_octree(voxels);
  for (auto _ : state) {
    auto evaluator = make_evaluator(type, params, {6, true});
    float sum = 0.0f;
    for (const auto& v : voxels) sum += evaluator->at(v.x, v.y, v.z);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * voxels.size()));
}
BENCHMARK(BM_SphereSurface)
    ->Args({8, static_cast<int>(EvaluatorType::type3)})
    ->Args({10, static_cast<int>(EvaluatorType::type3)})
    ->Args({10, static_cast<int>(EvaluatorType::type4)})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
