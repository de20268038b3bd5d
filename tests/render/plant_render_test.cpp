// Plants as drawn (render/plant_renderer.hpp): they show where they stand and nowhere else, the
// same input gives the same bytes, a single tree is framed whole, a mesh and its impostor agree in
// colour, and a quarter of a million plants go through all three levels of detail.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "look/plant_lod.hpp"
#include "look/sky_dome.hpp"
#include "render/headless_context.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_image.hpp"
#include "render/terrain_renderer.hpp"
#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"
#include "vegetation/species.hpp"

namespace sansui::render {

using namespace look;  // the look this file draws: params, layers, plant levels of detail
namespace {

std::uint16_t species_index(std::string_view name) {
  const auto& library = vegetation::species_library();
  return static_cast<std::uint16_t>(&vegetation::species_named(name) - library.data());
}

/// Flat ground 100 m up.
Heightfield flat_ground(int samples, double cell_m) {
  return Heightfield(samples, samples, 100.0f, cell_m);
}

vegetation::Instance tree_at(double x_m, double y_m, std::string_view species, float rotation_rad = 0.0f) {
  vegetation::Instance tree;
  tree.x_m = static_cast<float>(x_m);
  tree.y_m = static_cast<float>(y_m);
  tree.height_m = 100.0f;
  tree.rotation_rad = rotation_rad;
  tree.species = species_index(species);
  return tree;
}

RenderParams small(View view, int width, int height) {
  RenderParams params;
  params.view = view;
  params.width = width;
  params.height = height;
  params.samples = 1;
  // Every band grey: anything green is a plant.
  const Rgb grey{0.45f, 0.44f, 0.43f};
  params.land.beach = params.land.forest_low = params.land.forest_high = params.land.cliff = params.land.snow = grey;
  return params;
}

Image render_headless(const Heightfield& heights, const RenderParams& params, const vegetation::Placement* plants) {
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  TerrainLayers layers;
  PlantKindCache kinds;
  if (plants != nullptr) layers.plants = kinds.plants_to_draw(*plants, {});
  return render_image(heights, params, layers);
}

/// Draws with TerrainRenderer directly, for its plant statistics and level-of-detail limits.
struct Drawn {
  Image image;
  PlantStats stats;
};
Drawn draw_directly(const Heightfield& heights, const RenderParams& given, const vegetation::Placement& plants,
                    const PlantLodLimits& limits = {}) {
  ::unsetenv("DISPLAY");
  RenderParams params = with_fallbacks(given);
  params.sea_level_m = effective_sea_level(given, heights);
  params.height = resolved_height(given, heights);
  const HeadlessContext context;
  const OffscreenTarget target(params.width, *params.height, params.samples);
  TerrainRenderer renderer;
  renderer.set_plant_limits(limits);
  renderer.set_plant_timing(true);
  renderer.set_terrain(heights, params);
  PlantKindCache kinds;
  renderer.set_plants(kinds.plants_to_draw(plants, {}));
  renderer.set_sky(bake_sky_dome(params, nullptr, 256, 64), params);
  target.bind();
  renderer.draw(params, params.width, *params.height);
  return {target.read_pixels(), renderer.plant_stats()};
}

bool greenish(const Rgba8& c) {
  return c.g > c.r + 6 && c.g > c.b + 6;
}

TEST(PlantRender, PlantsShowWhereTheyStandAndNowhereElse) {
  // Top view of a 256 m square at 1 pixel per metre: a plant at (x, y) metres is at pixel (x, y).
  const Heightfield ground = flat_ground(65, 4.0);
  const RenderParams params = small(View::top, 256, 256);
  vegetation::Placement plants;
  const std::vector<std::pair<int, int>> spots = {{60, 70}, {190, 60}, {128, 128}, {70, 200}, {200, 190}};
  for (const auto& [x, y] : spots) plants.trees.push_back(tree_at(x, y, "oak"));
  const Image bare = render_headless(ground, params, nullptr);
  const Image wooded = render_headless(ground, params, &plants);
  std::vector<int> changed_near(spots.size(), 0), green_near(spots.size(), 0);
  int green_without_plants = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      green_without_plants += greenish(bare(x, y)) ? 1 : 0;
      if (wooded(x, y) == bare(x, y)) continue;
      int nearest = -1, shadowing = -1;
      for (std::size_t k = 0; k < spots.size(); ++k) {
        const double distance = std::hypot(x - spots[k].first, y - spots[k].second);
        if (distance < 14.0) nearest = static_cast<int>(k);
        if (distance < 40.0) shadowing = static_cast<int>(k);
      }
      // Beyond the crown, a tree only darkens the ground, with its shadow.
      const Rgba8 now = wooded(x, y), before = bare(x, y);
      const bool darker = now.r <= before.r && now.g <= before.g && now.b <= before.b;
      if (nearest < 0 && shadowing >= 0 && darker) continue;
      ASSERT_GE(nearest, 0) << "a pixel changed far from every plant: " << x << "," << y;
      ++changed_near[nearest];
      green_near[nearest] += greenish(wooded(x, y)) ? 1 : 0;
    }
  EXPECT_EQ(green_without_plants, 0);
  for (std::size_t k = 0; k < spots.size(); ++k) {
    EXPECT_GT(changed_near[k], 40) << "plant " << k;
    EXPECT_GT(green_near[k], changed_near[k] / 2) << "plant " << k;
  }
}

/// Mean brightness (r + g + b) of a window of pixels around (x, y).
double brightness_around(const Image& image, int x, int y, int half) {
  double sum = 0.0;
  int count = 0;
  for (int yy = y - half; yy <= y + half; ++yy)
    for (int xx = x - half; xx <= x + half; ++xx) {
      const Rgba8 c = image(xx, yy);
      sum += c.r + c.g + c.b;
      ++count;
    }
  return sum / count;
}

TEST(PlantRender, TheGroundUnderATreeIsDarkerOnTheSideAwayFromTheSun) {
  // Seen from above, 1 pixel a metre: an oak at the middle, the sun in the east 45 degrees up.
  // Its shadow falls west: the ground 12 m west of the trunk (beyond the crown seen from above)
  // is darker than 12 m east, and than the same ground without the tree.
  const Heightfield ground = flat_ground(33, 4.0);
  RenderParams params = small(View::top, 128, 128);
  for (double azimuth : {90.0, 270.0}) {
    params.sun_azimuth_deg = azimuth;
    params.sun_elevation_deg = 45.0;
    vegetation::Placement plants;
    plants.trees.push_back(tree_at(64.0, 64.0, "oak"));
    const Image bare = render_headless(ground, params, nullptr);
    const Image wooded = render_headless(ground, params, &plants);
    const int away = azimuth == 90.0 ? 64 - 12 : 64 + 12, toward = azimuth == 90.0 ? 64 + 12 : 64 - 12;
    const double shaded = brightness_around(wooded, away, 64, 2), lit = brightness_around(wooded, toward, 64, 2);
    EXPECT_LT(shaded, 0.85 * lit) << "sun at " << azimuth;
    EXPECT_LT(shaded, 0.85 * brightness_around(bare, away, 64, 2)) << "sun at " << azimuth;
    EXPECT_NEAR(lit, brightness_around(bare, toward, 64, 2), 3.0) << "sun at " << azimuth;
  }
}

TEST(PlantRender, SameInputSameBytes) {
  const Heightfield ground = flat_ground(33, 4.0);
  vegetation::Placement plants;
  for (int i = 0; i < 24; ++i)
    plants.trees.push_back(tree_at(10.0 + 5.0 * i, 20.0 + 4.0 * (i % 5), i % 2 == 0 ? "spruce" : "birch", 0.3f * static_cast<float>(i)));
  const RenderParams params = small(View::perspective, 240, 160);
  const Image first = render_headless(ground, params, &plants);
  const Image second = render_headless(ground, params, &plants);
  EXPECT_EQ(test::fnv1a(first.data(), first.size() * sizeof(Rgba8)), test::fnv1a(second.data(), second.size() * sizeof(Rgba8)));
}

TEST(PlantRender, AFittedPictureFramesASingleTreeWhole) {
  // A 16 m patch with an oak in the middle, taller than the patch is wide.
  const Heightfield ground = flat_ground(9, 2.0);
  vegetation::Placement plants;
  plants.trees.push_back(tree_at(8.0, 8.0, "oak"));
  RenderParams params = small(View::perspective, 240, 240);
  params.sea_level_m = 99.0;  // a thin slab of ground
  const Image image = render_headless(ground, params, &plants);
  int top = image.height(), bottom = -1, left = image.width(), right = -1, count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (greenish(image(x, y))) {
        top = std::min(top, y), bottom = std::max(bottom, y), left = std::min(left, x), right = std::max(right, x);
        ++count;
      }
  ASSERT_GT(count, 500);
  EXPECT_GT(top, 10);  // the crown is not cut at the top
  EXPECT_GT(left, 2);
  EXPECT_LT(right, image.width() - 3);
  EXPECT_GT(bottom - top, image.height() / 4);  // and the tree is big in the picture
}

/// The mean colour of the green pixels.
glm::dvec3 mean_plant_colour(const Image& image) {
  glm::dvec3 sum(0.0);
  int count = 0;
  for (const Rgba8& c : image.values())
    if (greenish(c)) sum += glm::dvec3(c.r, c.g, c.b), ++count;
  return count > 0 ? sum / static_cast<double>(count) : sum;
}

TEST(PlantRender, MeshImpostorAndSpriteAgreeInColour) {
  // One tree about 120 pixels tall, drawn once as each level: no jump in colour between them.
  const Heightfield ground = flat_ground(17, 2.0);
  vegetation::Placement plants;
  plants.trees.push_back(tree_at(16.0, 16.0, "oak", 0.7f));
  RenderParams params = small(View::perspective, 200, 200);
  params.samples = 4;
  PlantLodLimits as_mesh, as_card, as_sprite;
  as_mesh.full_min_px = 0.0f;
  as_card.full_min_px = as_card.simplified_min_px = as_sprite.full_min_px = as_sprite.simplified_min_px = 1e9f;
  as_card.sprite_below_px = 0.0f;
  as_sprite.sprite_below_px = 1e9f;
  const Drawn mesh = draw_directly(ground, params, plants, as_mesh);
  const Drawn card = draw_directly(ground, params, plants, as_card);
  const Drawn sprite = draw_directly(ground, params, plants, as_sprite);
  ASSERT_EQ(mesh.stats.full, 1);
  ASSERT_EQ(card.stats.impostors, 1);
  ASSERT_EQ(sprite.stats.sprites, 1);
  const glm::dvec3 a = mean_plant_colour(mesh.image), b = mean_plant_colour(card.image), c = mean_plant_colour(sprite.image);
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(a[channel], b[channel], 8.0) << "mesh and card, channel " << channel;
    EXPECT_NEAR(b[channel], c[channel], 4.0) << "card and sprite, channel " << channel;
  }
}

