// Plant instances for game engines and other renderers (issue 11): one row per plant with its
// layer, species name, world position, ground height, scale, turn and shape variant, as CSV or
// JSON, chosen by the extension. Columns and keys, in this order:
//   layer (tree | ground), species, x_east_m, y_south_m, height_m (ground height under the plant),
//   scale (times the species' typical size), rotation_deg (about the vertical, [0, 360)), variant.
// Trees come first, then the ground layer, each in the placement's order.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/placed_plant.hpp"

namespace sansui::io {

enum class PlantFormat { csv, json };

/// The format for a file name's extension (.csv .json), or nullopt.
std::optional<PlantFormat> plant_format_for(const std::filesystem::path& path);

/// What rows are written and read against: the names of the species that instances index, and
/// how many shape variants each has.
struct PlantCatalogue {
  std::vector<std::string> species;
  int variants = 1;
};

/// The two layers of a plant file.
struct PlantLayers {
  std::vector<PlacedPlant> trees, ground;
};

/// Writes every instance atomically; with `provenance`, the sidecar NAME.EXT.json beside it.
/// Throws InputError for an unknown extension, an unwritable directory or a species index
/// outside the catalogue.
void write_plant_instances(const std::filesystem::path& path, std::span<const PlacedPlant> trees, std::span<const PlacedPlant> ground,
                           const PlantCatalogue& catalogue, const std::optional<nlohmann::json>& provenance = std::nullopt);

/// Reads a file write_plant_instances wrote. Positions, heights and scales come back bit for bit;
/// rotations to within float rounding of the degrees. Throws InputError naming the file and line
/// (an unknown species or layer, a variant outside the catalogue's, a number that is not finite).
PlantLayers read_plant_instances(const std::filesystem::path& path, const PlantCatalogue& catalogue);

}  // namespace sansui::io
