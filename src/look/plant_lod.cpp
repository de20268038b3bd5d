#include "look/plant_lod.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>

#include "core/parallel.hpp"
#include "core/parallel_sort.hpp"

namespace sansui::look {
namespace {

enum Level : std::uint8_t { dropped, sprite, impostor, simplified, full };

/// Where one plant ended up in this view.
struct Choice {
  float y = 0.0f;       ///< drawn ground
  float scale = 0.0f;   ///< enlarged when thinned
  float pixels = 0.0f;  ///< height on the picture
  float depth = 0.0f;   ///< along the view direction, for front-to-back order
  Level level = dropped;
  bool culled = false;
};

/// The six planes of the view frustum (Gribb and Hartmann: sums of the matrix's rows),
/// normalised so that a sphere's distance can be compared with its radius.
std::array<glm::vec4, 6> frustum_planes(const glm::mat4& m) {
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]), row1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::vec4 row2(m[0][2], m[1][2], m[2][2], m[3][2]), row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  std::array<glm::vec4, 6> planes{row3 + row0, row3 - row0, row3 + row1, row3 - row1, row3 + row2, row3 - row2};
  for (glm::vec4& plane : planes) plane /= std::max(glm::length(glm::vec3(plane)), 1e-20f);
  return planes;
}

/// Bilinear sample of channel `channel` (0..1) of the RGBA8 shading texels at a point of the
/// terrain, as the GPU filters it (sample i at texel centre i).
float shading_at(const PlantView& view, float x_m, float z_m, int channel) {
  if (view.shading.empty()) return 1.0f;
  const int w = view.shading_width, h = view.shading_height;
  const float fx = std::clamp(x_m / view.width_m, 0.0f, 1.0f) * static_cast<float>(w - 1);
  const float fy = std::clamp(z_m / view.depth_m, 0.0f, 1.0f) * static_cast<float>(h - 1);
  const int x0 = std::min(static_cast<int>(fx), w - 2 < 0 ? 0 : w - 2), y0 = std::min(static_cast<int>(fy), h - 2 < 0 ? 0 : h - 2);
  const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
  const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
  auto at = [&](int x, int y) { return static_cast<float>(view.shading[(static_cast<std::size_t>(y) * w + x) * 4 + channel]) / 255.0f; };
  return (at(x0, y0) * (1.0f - tx) + at(x1, y0) * tx) * (1.0f - ty) + (at(x0, y1) * (1.0f - tx) + at(x1, y1) * tx) * ty;
}

/// The haze colour toward a horizontal direction (the sky texture's linear filtering along azimuth).
glm::vec3 haze_toward(const PlantView& view, float east, float south) {
  const auto n = static_cast<int>(view.haze.size());
  const float azimuth = std::atan2(east, -south);  // clockwise from north
  float u = azimuth / (2.0f * std::numbers::pi_v<float>);
  u -= std::floor(u);
  const float texel = u * static_cast<float>(n) - 0.5f;
  const float floor_texel = std::floor(texel);
  const int i0 = ((static_cast<int>(floor_texel) % n) + n) % n, i1 = (i0 + 1) % n;
  return glm::mix(view.haze[i0], view.haze[i1], texel - floor_texel);
}

/// The impostor's view of a plant (PlantInstance::box): the side view nearest to the direction
/// it is seen from, turned into its own frame, or the view from above when seen from higher than
/// about 53 degrees.
int impostor_view(const PlantView& view, const PlantSpot& spot, const glm::vec3& centre) {
  const glm::vec3 offset = view.camera_pos - centre;
  const glm::vec3 to_eye = view.orthographic || glm::length(offset) < 1e-6f ? -view.camera_forward : glm::normalize(offset);
  const float across = std::sqrt(to_eye.x * to_eye.x + to_eye.z * to_eye.z);
  if (to_eye.y > 0.8f || across < 1e-3f) return view.side_views;
  // The inverse of the plant's turn (plant_shaders.cpp: turn()).
  const float x = spot.cos_turn * to_eye.x - spot.sin_turn * to_eye.z, z = spot.sin_turn * to_eye.x + spot.cos_turn * to_eye.z;
  const float step = 2.0f * std::numbers::pi_v<float> / static_cast<float>(view.side_views);
  const int nearest = static_cast<int>(std::floor(std::atan2(x, z) / step + 0.5f));
  return ((nearest % view.side_views) + view.side_views) % view.side_views;
}

