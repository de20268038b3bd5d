// One plant as a mesh (seed 003, Sec. 4.1.6; SPEC 3.3): a recursive branching structure of
// tapered, closed cylinders for the wood and cards for the leaves, coloured per vertex for the
// season. A pure function of (species, seed, season, snow, detail): the same arguments give the
// same bytes.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "core/budget.hpp"
#include "core/season.hpp"
#include "core/triangle_mesh.hpp"
#include "vegetation/species.hpp"

namespace sansui::vegetation {

/// How finely a plant is built: the renderer's levels of detail.
enum class Detail {
  full,        ///< every branch level, 6-sided wood, every leaf card
  simplified,  ///< one branch level less, 3-sided wood, leaves merged into fewer larger cards
};

struct TreeOptions {
  Season season = Season::summer;
  bool snow = false;  ///< evergreens carry snow on their upper surfaces (winter where it snows)
  Detail detail = Detail::full;
};

/// The plant at the origin: its base at (0, 0, 0), y up, x east, z south, in metres, at the
/// species' typical height (the placement scales and turns each instance). Positions, normals
/// and sRGB colours, one per vertex; no NaN. Throws InputError if `species` is invalid or its
/// tree_cost() does not fit the budget (budget::check).
TriangleMesh build_tree(const Species& species, std::uint64_t seed, const TreeOptions& options = {});

/// The size of build_tree's plant, counted level by level from the species' numbers (branching,
/// depth, leaves per twig, the forms' fixed segment and side counts) without growing it.
struct TreeSize {
  double branches = 0.0;   ///< tubes of wood
  double points = 0.0;     ///< points of their polylines
  double cards = 0.0;      ///< leaf, frond, blade and flower cards
  double vertices = 0.0;   ///< of the mesh
  double triangles = 0.0;  ///< of the mesh
};
TreeSize tree_size(const Species& species, const TreeOptions& options = {});

/// What build_tree needs for `species`: its skeleton and mesh at once, and the time to build and
/// write them (measured: about 0.7 microseconds a triangle on the reference machine).
budget::Cost tree_cost(const Species& species, const TreeOptions& options = {});

/// Whether a deciduous species has leaves in `season` (none in winter).
bool has_leaves(const Species& species, Season season);

}  // namespace sansui::vegetation
