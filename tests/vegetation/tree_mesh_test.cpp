// Tree meshes (vegetation/tree_mesh.hpp): deterministic bytes, valid meshes (finite, indices in
// range, unit normals, closed wood), seasons (bare deciduous winters, blossom, autumn colours,
// snow on evergreens) and shapes that read as their species (a spruce is a cone, a palm has its
// leaves at the top, a cactus has no leaves).
#include "vegetation/tree_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "vegetation/placement.hpp"

namespace sansui::vegetation {
namespace {

std::uint64_t hash_of(const TriangleMesh& mesh) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  };
  add(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  add(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  add(mesh.colors.data(), mesh.colors.size() * sizeof(glm::vec3));
  add(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  return h;
}

void expect_valid(const TriangleMesh& mesh, const std::string& what) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << what;
  ASSERT_EQ(mesh.colors.size(), mesh.positions.size()) << what;
  ASSERT_EQ(mesh.indices.size() % 3, 0u) << what;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(mesh.positions[i][k])) << what;
      ASSERT_TRUE(std::isfinite(mesh.normals[i][k])) << what;
      ASSERT_GE(mesh.colors[i][k], 0.0f) << what;
      ASSERT_LE(mesh.colors[i][k], 1.0f) << what;
    }
    EXPECT_NEAR(glm::length(mesh.normals[i]), 1.0f, 1e-3f) << what;
  }
  for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size()) << what;
}

/// Vertices coloured like the species' bark (the wood).
bool is_bark(const Species& s, const glm::vec3& c) {
  return std::abs(c.r - s.bark.r) < 1e-4f && std::abs(c.g - s.bark.g) < 1e-4f && std::abs(c.b - s.bark.b) < 1e-4f;
}

TEST(TreeMesh, TheSameSpeciesAndSeedGiveTheSameBytesAndAnotherSeedAnotherTree) {
  const Species& oak = species_named("oak");
  EXPECT_EQ(hash_of(build_tree(oak, 7)), hash_of(build_tree(oak, 7)));
  EXPECT_NE(hash_of(build_tree(oak, 7)), hash_of(build_tree(oak, 8)));
}

TEST(TreeMesh, EverySpeciesInEverySeasonAndDetailIsAValidMeshOfItsHeight) {
  for (const Species& species : species_library())
    for (Season season : {Season::spring, Season::summer, Season::autumn, Season::winter})
      for (Detail detail : {Detail::full, Detail::simplified}) {
        const TriangleMesh mesh = build_tree(species, 3, {season, true, detail});
        const std::string what =
            species.name + " " + std::to_string(static_cast<int>(season)) + " " + std::to_string(static_cast<int>(detail));
        expect_valid(mesh, what);
        ASSERT_GT(mesh.triangle_count(), 0u) << what;
        float top = 0.0f, bottom = 1e9f;
        for (const glm::vec3& p : mesh.positions) top = std::max(top, p.y), bottom = std::min(bottom, p.y);
        // Grass blades and fronds arch over, so ground plants stand lower than their blades are long.
        EXPECT_GT(top, (species.layer == Layer::tree ? 0.5 : 0.25) * species.height_m) << what;
        EXPECT_LT(top, 1.6 * species.height_m + 0.5) << what;
        EXPECT_GT(bottom, -0.2 * species.height_m - 0.1) << what;
      }
}

TEST(TreeMesh, SimplifiedPlantsHaveFarFewerTriangles) {
  for (const char* name : {"oak", "spruce", "coconut_palm", "saguaro"}) {
    const Species& s = species_named(name);
    EXPECT_LT(build_tree(s, 1, {Season::summer, false, Detail::simplified}).triangle_count() * 3,
              build_tree(s, 1, {Season::summer, false, Detail::full}).triangle_count())
        << name;
  }
}

TEST(TreeMesh, WoodIsClosedEveryEdgeSharedByTwoTriangles) {
  // In winter a deciduous tree is wood only: its tubes and caps must be closed surfaces.
  for (const char* name : {"oak", "birch", "saguaro"}) {
    const TriangleMesh mesh = build_tree(species_named(name), 5, {Season::winter, false, Detail::full});
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.indices[t + k], b = mesh.indices[t + (k + 1) % 3];
        edges[{std::min(a, b), std::max(a, b)}] += 1;
      }
    int open = 0;
    for (const auto& [edge, count] : edges) open += count != 2 ? 1 : 0;
    EXPECT_EQ(open, 0) << name;
  }
}