/// Within-budget meshes: the biggest on the picture first; the others go down one level.
void enforce_budget(std::vector<Choice>& choices, std::span<const PlantKindInfo> kinds, std::span<const PlantSpot> spots, Level level,
                    std::int64_t budget, std::int64_t& used) {
  std::vector<int> candidates;
  std::int64_t total = 0;
  for (std::size_t i = 0; i < choices.size(); ++i)
    if (choices[i].level == level) {
      candidates.push_back(static_cast<int>(i));
      const PlantKindInfo& kind = kinds[spots[i].kind];
      total += level == full ? kind.full_triangles : kind.simplified_triangles;
    }
  used = total;
  if (total <= budget) return;
  parallel_sort(candidates.begin(), candidates.end(),
                [&](int a, int b) { return choices[a].pixels != choices[b].pixels ? choices[a].pixels > choices[b].pixels : a < b; });
  used = 0;
  for (int i : candidates) {
    const PlantKindInfo& kind = kinds[spots[i].kind];
    const std::int64_t triangles = level == full ? kind.full_triangles : kind.simplified_triangles;
    if (used + triangles <= budget) {
      used += triangles;
    } else {
      choices[i].level = static_cast<Level>(level - 1);
    }
  }
}

/// The share of sunlight that reaches the crown of tree `i` past its neighbours' crowns: each
/// crown the sun's ray from its middle passes through (a cylinder from a third of the way up
/// the neighbour to its top) lets about half through, less near its axis.
float light_past_neighbours(std::size_t i, std::span<const PlantSpot> spots, std::span<const PlantKindInfo> kinds, const TreeGrid& grid,
                            const PlantView& view, float tallest_m, float widest_m) {
  const glm::vec3 sun = view.sun_dir;
  const float level = std::sqrt(sun.x * sun.x + sun.z * sun.z);
  if (!(sun.y > 0.05f) || level < 1e-4f || grid.columns == 0) return 1.0f;
  const glm::vec2 toward(sun.x / level, sun.z / level);
  const float run_per_rise = level / sun.y;
  const PlantSpot& me = spots[i];
  const PlantBounds& mine = kinds[me.kind].bounds;
  const float eye = me.ground_rows_m + (mine.bottom + 0.6f * (mine.top - mine.bottom)) * me.scale;
  // Far enough toward the sun that the ray has risen above the tallest tree.
  const float reach = std::min(std::max(tallest_m - (eye - me.ground_rows_m), 0.0f) * run_per_rise + widest_m, 80.0f);
  const glm::vec2 from(me.x_m, me.z_m), to = from + toward * reach;
  const int x0 = std::max(static_cast<int>(std::floor((std::min(from.x, to.x) - widest_m) / grid.cell_m)), 0);
  const int x1 = std::min(static_cast<int>(std::floor((std::max(from.x, to.x) + widest_m) / grid.cell_m)), grid.columns - 1);
  const int y0 = std::max(static_cast<int>(std::floor((std::min(from.y, to.y) - widest_m) / grid.cell_m)), 0);
  const int y1 = std::min(static_cast<int>(std::floor((std::max(from.y, to.y) + widest_m) / grid.cell_m)), grid.rows - 1);
  float light = 1.0f;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const std::size_t bucket = static_cast<std::size_t>(y) * grid.columns + x;
      for (std::uint32_t k = grid.first[bucket]; k < grid.first[bucket + 1]; ++k) {
        const std::uint32_t j = grid.index[k];
        if (j == i) continue;
        const PlantSpot& other = spots[j];
        const glm::vec2 offset(other.x_m - me.x_m, other.z_m - me.z_m);
        const float along = glm::dot(offset, toward);
        if (along <= 0.0f) continue;
        const PlantBounds& theirs = kinds[other.kind].bounds;
        const float crown = 0.8f * theirs.radius * other.scale;
        const float across = std::abs(offset.x * toward.y - offset.y * toward.x);
        if (across >= crown) continue;
        const float ray = eye + along / run_per_rise;
        const float low = other.ground_rows_m + (theirs.bottom + 0.35f * (theirs.top - theirs.bottom)) * other.scale;
        const float high = other.ground_rows_m + theirs.top * other.scale;
        if (ray > low && ray < high) light *= 0.35f + 0.3f * across / crown;
      }
    }
  return std::max(light, 0.25f);
}

