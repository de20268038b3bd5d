#include "look/plant_models.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "look/colour_space.hpp"

namespace sansui::look {
namespace {

// How far a leaf's normal turns toward the crown's outward normal (0: its card's own, 1: the
// ellipsoid's); the rest keeps some sparkle between neighbouring cards.
constexpr float crown_bend = 0.75f;
// Light left at the crown's centre (leaves) and on wood deep inside it, as a fraction.
constexpr float leaf_core_light = 0.45f;
constexpr float wood_core_light = 0.35f;
// Light left at the bottom of the crown, rising to full at its top.
constexpr float lower_crown_light = 0.6f;

std::int8_t to_snorm8(float v) {
  return static_cast<std::int8_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 127.0f));
}
std::uint16_t to_unorm16(float v) {
  return static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f));
}

/// Leaves are the vertices of flat-shaded triangles only (see the header).
std::vector<bool> find_leaves(const TriangleMesh& mesh) {
  std::vector<bool> leaf(mesh.positions.size(), !mesh.normals.empty());
  if (mesh.normals.empty()) return leaf;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::vec3 &na = mesh.normals[a], &nb = mesh.normals[b], &nc = mesh.normals[c];
    const bool flat =
        glm::all(glm::lessThan(glm::abs(na - nb), glm::vec3(1e-4f))) && glm::all(glm::lessThan(glm::abs(na - nc), glm::vec3(1e-4f)));
    if (!flat) leaf[a] = leaf[b] = leaf[c] = false;
  }
  return leaf;
}

}  // namespace

PlantModel prepare_plant_model(const TriangleMesh& mesh) {
  PlantModel model;
  const std::size_t count = mesh.positions.size();
  if (count == 0) return model;
  const std::vector<bool> leaf = find_leaves(mesh);

  // Bounds, and the crown: the box around the leaves (around everything when bare).
  glm::vec3 low(1e30f), high(-1e30f), leaf_low(1e30f), leaf_high(-1e30f);
  int leaves = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3& p = mesh.positions[i];
    low = glm::min(low, p);
    high = glm::max(high, p);
    model.bounds.radius = std::max(model.bounds.radius, std::sqrt(p.x * p.x + p.z * p.z));
    if (leaf[i]) {
      leaf_low = glm::min(leaf_low, p);
      leaf_high = glm::max(leaf_high, p);
      ++leaves;
    }
  }
  // A margin, so that filtering in the impostor atlas does not reach the next cell.
  model.bounds.radius *= 1.04f;
  model.bounds.bottom = std::min(low.y, 0.0f);
  model.bounds.top = std::max(high.y, 0.0f) * 1.02f;
  if (leaves < 4) leaf_low = low, leaf_high = high;
  const glm::vec3 centre = 0.5f * (leaf_low + leaf_high);
  const float size = std::max({high.x - low.x, high.y - low.y, high.z - low.z, 1e-3f});
  const glm::vec3 half = glm::max(0.5f * (leaf_high - leaf_low), glm::vec3(0.05f * size));

  model.vertices.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3& p = mesh.positions[i];
    glm::vec3 normal = mesh.normals.empty() ? glm::vec3(0.0f, 1.0f, 0.0f) : mesh.normals[i];
    // Where the vertex sits in the crown's ellipsoid: 0 at its centre, 1 on its surface.
    const glm::vec3 inside = (p - centre) / half;
    const float depth = glm::length(inside);
    float light = 1.0f;
    if (leaf[i]) {
      const glm::vec3 gradient = inside / half;
      const glm::vec3 outward = glm::length(gradient) > 1e-6f ? glm::normalize(gradient) : glm::vec3(0.0f, 1.0f, 0.0f);
      if (glm::dot(normal, outward) < 0.0f) normal = -normal;  // cards are two-sided
      normal = glm::normalize(glm::mix(normal, outward, crown_bend));
      const float t = std::clamp(depth, 0.0f, 1.0f);
      light = leaf_core_light + (1.0f - leaf_core_light) * t * t * (3.0f - 2.0f * t);
      // The lower crown is shaded by the upper one and, in a forest, by the neighbours' crowns.
      const float up_crown = std::clamp((p.y - leaf_low.y) / std::max(leaf_high.y - leaf_low.y, 1e-3f), 0.0f, 1.0f);
      light *= lower_crown_light + (1.0f - lower_crown_light) * up_crown;
    } else if (leaves >= 4 && depth < 1.0f) {
      light = wood_core_light + (1.0f - wood_core_light) * depth;
    }
    const glm::vec3 colour = mesh.colors.empty() ? glm::vec3(0.5f) : mesh.colors[i];
    PlantVertex& v = model.vertices[i];
    v.x = p.x, v.y = p.y, v.z = p.z;
    v.normal_x = to_snorm8(normal.x), v.normal_y = to_snorm8(normal.y), v.normal_z = to_snorm8(normal.z);
    v.leaf = leaf[i] ? 127 : 0;
    v.red = to_unorm16(srgb_to_linear(colour.r) * light);
    v.green = to_unorm16(srgb_to_linear(colour.g) * light);
    v.blue = to_unorm16(srgb_to_linear(colour.b) * light);
  }
  model.indices = mesh.indices;
  return model;
}

std::vector<PlantModel> build_plant_models(const std::vector<std::uint32_t>& keys, const vegetation::TreeOptions& options,
                                           const std::vector<vegetation::Species>& library) {
  constexpr auto variants = static_cast<std::uint32_t>(vegetation::variants_per_species);
  std::vector<PlantModel> models(2 * keys.size());
  parallel_for(std::size_t{0}, models.size(), [&](std::size_t i) {
    const std::uint32_t key = keys[i / 2];
    vegetation::TreeOptions detailed = options;
    detailed.detail = i % 2 == 0 ? vegetation::Detail::full : vegetation::Detail::simplified;
    const auto species = static_cast<int>(key / variants);
    models[i] = prepare_plant_model(
        vegetation::build_tree(library[key / variants], vegetation::variant_seed(species, static_cast<int>(key % variants)), detailed));
  });
  return models;
}

PlantsToDraw PlantKindCache::plants_to_draw(const vegetation::Placement& placement, const vegetation::TreeOptions& look) {
  const auto& library = placement.library();
  constexpr auto variants = static_cast<std::uint32_t>(vegetation::variants_per_species);
  // The kinds in use, ascending.
  std::vector<bool> used(library.size() * variants, false);
  for (const auto* layer : {&placement.trees, &placement.ground})
    for (const PlacedPlant& plant : *layer) {
      if (plant.species >= library.size() || plant.variant >= variants)
        fail("a plant of species {} and variant {} cannot be drawn: there are {} species and {} variants of each", plant.species,
             plant.variant, library.size(), variants);
      used[plant.species * variants + plant.variant] = true;
    }
  std::vector<std::uint32_t> keys;
  for (std::size_t key = 0; key < used.size(); ++key)
    if (used[key]) keys.push_back(static_cast<std::uint32_t>(key));
  const bool same =
      last_ && last_->keys == keys && last_look_.season == look.season && last_look_.snow == look.snow && last_library_ == &library;
  if (!same) {
    auto kinds = std::make_shared<PlantKinds>();
    kinds->models = build_plant_models(keys, look, library);
    kinds->keys = std::move(keys);
    last_ = std::move(kinds);
    last_look_ = look;
    last_library_ = &library;
  }
  return {&placement.trees, &placement.ground, last_};
}

}  // namespace sansui::look
