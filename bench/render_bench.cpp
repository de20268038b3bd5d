// Headless rendering of a 1025x1025 terrain at 1280x720 (issue 3: under 3 s including
// start-up), whole and stage by stage; and of a forest (issue 11: a 1920x1080 picture of a 4097^2
// terrain with at least 200,000 visible trees in under 10 s), with the time split by stage.
// Run: build/bench/bench_render [--benchmark_filter=Forest --benchmark_counters_tabular=true]
// Wall-clock times (UseRealTime): llvmpipe draws on its own threads.
#include <chrono>
#include <cstdlib>

#include <epoxy/gl.h>

#include <benchmark/benchmark.h>

#include "look/horizon_shading.hpp"
#include "render/headless_context.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_image.hpp"
#include "render/terrain_renderer.hpp"
#include "terrain/midpoint.hpp"
#include "vegetation/placement.hpp"

namespace sansui::render {
namespace {

using namespace look;  // the look the renderer draws

/// The main job's terrain: 1025x1025, 10 m cells, default parameters.
const Heightfield& terrain_1025() {
  static const Heightfield heights = [] {
    Heightfield h = terrain::generate_midpoint(terrain::MidpointParams{}, 1025);
    h.cell_size_m = 10.0;
    return h;
  }();
  return heights;
}

RenderParams params_with_samples(int samples) {
  RenderParams params;
  params.samples = samples;
  return params;
}

/// Everything a `sansui render` does after reading the file: context, shaders, upload,
/// shadows and occlusion, draw, read back.
void BM_RenderHeadless(benchmark::State& state) {
  ::unsetenv("DISPLAY");
  const Heightfield& heights = terrain_1025();
  const RenderParams params = params_with_samples(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(render_image(heights, params));
  state.SetLabel("1025^2 terrain, 1280x720, samples " + std::to_string(state.range(0)));
}
BENCHMARK(BM_RenderHeadless)->Arg(4)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

/// The reference point of the same run: generating the terrain that is drawn.
void BM_Reference_GenerateTerrain(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(terrain::generate_midpoint(terrain::MidpointParams{}, 1025));
}
BENCHMARK(BM_Reference_GenerateTerrain)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_Stage_ContextCreation(benchmark::State& state) {
  ::unsetenv("DISPLAY");
  for (auto _ : state) {
    const HeadlessContext context;
    benchmark::DoNotOptimize(&context);
  }
}
BENCHMARK(BM_Stage_ContextCreation)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_Stage_CompileShaders(benchmark::State& state) {
  const HeadlessContext context;
  for (auto _ : state) {
    TerrainRenderer renderer;
    glFinish();
  }
}
BENCHMARK(BM_Stage_CompileShaders)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_Stage_SunVisibility(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sun_visibility(terrain_1025(), {300.0, 32.0, 1.5, 1.2}));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 1025 * 1025);
}
BENCHMARK(BM_Stage_SunVisibility)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Stage_AmbientOcclusion(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(ambient_occlusion(terrain_1025(), {1.5, 64}));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 1025 * 1025);
}
BENCHMARK(BM_Stage_AmbientOcclusion)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Upload with shading (the first draw traces shadows and occlusion), in a warm context.
void BM_Stage_UploadAndShade(benchmark::State& state) {
  const HeadlessContext context;
  const OffscreenTarget target(64, 64, 1);
  TerrainRenderer renderer;
  const RenderParams params = with_fallbacks({});
  renderer.set_sky(bake_sky_dome(params, nullptr), params);
  for (auto _ : state) {
    renderer.set_terrain(terrain_1025(), params);
    renderer.draw(params, 64, 64);
    glFinish();
  }
}
BENCHMARK(BM_Stage_UploadAndShade)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

/// Drawing and reading back, terrain already uploaded and shaded: what the viewer pays per frame.
void BM_Stage_DrawAndReadBack(benchmark::State& state) {
  const HeadlessContext context;
  const RenderParams params = with_fallbacks(params_with_samples(static_cast<int>(state.range(0))));
  const OffscreenTarget target(params.width, params.height.value_or(720), params.samples);
  TerrainRenderer renderer;
  renderer.set_terrain(terrain_1025(), params);
  renderer.set_sky(bake_sky_dome(params, nullptr), params);
  renderer.draw(params, params.width, params.height.value_or(720));
  for (auto _ : state) {
    target.bind();
    renderer.draw(params, params.width, params.height.value_or(720));
    benchmark::DoNotOptimize(target.read_pixels());
  }
}
BENCHMARK(BM_Stage_DrawAndReadBack)->Arg(4)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