/// The shadows on the ground of the trees in `orders` at least limits.shadow_min_px big, six
/// corners each, in order.
std::vector<ShadowVertex> shadows_of(std::span<const PlantSpot> spots, std::span<const PlantKindInfo> kinds,
                                     const std::vector<Choice>& choices, const std::vector<int>& order, const PlantView& view,
                                     const PlantLodLimits& limits) {
  std::vector<ShadowVertex> shadows;
  const glm::vec3 sun = view.sun_dir;
  // A sun a few degrees up casts shadows far longer than they are worth drawing.
  if (view.shadow_strength <= 0.0f || !(sun.y > 0.08f)) return shadows;
  const float level = std::sqrt(sun.x * sun.x + sun.z * sun.z);
  const glm::vec2 away = level > 1e-4f ? glm::vec2(-sun.x, -sun.z) / level : glm::vec2(1.0f, 0.0f);
  const glm::vec2 side(-away.y, away.x);
  const float run_per_rise = std::min(level / sun.y, 4.0f);
  const float stretch = std::min(1.0f / sun.y, 4.0f);
  const bool fog = !view.orthographic && view.fog_density > 0.0f;
  std::vector<int> casting;
  for (int i : order)
    if (!spots[i].ground_layer && choices[i].pixels >= limits.shadow_min_px) casting.push_back(i);
  shadows.resize(6 * casting.size());
  parallel_for_ranges<std::size_t>(0, casting.size(), 1024, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t k = range_begin; k != range_end; ++k) {
      const PlantSpot& spot = spots[casting[k]];
      const Choice& choice = choices[casting[k]];
      const PlantBounds& bounds = kinds[spot.kind].bounds;
      const float crown = std::max(0.8f * bounds.radius * choice.scale, 0.05f);
      const float crown_height = (bounds.bottom + 0.55f * (bounds.top - bounds.bottom)) * choice.scale;
      const float reach = crown_height * run_per_rise / crown;
      const float ground = ((view.rows_triangulation ? spot.ground_rows_m : spot.ground_columns_m) - view.sea_level_m) * view.exaggeration;
      const float lift = 0.1f + 0.03f * crown;
      float strength = view.shadow_strength * (view.shadows ? shading_at(view, spot.x_m, spot.z_m, 0) : 1.0f);
      if (fog) {
        const glm::vec3 offset = glm::vec3(spot.x_m, ground, spot.z_m) - view.camera_pos;
        strength *= std::exp(-view.fog_density * std::max(glm::length(offset) - view.fog_start_m, 0.0f) / view.terrain_size_m);
      }
      // The trunk's shadow: about a fiftieth of the tree's height wide, a few pixels at least.
      const float trunk = std::max(0.02f * bounds.top * choice.scale, 0.06f * crown) / crown;
      auto corner = [&](float along, float across) {
        const glm::vec2 d = (away * along + side * across) * crown;
        const float y = ground + (spot.gradient_x * d.x + spot.gradient_z * d.y) * view.exaggeration + lift;
        return ShadowVertex{spot.x_m + d.x, y, spot.z_m + d.y, along, across, reach, stretch, strength, trunk};
      };
      const float far = reach + stretch;
      const ShadowVertex a = corner(-1.0f, -1.0f), b = corner(far, -1.0f), c = corner(far, 1.0f), d = corner(-1.0f, 1.0f);
      ShadowVertex* out = &shadows[6 * k];
      out[0] = a, out[1] = b, out[2] = c, out[3] = a, out[4] = c, out[5] = d;
    }
  });
  return shadows;
}

}  // namespace

