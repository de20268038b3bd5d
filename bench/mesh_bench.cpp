// Fractal mesh subdivision and rasterisation speed (issue 6). The paper's kind of input, the
// 80-triangle sketch in examples/, subdivided 7 and 8 steps (1.3 M and 5.2 M triangles) with 1
// and 2 threads, beside the plain hash-map reference (one thread) in the same run; then the
// 5.2 M-triangle mesh rasterised into a 4097 x 4097 DEM, beside filling that grid once.
// CPU time is the whole process (all threads): on a shared machine, CPU / threads is what the
// wall time would be on idle cores. Run: build/bench/bench_mesh --benchmark_counters_tabular=true
#include <cstring>

#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "bench/bench_paths.hpp"
#include "bench/reference_subdivide.hpp"
#include "io/sketch_geojson.hpp"
#include "mesh/rasterize.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"

namespace {

using namespace sansui;

const mesh::EdgeMesh& mountain80() {
  static const mesh::EdgeMesh coarse = [] {
    const mesh::SketchMesh sketch =
        mesh::triangulate_sketch(io::read_sketch_geojson(std::string(sansui::bench::source_dir) + "/examples/sketches/mountain80.geojson"));
    return mesh::build_edge_mesh(sketch.mesh, sketch.locked);
  }();
  return coarse;
}

mesh::SubdivideParams params(int steps) {
  mesh::SubdivideParams p;
  p.steps = steps;
  p.seed = 1;
  return p;
}

void set_rate(benchmark::State& state, double triangles) {
  state.counters["Mtriangles/s"] = benchmark::Counter(triangles * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles"] = triangles;
}

void Reference_OneThread(benchmark::State& state) {
  const int steps = int(state.range(0));
  const mesh::EdgeMesh& coarse = mountain80();
  const double s0 = params(steps).roughness * mesh::mean_edge_length(coarse);
  for (auto _ : state) benchmark::DoNotOptimize(reference::subdivide(reference::keyed(coarse), 1, s0, 0.8, steps));
  set_rate(state, double(coarse.triangle_count() << (2 * steps)));
}

void Subdivide(benchmark::State& state) {
  const int steps = int(state.range(0));
  tbb::task_arena arena(int(state.range(1)));
  for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(mesh::subdivide(mountain80(), params(steps))); });
  set_rate(state, double(mountain80().triangle_count() << (2 * steps)));
}

/// What the CLI does before writing: subdivide, then the plain mesh with vertex normals.
void SubdivideAndNormals(benchmark::State& state) {
  const int steps = int(state.range(0));
  tbb::task_arena arena(int(state.range(1)));
  for (auto _ : state)
    arena.execute([&] { benchmark::DoNotOptimize(mesh::to_triangle_mesh(mesh::subdivide(mountain80(), params(steps)).mesh)); });
  set_rate(state, double(mountain80().triangle_count() << (2 * steps)));
}

const TriangleMesh& mountain_5m() {
  static const TriangleMesh fine = mesh::to_triangle_mesh(mesh::subdivide(mountain80(), params(8)).mesh, false);
  return fine;
}

void Rasterize4097(benchmark::State& state) {
  const TriangleMesh& fine = mountain_5m();
  const mesh::RasterFrame frame = mesh::square_frame(fine, 4097);
  tbb::task_arena arena(int(state.range(0)));
  for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(mesh::rasterize(fine, frame)); });
  set_rate(state, double(fine.triangle_count()));
  state.counters["Msamples/s"] = benchmark::Counter(4097.0 * 4097.0 * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// The least a rasteriser must do: make the 4097 x 4097 grid and write every sample once.
void Reference_FillGrid4097(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(Heightfield(4097, 4097, 1.0f));
  state.counters["Msamples/s"] = benchmark::Counter(4097.0 * 4097.0 * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(Reference_OneThread)->Arg(7)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(Subdivide)
    ->Args({7, 1})
    ->Args({7, 2})
    ->Args({8, 1})
    ->Args({8, 2})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(SubdivideAndNormals)->Args({8, 2})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(Rasterize4097)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(Reference_FillGrid4097)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