TEST(TreeMesh, DeciduousTreesAreBareInWinterAndEvergreensKeepTheirLeaves) {
  const Species& oak = species_named("oak");
  const TriangleMesh winter = build_tree(oak, 2, {Season::winter, false});
  for (const glm::vec3& c : winter.colors) ASSERT_TRUE(is_bark(oak, c));
  const TriangleMesh summer = build_tree(oak, 2, {Season::summer, false});
  EXPECT_TRUE(std::any_of(summer.colors.begin(), summer.colors.end(), [&](const glm::vec3& c) { return !is_bark(oak, c); }));
  const Species& spruce = species_named("spruce");
  const TriangleMesh snowy = build_tree(spruce, 2, {Season::winter, true});
  EXPECT_TRUE(std::any_of(snowy.colors.begin(), snowy.colors.end(), [&](const glm::vec3& c) { return !is_bark(spruce, c) && c.r > 0.7f; }))
      << "snow on the spruce";
  const TriangleMesh green = build_tree(spruce, 2, {Season::winter, false});
  EXPECT_FALSE(std::any_of(green.colors.begin(), green.colors.end(), [](const glm::vec3& c) { return c.r > 0.7f; }));
}

TEST(TreeMesh, AutumnTurnsDeciduousLeavesAndSpringBringsBlossom) {
  const Species& maple = species_named("maple");
  auto mean_leaf = [&](Season season) {
    const TriangleMesh mesh = build_tree(maple, 4, {season, false});
    glm::dvec3 sum{0.0};
    int n = 0;
    for (const glm::vec3& c : mesh.colors)
      if (!is_bark(maple, c)) sum += glm::dvec3(c), ++n;
    return sum / static_cast<double>(std::max(n, 1));
  };
  const glm::dvec3 summer = mean_leaf(Season::summer), autumn = mean_leaf(Season::autumn);
  EXPECT_GT(autumn.r - autumn.g, summer.r - summer.g + 0.2) << "autumn leaves are redder";
  const Species& chestnut = species_named("chestnut");
  const TriangleMesh spring = build_tree(chestnut, 4, {Season::spring, false});
  const int blossoms = static_cast<int>(std::count_if(spring.colors.begin(), spring.colors.end(), [&](const glm::vec3& c) {
    return std::abs(c.r - chestnut.blossom.r) < 0.15f && std::abs(c.g - chestnut.blossom.g) < 0.15f &&
           std::abs(c.b - chestnut.blossom.b) < 0.15f;
  }));
  EXPECT_GT(blossoms, 100);
}

/// Horizontal spread of the vertices in the lower and upper thirds of the plant's height.
std::pair<double, double> spreads(const TriangleMesh& mesh) {
  float top = 0.0f;
  for (const glm::vec3& p : mesh.positions) top = std::max(top, p.y);
  double low = 0.0, high = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    const double r = std::hypot(p.x, p.z);
    if (p.y > 0.2f * top && p.y < 0.45f * top) low = std::max(low, r);
    if (p.y > 0.7f * top) high = std::max(high, r);
  }
  return {low, high};
}

TEST(TreeMesh, ASpruceIsAConeAndAPalmCarriesItsLeavesAtTheTop) {
  const auto [spruce_low, spruce_high] = spreads(build_tree(species_named("spruce"), 1));
  EXPECT_GT(spruce_low, 1.8 * spruce_high) << "a spruce is widest low down";
  const Species& palm = species_named("coconut_palm");
  const TriangleMesh mesh = build_tree(palm, 1);
  float top = 0.0f;
  for (const glm::vec3& p : mesh.positions) top = std::max(top, p.y);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!is_bark(palm, mesh.colors[i])) {
      ASSERT_GT(mesh.positions[i].y, 0.45f * top) << "a palm has no leaves low on its stem";
    }
  const Species& cactus = species_named("saguaro");
  const TriangleMesh saguaro = build_tree(cactus, 1, {Season::summer, false});
  for (const glm::vec3& c : saguaro.colors) ASSERT_TRUE(is_bark(cactus, c)) << "a cactus has no leaves";
}

