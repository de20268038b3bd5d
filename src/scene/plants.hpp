// A scene's plants (SPEC 3.3): the placement rules its resolved look gives (tree line, sea level,
// climate's species, season, densities), the plants themselves, and one plant on its own for
// `sansui tree`. The CLI, scene files and the viewer all place plants through here.
#pragma once

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"
#include "io/plant_instances.hpp"
#include "scene/recipe.hpp"
#include "vegetation/placement.hpp"
#include "vegetation/tree_mesh.hpp"

namespace sansui::scene {

/// The plants a scene places (trees and ground plants, world coordinates): the engine's product
/// that the viewer and Python hold, by the scene's name for it.
using Plants = vegetation::Placement;

/// `looked` must have been through resolve_look() (tree line, densities set). The tree line is
/// a fraction of the highest point above sea level, as the renderer's bands take it.
vegetation::PlacementRules placement_rules(const Recipe& looked, const Heightfield& heights);

/// Season and snow of the scene's plants: evergreens carry snow in winter when it snows or the
/// snow line reaches down to the forest.
vegetation::TreeOptions plant_look(const Recipe& looked);

/// The scene's plants on `heights`; none when [vegetation] enabled = false.
vegetation::Placement place_scene_plants(const Recipe& looked, const Heightfield& heights, const Context& context);

/// The plants a picture draws: the scene's, without the ground layer when its grid would have
/// more than max_drawn_ground_cells cells. Grass seen over a whole large terrain is far below a
/// pixel, and would cost memory and time for nothing (23 M ground plants on a 20 km terrain):
/// there the terrain's colour carries it. Plant lists (--plants) keep every plant.
vegetation::Placement plants_to_draw(const Recipe& looked, const Heightfield& heights, const Context& context);

/// The plants a picture from `looked.render.camera` draws: plants_to_draw(), and where that
/// leaves out the ground layer, the ground plants within ground_plants_reach_m of a camera
/// standing at most ground_plants_eye_height_m above the ground (or, for an orbiting camera, out
/// to one and a half times its distance from its target): they are what it sees of them (farther
/// out a plant is below a pixel), so a walker in a large forest stands in its grass.
vegetation::Placement plants_for_picture(const Recipe& looked, const Heightfield& heights, const Context& context);
inline constexpr double ground_plants_reach_m = 600.0;
inline constexpr double ground_plants_eye_height_m = 100.0;

/// The species and shape variants plant files name (vegetation::species_library()).
io::PlantCatalogue plant_catalogue();

/// A placement as a plant instance file (io/plant_instances.hpp), and back.
void write_plant_instances(const std::filesystem::path& path, const vegetation::Placement& placement,
                           const std::optional<nlohmann::json>& provenance = std::nullopt);
vegetation::Placement read_plant_instances(const std::filesystem::path& path);

/// What plants_to_draw() and plant_look() read of a resolved recipe, as text (the heights aside):
/// vegetation, climate, season, weather, the tree and snow lines and the sea level.
std::string plants_key(const Recipe& looked);
inline constexpr double max_drawn_ground_cells = 4.0e6;

/// The species [tree] may name: the library, plus (replacing same names) [tree] species_file's.
/// Throws InputError for an unreadable or bad species file, naming the file, line and key.
std::vector<vegetation::Species> tree_species(const Recipe& recipe);

/// Throws InputError unless [tree] species names one of tree_species(), listing them.
void check_tree_species(const Recipe& recipe);

/// The [tree] plant as a mesh, in the recipe's season.
TriangleMesh tree_mesh_of(const Recipe& recipe);

/// A picture of the [tree] plant standing on a patch of ground, as the renderer draws scenes.
Image tree_picture(const Recipe& recipe, const Context& context);

}  // namespace sansui::scene
