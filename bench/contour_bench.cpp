// Contour generation speed (issue 4), with Clipper's own offset of the same polygons measured in
// the same run as the reference:
//  - Mountain_Revised: a whole mountain from a 1000-vertex seed, about 60 levels inward, revised
//    method with the paper's defaults; counters give the seconds of each step per mountain;
//  - Mountain_1000Levels, Coastline_500km (issue 17): 1,000 levels of a 1,000-vertex seed, and a
//    700-vertex coastline 500 km across with the offset derived from its size (scale.hpp);
//  - ClipperOffset_SameRings: ClipperOffset (miter joins + its own union) of every contour of that
//    mountain by the same d: the bare polygon offset our offset+union step is compared with;
//  - ContoursToDem: that mountain rasterised at 2049 x 2049 with 1 and 2 threads;
//  - Offset100k/JOIN: offset (raw curve + positive union) of a 100,000-vertex polygon with each join,
//    beside ClipperOffset of the same polygon.
// Run: build/bench/bench_contour --benchmark_counters_tabular=true
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>
#include <polyclipping/clipper.hpp>
#include <tbb/task_arena.h>

#include "contour/clipping.hpp"
#include "contour/fourier.hpp"
#include "contour/generate.hpp"
#include "contour/midpoint.hpp"
#include "contour/scale.hpp"
#include "contour/shrink.hpp"
#include "contour/to_dem.hpp"
#include "core/random.hpp"

namespace {

using namespace sansui;
using namespace sansui::contour;

/// A rugged star-shaped seed: radius ~1000 m modulated by random harmonics, `vertices` points.
Ring rugged_seed(int vertices, double radius = 1000.0) {
  Ring ring;
  const std::uint64_t key = rng::stream_key(2024, 7);
  constexpr int harmonics = 24;
  double amplitude[harmonics], phase[harmonics];
  for (int k = 0; k < harmonics; ++k) {
    amplitude[k] = 0.35 * rng::to_uniform(rng::bits(key, rng::pack(k, 0))) / (1.0 + 0.6 * k);
    phase[k] = 2.0 * std::numbers::pi * rng::to_uniform(rng::bits(key, rng::pack(k, 1)));
  }
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * std::numbers::pi * i / vertices;
    double r = 1.0;
    for (int k = 0; k < harmonics; ++k) r += amplitude[k] * std::cos((k + 2) * a + phase[k]);
    ring.push_back({radius * r * std::cos(a), radius * 0.8 * r * std::sin(a)});
  }
  return ring;
}

GenerationParams mountain_params() {
  GenerationParams p;  // revised, the paper's defaults
  p.offset_m = 10.0;
  p.interval_m = 10.0;
  return p;
}

const ContourTree& the_mountain() {
  static const ContourTree tree = generate_contours(rugged_seed(1000), mountain_params());
  return tree;
}

/// Generates the mountain of `seed` with `params` in a loop; counters give the seconds of each step.
void run_mountain(benchmark::State& state, const Ring& seed, const GenerationParams& params) {
  GenerationTimes total;
  std::size_t contours = 0;
  int levels = 0;
  for (auto _ : state) {
    const ContourTree tree = generate_contours(seed, params, quiet_context(), &total);
    contours = tree.nodes.size();
    levels = 0;
    for (const ContourNode& n : tree.nodes) levels = std::max(levels, n.level);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["contours"] = static_cast<double>(contours);
  state.counters["levels"] = levels;
  state.counters["vertices"] = static_cast<double>(seed.size());
  state.counters["offset+union_s"] = total.offset_s / n;
  state.counters["midpoint_s"] = total.midpoint_s / n;
  state.counters["fourier_s"] = total.fourier_s / n;
  state.counters["decimate_s"] = total.decimate_s / n;
  state.counters["loops_s"] = total.loops_s / n;
  state.counters["clip_s"] = total.clip_s / n;
}

void Mountain_Revised(benchmark::State& state) {
  run_mountain(state, rugged_seed(1000), mountain_params());
}

/// Issue 17: 1,000 levels of a 1,000-vertex seed (20 km across, d = inradius / 1000).
void Mountain_1000Levels(benchmark::State& state) {
  const Ring seed = rugged_seed(1000, 10000.0);
  GenerationParams p = mountain_params();
  p.offset_m = inradius(seed) / 1000.0;
  run_mountain(state, seed, p);
}

/// Issue 17: a 700-vertex coastline 500 km across with the offset derived from its size.
void Coastline_500km(benchmark::State& state) {
  const Ring seed = rugged_seed(700, 250000.0);
  GenerationParams p = mountain_params();
  p.offset_m = derived_offset_m(seed, p.interval_m);
  run_mountain(state, seed, p);
}

ClipperLib::Path to_path(const Ring& ring) {
  ClipperLib::Path path;
  for (const Point& p : ring)
    path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p.x * clipper_units_per_metre)),
                      static_cast<ClipperLib::cInt>(std::llround(p.y * clipper_units_per_metre)));
  return path;
}