TreeGrid tree_grid(std::span<const PlantSpot> spots, float width_m, float depth_m, float cell_m) {
  TreeGrid grid;
  grid.cell_m = cell_m;
  grid.columns = std::max(1, static_cast<int>(std::ceil(width_m / cell_m)) + 1);
  grid.rows = std::max(1, static_cast<int>(std::ceil(depth_m / cell_m)) + 1);
  auto bucket_of = [&](const PlantSpot& spot) {
    const int x = std::clamp(static_cast<int>(spot.x_m / cell_m), 0, grid.columns - 1);
    const int y = std::clamp(static_cast<int>(spot.z_m / cell_m), 0, grid.rows - 1);
    return static_cast<std::size_t>(y) * grid.columns + x;
  };
  // A counting sort: sizes, starts, then the indices in order.
  grid.first.assign(static_cast<std::size_t>(grid.columns) * grid.rows + 1, 0);
  for (const PlantSpot& spot : spots)
    if (!spot.ground_layer) ++grid.first[bucket_of(spot) + 1];
  for (std::size_t b = 1; b < grid.first.size(); ++b) grid.first[b] += grid.first[b - 1];
  grid.index.resize(grid.first.back());
  std::vector<std::uint32_t> next(grid.first.begin(), grid.first.end() - 1);
  for (std::size_t i = 0; i < spots.size(); ++i)
    if (!spots[i].ground_layer) grid.index[next[bucket_of(spots[i])]++] = static_cast<std::uint32_t>(i);
  return grid;
}

