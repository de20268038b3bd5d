// A scene's parts as plain data, for programs that build their own 3-D scenes (the Python
// module's sansui.scenery(), and through it the Blender add-on): the recipe's terrain, its ground
// colour and splat weights, the water standing on it and its plants, each made exactly as the
// outputs and the renderer make them (scene/outputs.cpp, scene/look.hpp, scene/plants.hpp), so
// that an imported scene looks like `sansui run` draws it.
//
// The scene's frame: x east of sample (0, 0) (the world's west edge), y north of it (negative
// southwards: row j of the heights lies at y = -j * cell), z the height; metres. Adding `origin`
// gives the world coordinates of every output's GeoJSON.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "scene/recipe.hpp"
#include "vegetation/placement.hpp"

namespace sansui::scene {

/// One plant in the scene's frame.
struct SceneryPlant {
  float x_m = 0.0f;           ///< east of sample (0, 0). [Units: m]
  float y_m = 0.0f;           ///< north of sample (0, 0): negative on the terrain. [Units: m]
  float z_m = 0.0f;           ///< the ground's height under the plant (bilinear). [Units: m]
  std::uint16_t species = 0;  ///< index into Scenery::species
  std::uint16_t variant = 0;  ///< which of the species' mesh variants: [Range: 0..variants_per_species-1]
  float scale = 1.0f;         ///< times the species' typical size
  float rotation_rad = 0.0f;  ///< turn about the vertical, counter-clockwise seen from above. [Range: 0..2 pi]
  std::uint8_t layer = 0;     ///< 0: a tree, 1: the ground layer (grass, small plants)
};

/// Everything a 3-D scene needs for a recipe's terrain. Every grid has the heights' size, row 0
/// the north row.
struct Scenery {
  Heightfield heights;               ///< as recipe_heights() makes them, byte for byte. [Units: m]
  double sea_level_m = 0.0;          ///< the sea level the picture uses (without a sea: 1 m below the lowest point)
  bool sea = true;                   ///< whether the scene has a sea (render.sea)
  std::array<double, 2> origin{};    ///< world coordinates (east, north) of sample (0, 0). [Units: m]
  Image colour;                      ///< the ground's band colours, sRGB, alpha 255: the mesh outputs' base colour, one pixel a sample
  Image splat;                       ///< the splat map output's weights: r sand, g grass, b rock, a snow; r + g + b + a = 255
  Grid<float> water_m;               ///< water over the ground: lakes and rivers where the scene draws them, and the sea. [Units: m]
  std::vector<SceneryPlant> plants;  ///< trees first, then the ground layer, each in placement order
  std::vector<std::string> species;  ///< names, indexed by SceneryPlant::species
  Season season = Season::summer;    ///< the scene's season, which its plant meshes take
  bool plant_snow = false;           ///< whether its evergreens carry snow (plant_look())
};

/// The sections of a recipe that scenery() reads beyond the heights' own: those read by the
/// render, mesh, splat map, plants and tree outputs (climate, season, weather, time, land, sea,
/// vegetation, flow, ...), in recipe_sections() order. (Qualified: a unity batch also holds
/// climate.cpp's own Section.)
std::vector<const scene::Section*> scenery_sections();

/// The recipe's scene parts. Throws InputError for a bad recipe (as recipe_heights() and
/// resolve_look() do), Cancelled when asked to stop. A tile's splat weights are made on the tile
/// alone (a splat map output makes them on its apron, so they differ along its border).
Scenery make_scenery(const Recipe& recipe, const Context& context = quiet_context());

/// Plants in the scene's frame of `heights`: trees (layer 0) then ground plants (layer 1).
std::vector<SceneryPlant> scenery_plants(const vegetation::Placement& placement, const Heightfield& heights);

/// Water over the ground: `surface_depth_m` (lakes and rivers; may be empty: none) and, with a
/// sea, the sea's depth over ground below `sea_level_m`; the larger of the two. [Units: m]
Grid<float> water_depth(const Heightfield& heights, const Grid<float>& surface_depth_m, bool sea, double sea_level_m);

}  // namespace sansui::scene
