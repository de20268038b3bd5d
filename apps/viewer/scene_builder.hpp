// Builds what the viewer draws from a recipe on a worker thread, so the window never freezes
// while a terrain regenerates: the heightfield (the recipe's source and shaping steps, the same
// library pipeline `sansui run` runs), the rock texture, the sky dome and the plants. A new
// request cancels the build in flight (at its next progress check) and takes over what it
// still had to do; OpenGL uploads stay on the window's thread.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/color.hpp"
#include "core/grid.hpp"
#include "look/sky_dome.hpp"
#include "scene/recipe.hpp"
#include "vegetation/placement.hpp"
#include "water/surface_water.hpp"

namespace sansui::viewer {

/// What a change of the recipe makes stale. Merged with |.
struct Stale {
  bool heights = false;  ///< the source or the shaping steps changed
  bool rock = false;     ///< the rock texture on cliffs
  bool plants = false;   ///< where plants stand and how they look
  bool sky = false;      ///< the sky dome: sun, haze, clouds
  bool water = false;    ///< rivers and lakes

  bool any() const { return heights || rock || plants || sky || water; }
  Stale operator|(const Stale& other) const {
    return {heights || other.heights, rock || other.rock, plants || other.plants, sky || other.sky, water || other.water};
  }
  static Stale all() { return {true, true, true, true, true}; }
};

/// What a change of the value of `key` (a key of scene::recipe_table(), "section.key") makes stale.
Stale stale_after_change(std::string_view key);

/// A finished build. Only what was stale is set.
struct SceneBuild {
  Stale built;
  std::shared_ptr<const Heightfield> heights;  ///< the heights everything else was built on
  scene::Recipe looked;                        ///< the recipe with its look resolved (scene/look.hpp)
  std::optional<Image> rock;
  std::optional<Grid<float>> clouds;
  std::optional<look::SkyDome> sky;
  std::optional<vegetation::Placement> plants;
  /// Rivers and lakes, when the scene draws them (scene/water_layers.hpp); with `water` stale
  /// and the scene not drawing them, an empty SurfaceWater.
  std::optional<water::SurfaceWater> water;
  double seconds = 0.0;  ///< wall time of the build
  std::string error;     ///< the recipe could not be built: what was wrong (nothing else is set)
};

class SceneBuilder {
 public:
  SceneBuilder() = default;
  ~SceneBuilder();
  SceneBuilder(const SceneBuilder&) = delete;
  SceneBuilder& operator=(const SceneBuilder&) = delete;

  /// Builds what `stale` says for `recipe`; `heights` are the current ones (used when the
  /// heights are not stale; null forces them to be built).
  void request(const scene::Recipe& recipe, Stale stale, std::shared_ptr<const Heightfield> heights);
  /// The finished build, once; starts a waiting request. Call every frame.
  std::optional<SceneBuild> take();
  /// True while a build runs or waits.
  bool busy() const;
  /// The running build's stage and fraction done.
  std::pair<std::string, double> progress() const;

 private:
  struct Job {
    scene::Recipe recipe;
    Stale stale;
    std::shared_ptr<const Heightfield> heights;
  };
  void start(Job job);
  void run(const Job& job);

  std::thread worker_;
  std::atomic<bool> cancel_{false}, done_{false};
  std::optional<Job> running_, waiting_;
  mutable std::mutex mutex_;  // guards stage_, fraction_, result_
  std::string stage_;
  double fraction_ = 0.0;
  std::optional<SceneBuild> result_;
};

}  // namespace sansui::viewer