void ClipperOffset_SameRings(benchmark::State& state) {
  const ContourTree& tree = the_mountain();
  std::vector<ClipperLib::Path> paths;
  for (const ContourNode& n : tree.nodes) paths.push_back(to_path(n.ring));
  for (auto _ : state)
    for (const auto& path : paths) {
      ClipperLib::ClipperOffset offset(3.0);
      offset.AddPath(path, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
      ClipperLib::Paths out;
      offset.Execute(out, -10.0 * clipper_units_per_metre);
      benchmark::DoNotOptimize(out);
    }
  state.counters["rings"] = static_cast<double>(paths.size());
}

void OurOffset_SameRings(benchmark::State& state) {
  const ContourTree& tree = the_mountain();
  OffsetParams params{10.0, Join::clipped, 3.0, 15.0, false, {}};
  for (auto _ : state)
    for (const ContourNode& n : tree.nodes) benchmark::DoNotOptimize(offset_ring(n.ring, params));
  state.counters["rings"] = static_cast<double>(tree.nodes.size());
}

void ContoursToDem(benchmark::State& state) {
  const ContourTree& tree = the_mountain();
  DemParams params = dem_frame_for(tree, static_cast<int>(state.range(0)));
  params.offset_m = 10.0;
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(contours_to_dem(tree, params)); });
  state.counters["Mcells/s"] =
      benchmark::Counter(double(params.width) * params.height * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

/// A 100,000-vertex contour about 16 km across: the rugged seed with midpoint-displaced detail
/// resampled to exactly 100,000 vertices, so that it has reflex and convex corners at every scale.
const Ring& big_polygon() {
  static const Ring ring = [] {
    const Ring coarse = rugged_seed(1000, 8000.0);
    const Ring fine = displace_midpoints(coarse, {0.5 * perimeter(coarse) / 100000.0, 3.0, 10.0, 40.0, {}}, 11, 12);
    return resample_closed(fine, 100000);
  }();
  return ring;
}

void Offset100k(benchmark::State& state) {
  const auto join = static_cast<contour::Join>(state.range(0));
  state.SetLabel(std::string(name_of(join)));
  const OffsetParams params{20.0, join, 1.4, 15.0, false, {}};
  std::size_t rings = 0;
  for (auto _ : state) rings = offset_ring(big_polygon(), params).size();
  state.counters["vertices"] = static_cast<double>(big_polygon().size());
  state.counters["islands"] = static_cast<double>(rings);
}

void Offset100k_ClipperOffsetMiter(benchmark::State& state) {
  const ClipperLib::Path path = to_path(big_polygon());
  for (auto _ : state) {
    ClipperLib::ClipperOffset offset(1.4);
    offset.AddPath(path, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::Paths out;
    offset.Execute(out, -20.0 * clipper_units_per_metre);
    benchmark::DoNotOptimize(out);
  }
}

BENCHMARK(Mountain_Revised)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(Mountain_1000Levels)->Unit(benchmark::kMillisecond)->Iterations(2)->UseRealTime();
BENCHMARK(Coastline_500km)->Unit(benchmark::kMillisecond)->Iterations(2)->UseRealTime();
BENCHMARK(OurOffset_SameRings)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(ClipperOffset_SameRings)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(ContoursToDem)->Args({2049, 1})->Args({2049, 2})->Args({1025, 2})->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(Offset100k)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();
BENCHMARK(Offset100k_ClipperOffsetMiter)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
