#include "scene/engines.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "terrain/midpoint.hpp"

namespace sansui::scene {
namespace {

constexpr std::array<int, 6> unreal_quads_per_section{7, 15, 31, 63, 127, 255};

bool is_power_of_two_plus_one(long long samples, long long low, long long high) {
  return samples >= low && samples <= high && terrain::levels_for_size(samples) >= 1;
}

/// Unreal's own layout for a side: the fewest components (largest sections) that give it.
struct UnrealLayout {
  int quads_per_section = 0, sections_per_component = 0, components = 0;
};
UnrealLayout unreal_layout(long long samples) {
  for (int components = 1; components <= 32; ++components)
    for (int sections = 2; sections >= 1; --sections)
      for (auto quads = unreal_quads_per_section.rbegin(); quads != unreal_quads_per_section.rend(); ++quads)
        if (static_cast<long long>(components) * sections * *quads + 1 == samples) return {*quads, sections, components};
  return {};
}

}  // namespace

std::string_view engine_name(Engine engine) {
  switch (engine) {
    case Engine::none:
      return "none";
    case Engine::unreal:
      return "unreal";
    case Engine::unity:
      return "unity";
    case Engine::godot:
      return "godot";
  }
  return "?";
}

bool is_unreal_landscape_size(long long samples) {
  return unreal_layout(samples).components > 0;
}

std::string engine_size_problem(Engine engine, long long width, long long height) {
  switch (engine) {
    case Engine::none:
      return {};
    case Engine::unreal:
      if (is_unreal_landscape_size(width) && is_unreal_landscape_size(height)) return {};
      return "Unreal landscape sizes: components (1-32) x sections (1 or 2) x quads per section (7, 15, 31, 63, 127, 255) + 1, "
             "such as 127, 253, 505, 1009, 2017, 4033, 8129";
    case Engine::unity:
      if (width == height && is_power_of_two_plus_one(width, 33, 4097)) return {};
      return "Unity heightmap resolutions: square, 2^k+1 from 33 to 4097";
    case Engine::godot:
      if (width == height && is_power_of_two_plus_one(width, 65, 4097)) return {};
      return "Godot terrains (HTerrain; Terrain3D takes these too): square, 2^k+1 from 65 to 4097";
  }
  return {};
}

std::vector<std::string> engine_extensions(Engine engine) {
  switch (engine) {
    case Engine::none:
      return {};
    case Engine::unreal:
      return {".r16", ".png"};
    case Engine::unity:
      return {".raw"};
    case Engine::godot:
      return {".r16", ".png"};
  }
  return {};
}

EngineImport engine_import(Engine engine, const Heightfield& heights, const io::HeightRange& range, const std::filesystem::path& file) {
  const double relief_m = range.max_m - range.min_m;
  const double cell = heights.cell_size_m;
  const std::string name = file.filename().string();
  EngineImport out;
  switch (engine) {
    case Engine::none:
      break;
    case Engine::unreal: {
      // Unreal: height_cm = location_z + (level - 32768) * scale_z / 128. With sansui's levels
      // (metres = min + level * relief / 65535) that is scale_z = relief_m * 12800 / 65535 (the
      // familiar relief_m * 100 / 512, exact to 1 part in 65536) and location_z at level 32768.
      const double scale_z = relief_m * 12800.0 / 65535.0;
      const double location_z_cm = (range.min_m + 32768.0 * relief_m / 65535.0) * 100.0;
      const UnrealLayout w = unreal_layout(heights.width()), h = unreal_layout(heights.height());
      out.sidecar = {{"name", "unreal"},
                     {"scale", {{"x", cell * 100.0}, {"y", cell * 100.0}, {"z", scale_z}}},
                     {"location_cm", {{"x", heights.origin_x_m * 100.0}, {"y", heights.origin_y_m * 100.0}, {"z", location_z_cm}}},
                     {"quads_per_section", w.quads_per_section},
                     {"sections_per_component", w.sections_per_component},
                     {"components", {{"x", w.components}, {"y", h.components}}},
                     {"height_cm", "location.z + (level - 32768) * scale.z / 128"}};
      out.note = fmt::format(
          "Unreal: import {} ({}x{}) with Location X {:.10g} Y {:.10g} Z {:.10g} cm, Scale X {:.10g} Y {:.10g} Z {:.10g}; "
          "{} quads per section, {} sections per component, {}x{} components",
          name, heights.width(), heights.height(), heights.origin_x_m * 100.0, heights.origin_y_m * 100.0, location_z_cm, cell * 100.0,
          cell * 100.0, scale_z, w.quads_per_section, w.sections_per_component, w.components, h.components);
      break;
    }
    case Engine::unity: {
      // Unity: height = position.y + level / 65535 * terrain height; x east, z north; the file
      // holds the south row first, the terrain's position is its south-west corner.
      const double width_m = (heights.width() - 1) * cell, length_m = (heights.height() - 1) * cell;
      const double south_west_z = -(heights.origin_y_m + length_m);  // sansui's y grows southwards
      out.sidecar = {{"name", "unity"},
                     {"heightmap_resolution", heights.width()},
                     {"byte_order", "Windows (little-endian)"},
                     {"flip_vertically", false},
                     {"terrain_size_m", {{"x", width_m}, {"y", relief_m}, {"z", length_m}}},
                     {"position_m", {{"x", heights.origin_x_m}, {"y", range.min_m}, {"z", south_west_z}}}};
      out.note = fmt::format(
          "Unity: Import Raw {} (depth 16 bit, resolution {}, byte order Windows, flip vertically off), Terrain Width {:.10g} m, "
          "Length {:.10g} m, Height {:.10g} m; place the terrain at X {:.10g} Y {:.10g} Z {:.10g} m",
          name, heights.width(), width_m, length_m, relief_m, heights.origin_x_m, range.min_m, south_west_z);
      break;
    }
    case Engine::godot: {
      // Godot: x east, -z north, so sansui's y (growing southwards) is Godot's z. Terrain3D reads
      // 16-bit levels as 0..1 (times its scale, plus its offset; .r16 with r16_range = min, max);
      // HTerrain asks for the min and max height.
      out.sidecar = {{"name", "godot"},
                     {"vertex_spacing_m", cell},
                     {"position_m", {{"x", heights.origin_x_m}, {"z", heights.origin_y_m}}},
                     {"terrain3d", {{"r16_range", {range.min_m, range.max_m}}, {"import_scale", relief_m}, {"height_offset", range.min_m}}},
                     {"hterrain", {{"min_height", range.min_m}, {"max_height", range.max_m}, {"map_scale", cell}}}};
      out.note = fmt::format(
          "Godot: Terrain3D: import {} with r16_range / height offset {:.10g} m, scale {:.10g} m (max {:.10g} m), vertex spacing "
          "{:.10g} m, position X {:.10g} Z {:.10g} m; HTerrain: min height {:.10g}, max height {:.10g}, map scale {:.10g}",
          name, range.min_m, relief_m, range.max_m, cell, heights.origin_x_m, heights.origin_y_m, range.min_m, range.max_m, cell);
      break;
    }
  }
  return out;
}

}  // namespace sansui::scene