namespace {

/// What choosing a plant's level needs of the view besides the plant itself.
struct ViewForChoice {
  const PlantView& view;
  const PlantLodLimits& limits;
  std::array<glm::vec4, 6> planes;  // the view frustum's
  float down_view, across_view;     // how far the view looks down (1: straight), and across
};

/// One plant on its own: culled, measured on the picture, thinned when small, given a level.
Choice choose_level(const PlantSpot& spot, const PlantBounds& bounds, const ViewForChoice& seen) {
  const PlantView& view = seen.view;
  const PlantLodLimits& limits = seen.limits;
  Choice choice;
  const float ground = view.rows_triangulation ? spot.ground_rows_m : spot.ground_columns_m;
  // Plants keep their true size on exaggerated relief; the trunk is sunk a little, by the
  // drawn slope, so that its downhill side does not float.
  const float sink = spot.scale * bounds.top * std::min(0.01f + 0.02f * spot.slope * view.exaggeration, 0.1f);
  choice.y = (ground - view.sea_level_m) * view.exaggeration - sink;
  const float tall = (bounds.top - bounds.bottom) * spot.scale;
  const glm::vec3 centre(spot.x_m, choice.y + 0.5f * (bounds.bottom + bounds.top) * spot.scale, spot.z_m);
  const float radius = std::sqrt(bounds.radius * bounds.radius * spot.scale * spot.scale + 0.25f * tall * tall);
  for (const glm::vec4& plane : seen.planes)
    if (glm::dot(glm::vec3(plane), centre) + plane.w < -radius) {
      choice.culled = true;
      break;
    }
  // A walker stands in a clearing: a plant whose crown would hold the eye is not drawn.
  if (!view.orthographic && view.camera_pos.y < choice.y + bounds.top * spot.scale + 0.5f) {
    const float dx = spot.x_m - view.camera_pos.x, dz = spot.z_m - view.camera_pos.z;
    const float reach = bounds.radius * spot.scale + 0.5f;
    if (dx * dx + dz * dz < reach * reach) choice.culled = true;
  }
  if (choice.culled) return choice;
  choice.depth = glm::dot(centre - view.camera_pos, view.camera_forward);
  // Its size on the picture: the height seen from the side, the crown's width from above.
  const float size = tall * seen.across_view + 2.0f * bounds.radius * spot.scale * seen.down_view;
  choice.pixels = view.orthographic ? size * view.pixels_per_unit : size * view.pixels_per_unit / std::max(choice.depth, 1e-3f);
  choice.scale = spot.scale;
  if (spot.ground_layer) {
    if (choice.pixels < limits.ground_min_px) return choice;
  } else if (choice.pixels < limits.thin_below_px) {
    const float keep = choice.pixels / limits.thin_below_px;
    if (static_cast<float>(spot.noise & 0xFFFFu) / 65536.0f >= keep * keep) return choice;
    choice.scale *= limits.thin_below_px / std::max(choice.pixels, 1e-6f);
    choice.pixels = limits.thin_below_px;
  }
  choice.level = choice.pixels >= limits.full_min_px         ? full
                 : choice.pixels >= limits.simplified_min_px ? simplified
                 : choice.pixels >= limits.sprite_below_px   ? impostor
                                                             : sprite;
  return choice;
}

using LevelOrders = std::array<std::vector<int>, 5>;  // the plants of each level, in drawing order

/// The plants by level, in drawing order: meshes by kind (one draw each), front to back within
/// a kind so that the depth test rejects hidden fragments early; impostors front to back.
/// Counts the culled and thinned plants into `list`.
LevelOrders drawing_orders(const std::vector<Choice>& choices, std::span<const PlantSpot> spots, PlantDrawList& list) {
  LevelOrders by_level;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i].culled) ++list.culled;
    by_level[choices[i].level].push_back(static_cast<int>(i));
  }
  list.thinned = static_cast<std::int64_t>(by_level[dropped].size()) - list.culled;
  auto by_kind_then_depth = [&](int a, int b) {
    if (spots[a].kind != spots[b].kind) return spots[a].kind < spots[b].kind;
    return choices[a].depth != choices[b].depth ? choices[a].depth < choices[b].depth : a < b;
  };
  parallel_sort(by_level[full].begin(), by_level[full].end(), by_kind_then_depth);
  parallel_sort(by_level[simplified].begin(), by_level[simplified].end(), by_kind_then_depth);
  // Impostors are many: sorted as 64-bit keys, depth (a non-negative float's bits order as its
  // value) then index, which is several times faster than comparing through the index.
  for (std::vector<int>& order : {std::ref(by_level[impostor]), std::ref(by_level[sprite])}) {
    std::vector<std::uint64_t> keys(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      keys[k] = static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(std::max(choices[order[k]].depth, 0.0f))) << 32 |
                static_cast<std::uint32_t>(order[k]);
    parallel_sort(keys.begin(), keys.end());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(keys[k] & 0xFFFFFFFFu);
  }
  return by_level;
}

/// What the instances of the chosen plants are made from.
struct InstanceSource {
  std::span<const PlantSpot> spots;
  std::span<const PlantKindInfo> kinds;
  const std::vector<Choice>& choices;
  const PlantView& view;
  const TreeGrid* trees;                // for the neighbours' shadows; null: none
  float tallest = 0.0f, widest = 0.0f;  // the largest trees' sizes, which bound the search for neighbours
  bool fog = false;
};

