// Where plants grow (SPEC 3.3): a jittered grid in world coordinates, every decision a pure
// function of (seed, layer, integer grid cell), so a tile of a world gets exactly the plants the
// whole world has there, in any thread order. Density from the climate (Table 4), modulated by a
// smooth multi-scale field (groves, clearings, edges) and thinned on steep slopes and toward the
// tree line; none above the tree line, under the sea or on slopes steeper than the species
// allows; species mixed by altitude band in patches; tree sizes from an age distribution.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "core/placed_plant.hpp"
#include "core/season.hpp"
#include "vegetation/species.hpp"

namespace sansui::vegetation {

/// The scene's [vegetation] section.
struct VegetationParams {
  /// Draw and place plants at all. [Default: true]
  bool enabled = true;
  /// Seed of the placement (which cells hold a plant, which species, size and turn). [Default: 1]
  std::uint64_t seed = 1;
  /// Share of the tree grid's cells that hold a tree, on flat land inside the forest band.
  /// [Range: 0..1] [Default: unset: the climate's (Table 4)]
  std::optional<double> density;
  /// Side of a tree grid cell: at density 1 there is one tree per cell. [Units: m] [Range: 1..1000] [Default: 8]
  double spacing_m = 8.0;
  /// Share of the ground grid's cells holding grass or a small plant. [Range: 0..1]
  /// [Default: unset: the climate's]
  std::optional<double> ground_density;
  /// Side of a ground grid cell. [Units: m] [Range: 0.2..100] [Default: 2]
  double ground_spacing_m = 2.0;
  /// Plants' sizes are multiplied by this. [Range: 0.05..20] [Default: 1]
  double scale = 1.0;
  /// How much a smooth noise field over the land gathers trees into groves and opens clearings
  /// and edges (the mean density stays `density`): 0 spreads them evenly on the grid.
  /// [Range: 0..1] [Default: 0.8]
  double clumping = 0.8;
  /// Width of the water's-edge band, where near-water species grow (an oasis's date palms), as a
  /// fraction of the maximum elevation above sea level. [Range: 0..1] [Default: 0.03]
  double water_edge = 0.03;

  void validate() const;
};

const params::Table<VegetationParams>& parameter_table(const VegetationParams*);

/// What placement needs from the scene, resolved to numbers (scene/ derives them from the
/// climate, season and look; tests set them directly).
struct PlacementRules {
  double tree_density = 0.4;    ///< [Range: 0..1]
  double ground_density = 0.0;  ///< [Range: 0..1]
  double sea_level_m = 0.0;     ///< no plant at or below it
  double tree_line_m = 1000.0;  ///< no plant above it (absolute height)
  double water_edge_m = 30.0;   ///< near-water species only below sea_level_m + this
  Season season = Season::summer;
  std::vector<ClimateSpecies> species;  ///< both layers; species_of_climate() gives a climate's
};

/// One plant.
using Instance = PlacedPlant;

/// Distinct seeded shapes built per species; instances pick one of them.
inline constexpr int variants_per_species = 4;

/// Most trees one grid cell holds where the density field gathers them into a grove.
inline constexpr int trees_per_cell = 3;

/// The density field at a world point (metres), as a factor on the climate's density: mean 1
/// over large areas, 0 in clearings, up to about 3.5 in groves. A pure function of the seed and
/// the point (lattice noise at integer world coordinates). Exposed for tests and pictures.
double density_field(std::uint64_t seed, double x_m, double y_m);

/// A tree's size factor from its age: many young, small trees and few old, large ones, from
/// `age_draw` in [0, 1). [Range: 0.5..1.55]
constexpr double size_of_age(double age_draw) {
  return 0.5 + 1.05 * age_draw * age_draw;
}

/// The build_tree seed of a species' variant: the same shapes in every scene, picture and export.
constexpr std::uint64_t variant_seed(int species, int variant) {
  return static_cast<std::uint64_t>(species) * 16u + static_cast<std::uint64_t>(variant);
}

struct Placement {
  std::vector<Instance> trees;   ///< sorted by (grid row, grid column): independent of threads
  std::vector<Instance> ground;  ///< the dense ground layer, same order
  /// The species the instances' indices refer to; null: species_library(). Not owned (a user's
  /// own species file for `sansui tree`).
  const std::vector<Species>* species = nullptr;

  const std::vector<Species>& library() const { return species != nullptr ? *species : species_library(); }
};

/// Scatters plants over `heights` (world coordinates from its origin and cell size). A plant
/// belongs to the heightfield whose half-open extent [origin, origin + (n-1) cell) holds it, so
/// tiles sharing border samples never both hold one. Reports progress as "vegetation".
Placement place_plants(const Heightfield& heights, const VegetationParams& params, const PlacementRules& rules,
                       const Context& context = quiet_context());

}  // namespace sansui::vegetation
