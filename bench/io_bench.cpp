// File-format writers against the floor of the machine, measured in the same run: every writer
// benchmark times, beside each write, one plain write(2) of the same number of bytes from memory
// to the same directory (the best the page cache and disk allow), and reports the ratio as
// `x_plain` (1.0 = at disk speed) with both throughputs.
//   build/bench/bench_io --benchmark_filter='Write/.*/8193'   # heightmaps, 8193 x 8193
//   build/bench/bench_io --benchmark_filter='Write/(Glb|Obj)'  # meshes of 1613^2 (5.2 M triangles) and 1025^2
// Png16None and GeoTiffNone: heightmap_output.compression = none (the others: the default, fast).
// Files go to a fresh directory under $TMPDIR (default /tmp); set TMPDIR to measure another disk.
// Peak memory of one writer: /usr/bin/time -v build/bench/bench_io --benchmark_filter='Write/R32/8193'
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <unistd.h>

#include <benchmark/benchmark.h>
#include <fcntl.h>

#include "core/random.hpp"
#include "io/heightmap_io.hpp"
#include "io/mesh_io.hpp"
#include "mesh/heightfield_mesh.hpp"

namespace {

using namespace sansui;
using Clock = std::chrono::steady_clock;

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

const TriangleMesh& mesh_of(int size) {
  static TriangleMesh cached;
  static int cached_size = 0;
  if (cached_size != size) {
    cached = {};
    cached = mesh::heightfield_to_mesh(heights_of(size));
    cached_size = size;
  }
  return cached;
}

/// The directory every file of the run goes to, removed at exit.
const std::filesystem::path& directory() {
  struct Directory {
    std::filesystem::path path = std::filesystem::temp_directory_path() / ("sansui-bench-io-" + std::to_string(::getpid()));
    Directory() { std::filesystem::create_directories(path); }
    ~Directory() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Directory directory;
  return directory.path;
}

std::filesystem::path output(const char* extension) {
  return directory() / (std::string("out") + extension);
}

/// The floor: open, one write(2) of `bytes` bytes already in memory (a loop only if the kernel
/// writes less at once, as Linux does above 2 GiB), close. Returns seconds.
double plain_write(std::size_t bytes) {
  static std::vector<char> source;
  if (source.size() < bytes) source.assign(bytes, 'S');  // touched once, outside any timing
  const auto path = directory() / "plain.bin";
  const auto start = Clock::now();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw std::runtime_error("bench_io: cannot create " + path.string());
  for (std::size_t done = 0; done < bytes;) {
    const ssize_t written = ::write(fd, source.data() + done, bytes - done);
    if (written <= 0) throw std::runtime_error("bench_io: write failed: " + std::string(std::strerror(errno)));
    done += static_cast<std::size_t>(written);
  }
  ::close(fd);
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::ranges::sort(values);
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Times `write` (the benchmark's time) and, right after each call, a plain write of the bytes it
/// wrote; reports both throughputs, the file size and the ratio of the median times (`x_plain`:
/// the page cache and the other processes of a shared machine make single writes vary by 2x, and
/// the median of alternating pairs is what stays put from run to run).
template <class Write>
void measure(benchmark::State& state, const std::filesystem::path& path, double items, const Write& write) {
  std::vector<double> writer_seconds, plain_seconds;
  std::uintmax_t bytes = 0;
  for (auto _ : state) {
    // Both start with no dirty pages, so neither pays for the other's writeback (the kernel
    // throttles a writer once enough of the page cache is dirty).
    ::sync();
    const auto start = Clock::now();
    write();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    state.SetIterationTime(seconds);
    writer_seconds.push_back(seconds);
    bytes = std::filesystem::file_size(path);
    ::sync();
    plain_seconds.push_back(plain_write(bytes));
  }
  const auto iterations = static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(items * iterations));
  state.SetBytesProcessed(static_cast<std::int64_t>(static_cast<double>(bytes) * iterations));
  state.counters["MiB"] = static_cast<double>(bytes) / (1 << 20);
  state.counters["ms_median"] = 1e3 * median(writer_seconds);
  state.counters["plain_ms_median"] = 1e3 * median(plain_seconds);
  state.counters["plain_MiB/s"] = static_cast<double>(bytes) / median(plain_seconds) / (1 << 20);
  state.counters["x_plain"] = median(writer_seconds) / median(plain_seconds);
  std::filesystem::remove(path);
  std::filesystem::remove(io::sidecar_path(path));
  std::filesystem::remove(directory() / "plain.bin");
}

void write_heightmap_as(benchmark::State& state, const char* extension, io::Compression compression = io::Compression::fast) {
  const Heightfield& heights = heights_of(static_cast<int>(state.range(0)));
  const auto path = output(extension);
  io::HeightmapWriteOptions options;
  options.compression = compression;
  measure(state, path, static_cast<double>(heights.size()), [&] { io::write_heightmap(path, heights, options); });
}

void write_mesh_as(benchmark::State& state, const char* extension) {
  const TriangleMesh& mesh = mesh_of(static_cast<int>(state.range(0)));
  const auto path = output(extension);
  measure(state, path, static_cast<double>(mesh.triangle_count()), [&] { io::write_mesh(path, mesh); });
  state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
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
  state.SetItemsProcessed(static_cast<std::int64_t>(heights.size()) * state.iterations());
  std::filesystem::remove(path);
  std::filesystem::remove(io::sidecar_path(path));
}

}  // namespace

// Heightmaps first, then meshes: each size's data is made once.
BENCHMARK_CAPTURE(write_heightmap_as, r32, ".r32")
    ->Name("Write/R32")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(9);
BENCHMARK_CAPTURE(write_heightmap_as, raw16, ".raw")
    ->Name("Write/Raw16")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(write_heightmap_as, png16, ".png")
    ->Name("Write/Png16")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, geotiff, ".tif")
    ->Name("Write/GeoTiff")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, png16_none, ".png", io::Compression::none)
    ->Name("Write/Png16None")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(write_heightmap_as, geotiff_none, ".tif", io::Compression::none)
    ->Name("Write/GeoTiffNone")
    ->Arg(8193)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(read_heightmap_as, png16, ".png")->Name("Read/Png16")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(read_heightmap_as, geotiff, ".tif")->Name("Read/GeoTiff")->Arg(8193)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(heightfield_to_mesh)->Name("Mesh/Heightfield")->Arg(1025)->Unit(benchmark::kMillisecond)->Iterations(3);
// 1613^2 vertices make 2 * 1612^2 = 5.2 M triangles, the 125 MB .glb.
BENCHMARK_CAPTURE(write_mesh_as, glb, ".glb")
    ->Name("Write/Glb")
    ->Arg(1613)
    ->Arg(1025)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(9);
BENCHMARK_CAPTURE(write_mesh_as, obj, ".obj")
    ->Name("Write/Obj")
    ->Arg(1613)
    ->Arg(1025)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(3);

BENCHMARK_MAIN();