TEST(TreeMesh, LeafCardsStayWithinALeafOfTheWood) {
  // Every leaf, frond or blossom hangs from the wood: no vertex farther out than a leaf's length
  // (fronds: 1.1 of it) beyond the box around the wood, for every woody species in leaf.
  for (const Species& species : species_library()) {
    if (species.layer != Layer::tree) continue;
    const TriangleMesh mesh = build_tree(species, 9, {Season::spring, false, Detail::full});
    glm::vec3 low{1e9f}, high{-1e9f};
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      if (is_bark(species, mesh.colors[i])) low = glm::min(low, mesh.positions[i]), high = glm::max(high, mesh.positions[i]);
    const float reach = 1.15f * static_cast<float>(species.leaf_size_m);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::vec3 p = mesh.positions[i];
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(p, low - reach)) && glm::all(glm::lessThanEqual(p, high + reach)))
          << species.name << " vertex " << i << " outside the crown";
    }
  }
}

TEST(TreeMesh, ASaguaroHasArmsThatRiseBesideItsStem) {
  // Issue 31: the saguaro was a plain cylinder. Its arms leave the stem, bend up and rise
  // parallel to it: wood well away from the stem's axis, high up, in both levels of detail.
  const Species& saguaro = species_named("saguaro");
  for (Detail detail : {Detail::full, Detail::simplified}) {
    const TreeOptions options{Season::summer, false, detail};
    EXPECT_EQ(tree_size(saguaro, options).branches, 1.0 + saguaro.branching);
    for (int variant = 0; variant < variants_per_species; ++variant) {
      const TriangleMesh mesh = build_tree(saguaro, variant_seed(7, variant), options);
      const double stem_radius = saguaro.trunk_radius * saguaro.height_m;
      int arm_vertices = 0;
      for (const glm::vec3& p : mesh.positions)
        if (std::hypot(p.x, p.z) > 2.5 * stem_radius && p.y > 0.5 * saguaro.height_m) ++arm_vertices;
      EXPECT_GT(arm_vertices, 10) << "variant " << variant;
    }
  }
}

TEST(TreeMesh, PalmFrondsAreAtTrueScaleAndBananaLeavesAreBroad) {
  // A coconut palm's fronds reach 4-6 m from the crown; a banana's leaves are broad paddles
  // (wide far out along the leaf, not spikes).
  const Species& coconut = species_named("coconut_palm");
  const TriangleMesh palm = build_tree(coconut, 1);
  // The crown's radius: half its leaves' extent across (the stem leans, so not from the axis).
  glm::vec3 low(1e9f), high(-1e9f);
  for (std::size_t i = 0; i < palm.positions.size(); ++i)
    if (!is_bark(coconut, palm.colors[i])) low = glm::min(low, palm.positions[i]), high = glm::max(high, palm.positions[i]);
  const double reach = 0.5 * std::max(high.x - low.x, high.z - low.z);
  EXPECT_GT(reach, 4.0);
  EXPECT_LT(reach, 7.0);
  const Species& banana = species_named("banana");
  EXPECT_EQ(banana.leaf, LeafKind::paddle);
  const TriangleMesh plant = build_tree(banana, 1);
  // Leaf area over leaf length squared: a paddle of length 4 width 1 gives about 0.2, a spike 0.1.
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < plant.indices.size(); t += 3) {
    const glm::vec3 a = plant.positions[plant.indices[t]], b = plant.positions[plant.indices[t + 1]],
                    c = plant.positions[plant.indices[t + 2]];
    const glm::vec3 n = plant.normals[plant.indices[t]];
    if (is_bark(banana, plant.colors[plant.indices[t]]) || n != plant.normals[plant.indices[t + 1]]) continue;  // leaves only
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  const double per_leaf = area / banana.leaves_per_twig;
  EXPECT_GT(per_leaf / (banana.leaf_size_m * banana.leaf_size_m), 0.15);
}

TEST(TreeMesh, AnInvalidSpeciesIsRefused) {
  Species broken = species_named("oak");
  broken.depth = 12;
  EXPECT_THROW((void)build_tree(broken, 1), InputError);
}

}  // namespace
}  // namespace sansui::vegetation
