// The parts of a scene beside its ground, put together one way for every front end (the render
// output, the viewer, scenery()): the rock texture on its cliffs, its sky (the cloud layer and the
// baked dome), its rivers and lakes where it draws them, and its plants, kept out of that water.
// With an evaluator, each part is kept in the evaluator's memory under the text of everything it
// is made from (SceneKeys), with the graph's results and in their budget: a front end that asks
// again for a part whose key is unchanged (the viewer, going back to an earlier value) gets it at
// once, and the viewer keeps no cache of its own.
#pragma once

#include <memory>
#include <string>

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/sky_dome.hpp"
#include "scene/evaluator.hpp"
#include "scene/recipe.hpp"
#include "scene/water_layers.hpp"
#include "vegetation/placement.hpp"

namespace sansui::scene {

/// The sky: the cloud layer (empty for a clear sky) and the dome baked with it.
struct SceneSky {
  Grid<float> clouds;
  look::SkyDome dome;
};
/// The sky dome's size, as every front end bakes it (the viewer shows the picture the CLI makes).
inline constexpr int sky_dome_width = 1024, sky_dome_height = 256;

/// The text of everything each part is made from. What stands on the terrain has the heights' key
/// in its own, and the plants the water's where the scene draws water (they are kept out of it).
struct SceneKeys {
  std::string heights, rock, sky, water, plants;
};
/// The keys of `recipe`'s parts on heights of key `heights_key` (as `recipe_heights` makes
/// them: terrain_key()). Throws InputError when its look cannot be resolved.
SceneKeys scene_keys(const Recipe& recipe, std::string heights_key);

/// Where the parts are kept: an evaluator and the keys of the parts asked for (scene_keys); no
/// evaluator: made anew each time.
struct PartsCache {
  Evaluator* evaluator = nullptr;
  SceneKeys keys;
};

/// The cliffs' rock texture (solid::rock_albedo): empty where the recipe has none.
std::shared_ptr<const Image> scene_rock(const Recipe& recipe, const Heightfield& heights, const PartsCache& cache, const Context& context);
/// The sky of a resolved recipe (`looked`, scene::resolve_look).
std::shared_ptr<const SceneSky> scene_sky(const Recipe& looked, const PartsCache& cache, const Context& context);
/// Rivers, lakes and wetness where the scene draws them (draws_surface_water(recipe)); else an
/// empty SurfaceWater.
std::shared_ptr<const SurfaceWater> scene_water(const Recipe& recipe, const Heightfield& heights, const PartsCache& cache,
                                                const Context& context);
/// The plants a picture of the whole terrain draws (plants_to_draw of `looked`), without those
/// standing in `water` (null or empty: none taken out).
std::shared_ptr<const vegetation::Placement> scene_plants(const Recipe& looked, const Heightfield& heights, const SurfaceWater* water,
                                                          const PartsCache& cache, const Context& context);

}  // namespace sansui::scene
