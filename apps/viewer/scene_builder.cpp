#include "viewer/scene_builder.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "core/context.hpp"
#include "core/error.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/water_layers.hpp"

namespace sansui::viewer {
namespace {

// Terrains and parts the evaluator keeps for going back: a 1025² grid is 4 MB, so about a hundred.
constexpr std::size_t kept_terrain_bytes = std::size_t{512} << 20;

}  // namespace

BuildKeys build_keys(const scene::Recipe& recipe) {
  return scene::scene_keys(recipe, scene::terrain_key(recipe));
}

Stale stale_between(const BuildKeys& built, const BuildKeys& wanted) {
  return {built.heights != wanted.heights, built.rock != wanted.rock, built.plants != wanted.plants, built.sky != wanted.sky,
          built.water != wanted.water};
}

SceneBuilder::SceneBuilder() : evaluator_(std::make_shared<scene::Evaluator>()) {
  evaluator_->keep_in_memory(kept_terrain_bytes);
}

SceneBuilder::~SceneBuilder() {
  cancel_ = true;
  if (worker_.joinable()) worker_.join();
}

Stale SceneBuilder::request(const scene::Recipe& recipe) {
  Job job{recipe, build_keys(recipe), {}, generation_};
  const Stale stale = stale_between(built_, job.keys);
  if (running_) {
    // A new terrain makes the running build worthless: stop it. Anything else (the sun moving
    // through an animated day) lets it finish, so that a stream of changes still shows. The
    // newest request waits; what it needs is worked out when it starts.
    if (running_->keys.heights != job.keys.heights) cancel_ = true;
    waiting_ = std::move(job);
    return stale;
  }
  if (stale.any()) start(std::move(job));
  return stale;
}

void SceneBuilder::forget() {
  ++generation_;
  built_ = {};
  evaluator_->forget_memory();
  if (running_) cancel_ = true;
}

void SceneBuilder::start(Job job) {
  job.stale = stale_between(built_, job.keys);
  if (!job.stale.any()) return;
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
  const Job finished = std::move(*running_);
  running_.reset();
  std::optional<SceneBuild> result;
  {
    const std::lock_guard lock(mutex_);
    result = std::move(result_);
    result_.reset();
  }
  // What was built is now what the next request is compared with (a cancelled build built
  // nothing; a scene opened since then starts afresh).
  if (result && result->error.empty() && finished.generation == generation_) {
    const Stale& built = result->built;
    if (built.heights) built_.heights = finished.keys.heights;
    if (built.rock) built_.rock = finished.keys.rock;
    if (built.sky) built_.sky = finished.keys.sky;
    if (built.water) built_.water = finished.keys.water;
    if (built.plants) built_.plants = finished.keys.plants;
  }
  if (waiting_) {
    Job next = std::move(*waiting_);
    waiting_.reset();
    start(std::move(next));
    if (result && result->error.empty() && finished.generation == generation_) return result;  // still show what finished
    return std::nullopt;
  }
  if (finished.generation != generation_) return std::nullopt;
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
    // Unchanged heights come from the evaluator's memory at once.
    build.heights = scene::recipe_heights(job.recipe, *evaluator_, context);
    build.looked = job.recipe;
    scene::resolve_look(build.looked);
    const Heightfield& heights = *build.heights;
    const scene::PartsCache cache{evaluator_.get(), job.keys};
    if (job.stale.rock) build.rock = scene::scene_rock(job.recipe, heights, cache, context);
    if (job.stale.sky) build.sky = scene::scene_sky(build.looked, cache, context);
    // Plants are kept out of rivers and lakes, so new plants need the water too.
    if (job.stale.water || (job.stale.plants && scene::draws_surface_water(job.recipe))) {
      build.built.water = true;
      build.water = scene::scene_water(job.recipe, heights, cache, context);
    }
    if (job.stale.plants) build.plants = scene::scene_plants(build.looked, heights, build.water.get(), cache, context);
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
