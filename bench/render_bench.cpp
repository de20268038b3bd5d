// Headless rendering of a 1025x1025 terrain at 1280x720 (issue 3: under 3 s including
// start-up), whole and stage by stage. Run: build/bench/bench_render
// Wall-clock times (UseRealTime): llvmpipe draws on its own threads.
#include <cstdlib>

#include <epoxy/gl.h>

#include <benchmark/benchmark.h>

#include "render/headless_context.hpp"
#include "render/horizon_shading.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_image.hpp"
#include "render/terrain_renderer.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::render {
namespace {

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

}  // namespace
}  // namespace sansui::render

BENCHMARK_MAIN();
