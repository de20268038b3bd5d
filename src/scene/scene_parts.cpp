#include "scene/scene_parts.hpp"

#include "core/params_text.hpp"
#include "look/render_params.hpp"
#include "scene/look.hpp"
#include "scene/plants.hpp"
#include "solid/rock_albedo.hpp"

namespace sansui::scene {
namespace {

/// `make()` through the evaluator's memory under `key`, or made anew without an evaluator.
template <class T, class Make>
std::shared_ptr<const T> kept(const PartsCache& cache, const char* label, const std::string& key, Make make,
                              std::size_t (*bytes)(const T&)) {
  if (cache.evaluator == nullptr || key.empty()) return std::make_shared<const T>(make());
  return cache.evaluator->product<T>(label, key, make, bytes);
}

std::size_t image_bytes(const Image& image) {
  return image.size() * sizeof(Rgba8);
}

std::size_t sky_bytes(const SceneSky& sky) {
  const look::SkyDome& dome = sky.dome;
  return sky.clouds.size() * sizeof(float) + (dome.rgba.size() + dome.clear.size() + dome.clouds.size()) * sizeof(float) +
         dome.stars.size() * sizeof(look::Star);
}

/// Its grids (the surface, depth, wetness, the lakes' surface and labels, the drainage area) and
/// about a quarter of a kilobyte a river reach.
std::size_t water_bytes(const SurfaceWater& water) {
  return water.surface.size() * (5 * sizeof(float) + sizeof(double)) + water.rivers.rivers.size() * 256;
}

std::size_t placement_bytes(const vegetation::Placement& placement) {
  return (placement.trees.size() + placement.ground.size()) * sizeof(vegetation::Instance);
}

}  // namespace

SceneKeys scene_keys(const Recipe& recipe, std::string heights_key) {
  Recipe looked = recipe;
  resolve_look(looked);
  SceneKeys keys;
  keys.heights = std::move(heights_key);
  keys.rock = keys.heights + "|" + params::text_of(recipe.rock);
  keys.sky = sky_key(looked);
  keys.water = keys.heights + "|" + surface_water_key(recipe);
  keys.plants = keys.heights + "|" + plants_key(looked) + (draws_surface_water(recipe) ? "|" + keys.water : "");
  return keys;
}

std::shared_ptr<const Image> scene_rock(const Recipe& recipe, const Heightfield& heights, const PartsCache& cache, const Context& context) {
  return kept<Image>(
      cache, "rock", cache.keys.rock, [&] { return solid::rock_albedo(heights, recipe.rock, context); }, image_bytes);
}

std::shared_ptr<const SceneSky> scene_sky(const Recipe& looked, const PartsCache& cache, const Context& context) {
  return kept<SceneSky>(
      cache, "sky", cache.keys.sky,
      [&] {
        SceneSky sky;
        sky.clouds = scene_clouds(looked, context);
        const look::RenderParams resolved = look::with_fallbacks(looked.render);
        sky.dome = look::bake_sky_dome(resolved, sky.clouds.empty() ? nullptr : &sky.clouds, sky_dome_width, sky_dome_height, context);
        return sky;
      },
      sky_bytes);
}

std::shared_ptr<const SurfaceWater> scene_water(const Recipe& recipe, const Heightfield& heights, const PartsCache& cache,
                                                const Context& context) {
  return kept<SurfaceWater>(
      cache, "water", cache.keys.water,
      [&] { return draws_surface_water(recipe) ? scene_surface_water(recipe, heights, context) : SurfaceWater{}; }, water_bytes);
}

std::shared_ptr<const vegetation::Placement> scene_plants(const Recipe& looked, const Heightfield& heights, const SurfaceWater* water,
                                                          const PartsCache& cache, const Context& context) {
  return kept<vegetation::Placement>(
      cache, "plants", cache.keys.plants,
      [&] {
        vegetation::Placement plants = plants_to_draw(looked, heights, context);
        if (water != nullptr && !water->depth_m.empty()) remove_plants_in_water(plants, *water);
        return plants;
      },
      placement_bytes);
}

}  // namespace sansui::scene
