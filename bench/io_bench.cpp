// File-format writers: samples (or vertices) per second, side by side in the same run with a plain
// reference, one fwrite of the float grid's bytes (what the disk and page cache allow at best).
//   build/bench/bench_io --benchmark_filter='8193'   # heightmaps, 8193 x 8193
//   build/bench/bench_io --benchmark_filter='1025'   # meshes of a 1025 x 1025 terrain
// Peak memory of one writer: /usr/bin/time -v build/bench/bench_io --benchmark_filter='R32/8193'
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include <benchmark/benchmark.h>

#include "core/random.hpp"
#include "io/heightmap_io.hpp"
#include "io/mesh_io.hpp"
#include "mesh/heightfield_mesh.hpp"

namespace {

using namespace sansui;

/// A smooth slope plus noise, like a terrain, so that PNG and Deflate see realistic data.
Heightfield bench_heights(int size) {
  auto heights = Heightfield::uninitialized(size, size, 10.0);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) heights(x, y) = static_cast<float>(2000.0 * (x + y) / (2.0 * size) + 20.0 * rng::uniform(1, 1, x, y));
  return heights;
}

const Heightfield& heights_of(int size) {
  static Heightfield cached;
  if (cached.width() != size) cached = bench_heights(size);
  return cached;
}

std::filesystem::path output(const char* extension) {
  return std::filesystem::temp_directory_path() / ("sansui-bench-io-" + std::to_string(::getpid()) + extension);
}

void finish(benchmark::State& state, const std::filesystem::path& path, double items) {
  state.SetItemsProcessed(static_cast<std::int64_t>(items * static_cast<double>(state.iterations())));
  state.counters["MiB"] = static_cast<double>(std::filesystem::file_size(path)) / (1 << 20);
  std::filesystem::remove(path);
  std::filesystem::remove(io::sidecar_path(path));
}

void reference_fwrite(benchmark::State& state) {
  const Heightfield& heights = heights_of(static_cast<int>(state.range(0)));
  const auto path = output(".bin");
  for (auto _ : state) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    std::fwrite(heights.data(), sizeof(float), heights.size(), file);
    std::fclose(file);
  }
  finish(state, path, static_cast<double>(heights.size()));
}

void write_heightmap_as(benchmark::State& state, const char* extension) {
  const Heightfield& heights = heights_of(static_cast<int>(state.range(0)));
  const auto path = output(extension);
  for (auto _ : state) io::write_heightmap(path, heights);
  finish(state, path, static_cast<double>(heights.size()));
}

void write_mesh_as(benchmark::State& state, const char* extension) {
  const TriangleMesh mesh = mesh::heightfield_to_mesh(heights_of(static_cast<int>(state.range(0))));
  const auto path = output(extension);
  for (auto _ : state) io::write_mesh(path, mesh);
  finish(state, path, static_cast<double>(mesh.positions.size()));
}

void heightfield_to_mesh(benchmark::State& state) {
  const Heightfield& heights = heights_of(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(mesh::heightfield_to_mesh(heights));
  state.SetItemsProcessed(static_cast<std::int64_t>(heights.size()) * state.iterations());
}

void read_heightmap_as(benchmark::State& state, const char* extension) {
  const Heightfield& heights = heights_of(static_cast<int>(state.range(0)));
  const auto path = output(extension);
  io::write_heightmap(path, heights);
  for (auto _ : state) benchmark::DoNotOptimize(io::read_heightmap(path));
  finish(state, path, static_cast<double>(heights.size()));
}

}  // namespace

BENCHMARK(reference_fwrite)->Name("Reference/fwrite")->Arg(8193)->Arg(1025)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, r32, ".r32")->Name("Write/R32")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, raw16, ".raw")->Name("Write/Raw16")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, png16, ".png")->Name("Write/Png16")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(write_heightmap_as, geotiff, ".tif")->Name("Write/GeoTiff")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(read_heightmap_as, png16, ".png")->Name("Read/Png16")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(read_heightmap_as, geotiff, ".tif")->Name("Read/GeoTiff")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(heightfield_to_mesh)->Name("Mesh/Heightfield")->Arg(1025)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(write_mesh_as, glb, ".glb")->Name("Write/Glb")->Arg(1025)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(write_mesh_as, obj, ".obj")->Name("Write/Obj")->Arg(1025)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
