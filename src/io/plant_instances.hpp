// Plant instances for game engines and other renderers (issue 11): one row per plant with its
// layer, species name, world position, ground height, scale, turn and shape variant, as CSV or
// JSON, chosen by the extension. Columns and keys, in this order:
//   layer (tree | ground), species, x_east_m, y_south_m, height_m (ground height under the plant),
//   scale (times the species' typical size), rotation_deg (about the vertical, [0, 360)), variant.
// Trees come first, then the ground layer, each in the placement's order.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "vegetation/placement.hpp"

namespace sansui::io {

enum class PlantFormat { csv, json };

/// The format for a file name's extension (.csv .json), or nullopt.
std::optional<PlantFormat> plant_format_for(const std::filesystem::path& path);

/// Writes every instance of `placement` atomically; with `provenance`, the sidecar NAME.EXT.json
/// beside it. Throws InputError for an unknown extension, an unwritable directory or a species
/// index outside vegetation::species_library().
void write_plant_instances(const std::filesystem::path& path, const vegetation::Placement& placement,
                           const std::optional<nlohmann::json>& provenance = std::nullopt);

/// Reads a file write_plant_instances wrote. Positions, heights and scales come back bit for bit;
/// rotations to within float rounding of the degrees. Throws InputError naming the file and line.
vegetation::Placement read_plant_instances(const std::filesystem::path& path);

}  // namespace sansui::io
