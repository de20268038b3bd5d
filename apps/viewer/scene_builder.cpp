#include "viewer/scene_builder.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <exception>
#include <utility>

#include "core/context.hpp"
#include "core/error.hpp"
#include "look/render_params.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/water_layers.hpp"
#include "solid/rock_albedo.hpp"

namespace sansui::viewer {
namespace {

bool one_of(std::string_view section, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), section) != names.end();
}

// Sky dome size: as `sansui render` bakes it, so the viewer shows the picture the CLI makes.
constexpr int sky_width = 1024, sky_height = 256;

}  // namespace

Stale stale_after_change(std::string_view key) {
  if (key == "source") return {true, true, true, false, true};
  const std::string_view section = scene::section_of(key);
  Stale stale;
  // Sections only drawn (colours, camera, exaggeration) or only read by outputs the viewer
  // does not show make nothing stale: the next frame draws them.
  if (section == "flow" || key == "render.draw_water" || key == "render.sea" || key == "render.sea_level") {
    stale.water = true;
    return stale;
  }
  if (one_of(section, {"render", "camera", "sea", "atmosphere", "map", "solid", "solid_field", "heightmap_output", "compare", "output"}))
    return stale;
  if (section == "rock") {
    stale.rock = true;
    return stale;
  }
  const bool look = one_of(section, {"climate", "season", "weather"});
  // Of the land's values only the lines move plants (trees end at the tree line); colours are drawn.
  stale.plants = look || one_of(section, {"vegetation", "tree"}) || key == "land.tree_line" || key == "land.snow_line";
  if (section == "land" && !stale.plants) return stale;
  stale.sky = look || one_of(section, {"time", "sky"});
  if (stale.plants || stale.sky) return stale;
  // A section of the source: the terrain itself changes, and what stands on it; the sky does not.
  return {true, true, true, false, true};
}

SceneBuilder::~SceneBuilder() {
  cancel_ = true;
  if (worker_.joinable()) worker_.join();
}

void SceneBuilder::request(const scene::Recipe& recipe, Stale stale, std::shared_ptr<const Heightfield> heights) {
  if (!heights) stale = Stale::all();
  if (stale.heights) heights.reset();
  if (running_) {
    // What a cancelled build had to do is still to do.
    const Stale pending = stale | (stale.heights ? running_->stale : Stale{}) | (waiting_ ? waiting_->stale : Stale{});
    waiting_ = Job{recipe, pending, pending.heights ? nullptr : std::move(heights)};
    // New heights make the running build worthless: stop it. Anything else (the sun moving
    // through an animated day) lets it finish, so that a stream of changes still shows.
    if (stale.heights) cancel_ = true;
    return;
  }
  start(Job{recipe, stale, std::move(heights)});
}

void SceneBuilder::start(Job job) {
  cancel_ = false;
  done_ = false;
  running_ = std::move(job);
  {
    const std::lock_guard lock(mutex_);
    stage_ = "starting";
    fraction_ = 0.0;
  }
  worker_ = std::thread([this] { run(*running_); });
}

bool SceneBuilder::busy() const {
  return running_.has_value() || waiting_.has_value();
}

std::pair<std::string, double> SceneBuilder::progress() const {
  const std::lock_guard lock(mutex_);
  return {stage_, fraction_};
}

std::optional<SceneBuild> SceneBuilder::take() {
  if (!running_ || !done_) return std::nullopt;
  worker_.join();
  running_.reset();
  std::optional<SceneBuild> result;
  {
    const std::lock_guard lock(mutex_);
    result = std::move(result_);
    result_.reset();
  }
  if (waiting_) {
    Job next = std::move(*waiting_);
    waiting_.reset();
    // A finished build's heights serve the next one when only the look changed.
    if (!next.stale.heights && result && result->heights) next.heights = result->heights;
    if (!next.heights) next.stale = Stale::all();
    start(std::move(next));
    if (result && result->error.empty()) return result;  // still show what finished
    return std::nullopt;
  }
  return result;
}

void SceneBuilder::run(const Job& job) {
  const auto start = std::chrono::steady_clock::now();
  Context context;
  context.cancel = &cancel_;
  context.on_progress = [this](std::string_view stage, double fraction) {
    const std::lock_guard lock(mutex_);
    stage_ = std::string(stage);
    fraction_ = fraction;
  };
  SceneBuild build;
  build.built = job.stale;
  try {
    build.heights = job.stale.heights ? std::make_shared<const Heightfield>(scene::recipe_heights(job.recipe, context)) : job.heights;
    build.looked = job.recipe;
    scene::resolve_look(build.looked);
    const Heightfield& heights = *build.heights;
    if (job.stale.rock) build.rock = solid::rock_albedo(heights, job.recipe.rock, context);
    if (job.stale.sky) {
      build.clouds = scene::scene_clouds(build.looked, context);
      const look::RenderParams resolved = look::with_fallbacks(build.looked.render);
      build.sky = look::bake_sky_dome(resolved, build.clouds->empty() ? nullptr : &*build.clouds, sky_width, sky_height, context);
    }
    // Plants are kept out of rivers and lakes, so new plants need the water too.
    const bool draws_water = scene::draws_surface_water(job.recipe);
    if (job.stale.water || (job.stale.plants && draws_water)) {
      build.built.water = true;
      build.water = draws_water ? scene::scene_surface_water(job.recipe, heights, context) : water::SurfaceWater{};
    }
    if (job.stale.plants) {
      build.plants = scene::plants_to_draw(build.looked, heights, context);
      if (build.water) scene::remove_plants_in_water(*build.plants, *build.water);
    }
  } catch (const Cancelled&) {
    done_ = true;
    return;
  } catch (const std::exception& e) {
    build = SceneBuild{};
    build.error = e.what();
  }
  build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  {
    const std::lock_guard lock(mutex_);
    result_ = std::move(build);
  }
  done_ = true;
}

}  // namespace sansui::viewer
