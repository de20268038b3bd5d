// Builds what the viewer draws from a recipe on a worker thread, so the window never freezes
// while a terrain regenerates: the heightfield (the recipe's source and shaping steps or graph,
// through the library's evaluator, as `sansui run` makes it), the rock texture, the sky dome,
// rivers and lakes, and the plants (scene/scene_parts.hpp, as the render output makes them). Each
// of them has a key, the text of everything it is made from; a request rebuilds exactly those
// whose keys changed. The evaluator keeps earlier terrains and parts in memory (the viewer keeps
// no cache of its own), so going back to an earlier value shows it at once. A new request cancels
// the build in flight (at its next progress check) when the terrain changes; OpenGL uploads
// stay on the window's thread.
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
#include "scene/evaluator.hpp"
#include "scene/plants.hpp"
#include "scene/recipe.hpp"
#include "scene/scene_parts.hpp"
#include "scene/water_layers.hpp"

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

/// The key of each thing the viewer builds: what it is made from, as text (scene/scene_parts.hpp).
using BuildKeys = scene::SceneKeys;

/// The keys of what `recipe` draws: its terrain's (scene::terrain_key) and its parts'. Throws
/// InputError when its look cannot be resolved.
BuildKeys build_keys(const scene::Recipe& recipe);

/// What has to be built to go from what `built` was made from to `wanted`.
Stale stale_between(const BuildKeys& built, const BuildKeys& wanted);

/// A finished build. Only what was stale is set.
struct SceneBuild {
  Stale built;
  std::shared_ptr<const Heightfield> heights;  ///< the heights everything else was built on
  scene::Recipe looked;                        ///< the recipe with its look resolved (scene/look.hpp)
  /// The scene's parts (scene/scene_parts.hpp), shared with the evaluator's memory, which keeps
  /// them for going back.
  std::shared_ptr<const Image> rock;
  std::shared_ptr<const scene::SceneSky> sky;
  std::shared_ptr<const scene::Plants> plants;
  /// Rivers and lakes, when the scene draws them (scene/water_layers.hpp); with `water` stale
  /// and the scene not drawing them, an empty SurfaceWater.
  std::shared_ptr<const scene::SurfaceWater> water;
  double seconds = 0.0;  ///< wall time of the build
  std::string error;     ///< the recipe could not be built: what was wrong (nothing else is set)
};

class SceneBuilder {
 public:
  SceneBuilder();
  ~SceneBuilder();
  SceneBuilder(const SceneBuilder&) = delete;
  SceneBuilder& operator=(const SceneBuilder&) = delete;

  /// Builds for `recipe` what differs from the last finished build, and returns what that is.
  /// Throws InputError when the recipe's look cannot be resolved (nothing is requested).
  Stale request(const scene::Recipe& recipe);
  /// Forgets what was built and the terrains kept: the next request builds everything, and
  /// reads the source's files again (a scene opened anew).
  void forget();
  /// The finished build, once; starts a waiting request. Call every frame.
  std::optional<SceneBuild> take();
  /// True while a build runs or waits.
  bool busy() const;
  /// The running build's stage and fraction done.
  std::pair<std::string, double> progress() const;

 private:
  struct Job {
    scene::Recipe recipe;
    BuildKeys keys;
    Stale stale;  ///< what differs from built_ when it starts
    std::uint64_t generation = 0;
  };
  void start(Job job);
  void run(const Job& job);

  std::thread worker_;
  std::atomic<bool> cancel_{false}, done_{false};
  std::optional<Job> running_, waiting_;
  BuildKeys built_;               ///< what the things last built were made from (empty: not built)
  std::uint64_t generation_ = 0;  ///< counts forget(): a build from before it is not kept
  std::shared_ptr<scene::Evaluator> evaluator_;
  mutable std::mutex mutex_;  // guards stage_, fraction_, result_
  std::string stage_;
  double fraction_ = 0.0;
  std::optional<SceneBuild> result_;
};

}  // namespace sansui::viewer