TEST(PlantRender, AQuarterMillionPlantsUseEveryLevelOfDetail) {
  terrain::MidpointParams midpoint;
  midpoint.seed = 46;  // land in front of the camera, close enough for full trees
  midpoint.sigma_m = 150.0;
  Heightfield heights = terrain::generate_midpoint(midpoint, 257);
  heights.cell_size_m = 16.0;  // 4 km square
  // 250,000 trees of four species, scattered at random on the land.
  vegetation::Placement plants;
  const std::uint64_t key = rng::stream_key(11, 0);
  const std::uint16_t species[] = {species_index("oak"), species_index("spruce"), species_index("beech"), species_index("pine")};
  for (std::uint64_t i = 0; plants.trees.size() < 250'000; ++i) {
    const double x = rng::to_uniform(rng::bits(key, 3 * i)) * 4096.0, y = rng::to_uniform(rng::bits(key, 3 * i + 1)) * 4096.0;
    const float ground = heights(static_cast<int>(x / 16.0), static_cast<int>(y / 16.0));
    if (ground <= 5.0f) continue;
    vegetation::Instance tree = tree_at(x, y, "oak", static_cast<float>(i % 628) * 0.01f);
    tree.height_m = ground;
    const std::uint64_t pick = rng::bits(key, 3 * i + 2);
    tree.species = species[pick % 4];
    tree.variant = static_cast<std::uint16_t>((pick >> 8) % vegetation::variants_per_species);
    tree.scale = 0.8f + 0.4f * static_cast<float>((pick >> 16) % 100) / 100.0f;
    plants.trees.push_back(tree);
  }
  RenderParams params = small(View::perspective, 480, 270);
  params.camera.distance = 0.25;  // close, low: trees from a hundred pixels tall to specks
  params.camera.elevation_deg = 12.0;
  // A small picture: the levels' thresholds are lowered to match.
  PlantLodLimits limits;
  limits.full_min_px = 60.0f;
  limits.simplified_min_px = 24.0f;
  limits.sprite_below_px = 8.0f;
  const Drawn drawn = draw_directly(heights, params, plants, limits);
  const PlantStats& stats = drawn.stats;
  EXPECT_EQ(stats.plants, 250'000);
  EXPECT_GT(stats.full, 0);
  EXPECT_GT(stats.simplified, 0);
  EXPECT_GT(stats.impostors, 100);
  EXPECT_GT(stats.sprites, 1000);
  EXPECT_GT(stats.culled, 0);
  EXPECT_EQ(stats.full + stats.simplified + stats.impostors + stats.sprites + stats.culled + stats.thinned, stats.plants);
  EXPECT_LE(stats.triangles, limits.full_triangle_budget + limits.simplified_triangle_budget + 2 * stats.impostors);
  EXPECT_GT(mean_plant_colour(drawn.image).g, 0.0);
}

TEST(PlantLod, SelectionIsDeterministicAndCullsBehindTheCamera) {
  std::vector<PlantSpot> spots;
  for (int i = 0; i < 1000; ++i) {
    PlantSpot spot;
    spot.x_m = static_cast<float>(i % 40) * 10.0f;
    spot.z_m = static_cast<float>(i / 40) * 10.0f;
    spot.noise = static_cast<std::uint32_t>(rng::bits(5, static_cast<std::uint64_t>(i)));
    spots.push_back(spot);
  }
  const std::vector<PlantKindInfo> kinds = {{{3.0f, 0.0f, 12.0f}, 2000, 400}};
  PlantView view;
  view.camera_pos = {200.0f, 30.0f, 300.0f};
  view.camera_forward = glm::normalize(glm::vec3(0.0f, -0.3f, -1.0f));
  view.view_proj = glm::perspective(0.8f, 1.5f, 1.0f, 2000.0f) *
                   glm::lookAt(view.camera_pos, view.camera_pos + view.camera_forward, glm::vec3(0.0f, 1.0f, 0.0f));
  view.pixels_per_unit = 300.0f;
  const PlantDrawList a = select_plants(spots, kinds, view), b = select_plants(spots, kinds, view);
  ASSERT_EQ(a.impostors.size(), b.impostors.size());
  EXPECT_EQ(test::fnv1a(a.impostors.data(), a.impostors.size() * sizeof(PlantInstance)),
            test::fnv1a(b.impostors.data(), b.impostors.size() * sizeof(PlantInstance)));
  // Plants south of the camera (z > 300) are behind it.
  EXPECT_GE(a.culled, 250);
  for (const PlantInstance& plant : a.impostors) EXPECT_LT(plant.place[2], 310.0f);
  // Front to back.
  for (std::size_t i = 1; i < a.impostors.size(); ++i) {
    const glm::vec3 p(a.impostors[i - 1].place[0], 0.0f, a.impostors[i - 1].place[2]),
        q(a.impostors[i].place[0], 0.0f, a.impostors[i].place[2]);
    EXPECT_LE(glm::dot(p - view.camera_pos, view.camera_forward), glm::dot(q - view.camera_pos, view.camera_forward) + 1.0f);
  }
}

}  // namespace
}  // namespace sansui::render