/// The forest: the default midpoint world at 4097^2 and 4 m cells (16 km across, as
/// bench/vegetation_bench.cpp), sea level 0, tree line 900 m, the Cfb (oceanic) species on a 10 m
/// grid at density 0.5: about 1.1 million trees.
struct Forest {
  Heightfield heights;
  vegetation::Placement plants;
};
const Forest& forest_4097() {
  static const Forest forest = [] {
    Forest f{terrain::generate_midpoint(terrain::MidpointParams{}, 4097), {}};
    f.heights.cell_size_m = 4.0;
    vegetation::PlacementRules rules;
    rules.tree_density = 0.5;
    rules.tree_line_m = 900.0;
    rules.species = vegetation::species_of_climate("Cfb");
    vegetation::VegetationParams params;
    params.spacing_m = 10.0;
    f.plants = vegetation::place_plants(f.heights, params, rules);
    return f;
  }();
  return forest;
}

/// What a `sansui render` of the forest does after placing it, stage by stage: context and
/// shaders, terrain upload, plants (meshes, impostor atlas, placing them on the drawn ground),
/// sky, the draw (shadows and occlusion, terrain, plants: selection and drawing, sky), read back.
/// Arg 0: the fitted camera (the whole terrain; every tree a few pixels tall); arg 1: a camera
/// close over the forest (trees up to a hundred pixels tall in front, meshes and impostors).
void BM_RenderForest(benchmark::State& state) {
  ::unsetenv("DISPLAY");
  const Forest& forest = forest_4097();
  RenderParams given;
  given.width = 1920;
  given.height = 1080;
  if (state.range(0) == 1) {
    given.camera.distance = 0.12;
    given.camera.elevation_deg = 15.0;
  }
  const RenderParams params = with_fallbacks(given);
  using Clock = std::chrono::steady_clock;
  auto lap = [](Clock::time_point& since) {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - since).count();
    since = now;
    return seconds;
  };
  double context_s = 0, terrain_s = 0, plants_s = 0, sky_s = 0, draw_s = 0, read_s = 0, total_s = 0;
  PlantStats stats;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    Clock::time_point t = start;
    const HeadlessContext context;
    const OffscreenTarget target(params.width, *params.height, params.samples);
    TerrainRenderer renderer;
    renderer.set_plant_timing(true);
    context_s += lap(t);
    renderer.set_terrain(forest.heights, params);
    terrain_s += lap(t);
    look::PlantKindCache kinds;  // models built afresh each run, as a first render builds them
    renderer.set_plants(kinds.plants_to_draw(forest.plants, {}));
    plants_s += lap(t);
    renderer.set_sky(bake_sky_dome(params, nullptr), params);
    sky_s += lap(t);
    target.bind();
    renderer.draw(params, params.width, *params.height);
    glFinish();
    draw_s += lap(t);
    benchmark::DoNotOptimize(target.read_pixels());
    read_s += lap(t);
    total_s += std::chrono::duration<double>(Clock::now() - start).count();
    stats = renderer.plant_stats();
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["total_s"] = total_s / n;
  state.counters["context_s"] = context_s / n;
  state.counters["terrain_s"] = terrain_s / n;
  state.counters["plants_s"] = plants_s / n;
  state.counters["mesh_build_s"] = stats.build_s;
  state.counters["atlas_s"] = stats.atlas_s;
  state.counters["plant_upload_s"] = stats.upload_s;
  state.counters["sky_s"] = sky_s / n;
  state.counters["draw_s"] = draw_s / n;
  state.counters["lod_select_s"] = stats.select_s;
  state.counters["plant_draw_s"] = stats.draw_s;
  state.counters["read_s"] = read_s / n;
  state.counters["trees"] = static_cast<double>(stats.plants);
  state.counters["drawn"] = static_cast<double>(stats.full + stats.simplified + stats.impostors + stats.sprites);
  state.counters["full"] = static_cast<double>(stats.full);
  state.counters["simplified"] = static_cast<double>(stats.simplified);
  state.counters["impostors"] = static_cast<double>(stats.impostors);
  state.counters["sprites"] = static_cast<double>(stats.sprites);
  state.counters["culled"] = static_cast<double>(stats.culled);
  state.counters["thinned"] = static_cast<double>(stats.thinned);
  state.SetLabel(state.range(0) == 1 ? "4097^2 forest, 1920x1080, close camera" : "4097^2 forest, 1920x1080, fitted camera");
}
BENCHMARK(BM_RenderForest)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// The forest's placement alone, for reference (its own benchmark: bench/vegetation_bench.cpp).
void BM_Reference_PlaceForest(benchmark::State& state) {
  const Forest& forest = forest_4097();
  vegetation::PlacementRules rules;
  rules.tree_density = 0.5;
  rules.tree_line_m = 900.0;
  rules.species = vegetation::species_of_climate("Cfb");
  vegetation::VegetationParams params;
  params.spacing_m = 10.0;
  for (auto _ : state) benchmark::DoNotOptimize(vegetation::place_plants(forest.heights, params, rules));
}
BENCHMARK(BM_Reference_PlaceForest)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace
}  // namespace sansui::render

BENCHMARK_MAIN();
