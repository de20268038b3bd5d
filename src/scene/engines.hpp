// Game-engine presets (heightmap_output.engine): which sizes and heightmap formats an engine's
// terrain importer takes, and the scales and location that bring a 16-bit heightmap back to its
// metres there. The import steps per engine are in docs/engines.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "io/heightmap_io.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {

std::string_view engine_name(Engine engine);

/// True for a side Unreal Engine's landscape takes without padding or cropping:
/// components (1..32) x sections per component (1 or 2) x quads per section (7, 15, 31, 63, 127
/// or 255) + 1, e.g. 505, 1009, 2017, 4033, 8129.
bool is_unreal_landscape_size(long long samples);

/// "" when a width x height heightmap suits the engine's importer, else what is allowed
/// ("Unreal landscape sizes such as 505, 1009, ...").
std::string engine_size_problem(Engine engine, long long width, long long height);

/// The heightmap extensions the engine's importer reads (".r16", ...); empty for Engine::none.
std::vector<std::string> engine_extensions(Engine engine);

/// What an importer needs to place a heightmap written with `range` (16-bit levels) at its
/// metres: the sidecar's "engine" member and one line for the user (a Context note).
struct EngineImport {
  nlohmann::json sidecar;
  std::string note;
};
EngineImport engine_import(Engine engine, const Heightfield& heights, const io::HeightRange& range, const std::filesystem::path& file);

}  // namespace sansui::scene