/// The instances of the plants in `order`: where, turned how, lit and fogged how, which card.
std::vector<PlantInstance> instances_of(const InstanceSource& source, const std::vector<int>& order, bool shaded_by_neighbours) {
  const PlantView& view = source.view;
  std::vector<PlantInstance> instances(order.size());
  parallel_for_ranges<std::size_t>(0, order.size(), 2048, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t k = range_begin; k != range_end; ++k) {
      const PlantSpot& spot = source.spots[order[k]];
      const Choice& choice = source.choices[order[k]];
      const PlantBounds& bounds = source.kinds[spot.kind].bounds;
      // A little variety between neighbours of one species, as light and health vary.
      const float tint = 0.88f + 0.24f * static_cast<float>(spot.noise >> 24) / 255.0f;
      float sun = view.shadows ? shading_at(view, spot.x_m, spot.z_m, 0) : 1.0f;
      if (shaded_by_neighbours && source.trees != nullptr && !spot.ground_layer)
        sun *= light_past_neighbours(static_cast<std::size_t>(order[k]), source.spots, source.kinds, *source.trees, view, source.tallest,
                                     source.widest);
      const float sky = 1.0f + (shading_at(view, spot.x_m, spot.z_m, 1) - 1.0f) * view.ambient_occlusion;
      const glm::vec3 centre(spot.x_m, choice.y + 0.5f * bounds.top * choice.scale, spot.z_m);
      glm::vec3 haze(0.0f);
      float fogged = 0.0f;
      if (source.fog) {
        const glm::vec3 offset = centre - view.camera_pos;
        fogged = 1.0f - std::exp(-view.fog_density * std::max(glm::length(offset) - view.fog_start_m, 0.0f) / view.terrain_size_m);
        haze = haze_toward(view, offset.x, offset.z);
      }
      const int card = choice.level <= impostor ? impostor_view(view, spot, centre) : 0;
      instances[k] = {{spot.x_m, choice.y, spot.z_m, choice.scale},
                      {spot.cos_turn, spot.sin_turn, sun * tint, sky * tint},
                      {haze.r, haze.g, haze.b, fogged},
                      {bounds.radius, bounds.bottom, bounds.top, static_cast<float>(spot.kind * 16 + card)}};
    }
  });
  return instances;
}

/// Where each kind's instances start in `order` (sorted by kind), and the count at the end.
std::vector<int> firsts_of(const std::vector<int>& order, std::span<const PlantSpot> spots, std::size_t kind_count) {
  std::vector<int> first(kind_count + 1, 0);
  for (int i : order) ++first[spots[i].kind + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  return first;
}

}  // namespace

PlantDrawList select_plants(std::span<const PlantSpot> spots, std::span<const PlantKindInfo> kinds, const PlantView& view,
                            const PlantLodLimits& limits, const TreeGrid* trees) {
  PlantDrawList list;
  std::vector<Choice> choices(spots.size());
  const float down_view = std::min(std::abs(view.camera_forward.y), 1.0f), across_view = std::sqrt(1.0f - down_view * down_view);
  const ViewForChoice seen{view, limits, frustum_planes(view.view_proj), down_view, across_view};

  // Each plant on its own: cull, measure, choose a level.
  parallel_for_ranges<std::size_t>(0, spots.size(), 4096, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t i = range_begin; i != range_end; ++i) choices[i] = choose_level(spots[i], kinds[spots[i].kind].bounds, seen);
  });

  enforce_budget(choices, kinds, spots, full, limits.full_triangle_budget, list.full_triangles);
  enforce_budget(choices, kinds, spots, simplified, limits.simplified_triangle_budget, list.simplified_triangles);
  const LevelOrders by_level = drawing_orders(choices, spots, list);

  InstanceSource source{spots, kinds, choices, view, trees};
  source.fog = !view.orthographic && view.fog_density > 0.0f && !view.haze.empty();
  // The tallest and widest trees bound the search for neighbours' shadows.
  if (trees != nullptr)
    for (const PlantKindInfo& kind : kinds)
      source.tallest = std::max(source.tallest, kind.bounds.top), source.widest = std::max(source.widest, kind.bounds.radius);
  source.tallest *= 1.6f, source.widest *= 1.6f * 0.8f;  // the largest trees' sizes (vegetation::size_of_age)
  list.full = instances_of(source, by_level[full], true);
  list.full_first = firsts_of(by_level[full], spots, kinds.size());
  list.simplified = instances_of(source, by_level[simplified], true);
  list.simplified_first = firsts_of(by_level[simplified], spots, kinds.size());
  list.impostors = instances_of(source, by_level[impostor], false);
  list.sprites = instances_of(source, by_level[sprite], false);
  for (Level level : {full, simplified, impostor}) {
    std::vector<ShadowVertex> part = shadows_of(spots, kinds, choices, by_level[level], view, limits);
    list.shadows.insert(list.shadows.end(), part.begin(), part.end());
  }
  return list;
}

}  // namespace sansui::look
