#include "io/plant_instances.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "io/binary_file.hpp"
#include "io/file_formats.hpp"
#include "io/json_text.hpp"
#include "io/sidecar.hpp"
#include "io/text_file.hpp"

namespace sansui::io {
namespace {

using Instance = PlacedPlant;

constexpr std::string_view csv_header = "layer,species,x_east_m,y_south_m,height_m,scale,rotation_deg,variant";
constexpr int json_version = 1;

float degrees_of(float radians) {
  return static_cast<float>(double(radians) * (180.0 / std::numbers::pi));
}
float radians_of(double degrees) {
  return static_cast<float>(degrees * (std::numbers::pi / 180.0));
}

/// One row, as CSV or as a JSON object. Floats in their shortest form that reads back to the same
/// float (fmt's "{}"), so positions round-trip exactly. `species` is ready to paste: quoted in JSON.
void append_row(fmt::memory_buffer& out, PlantFormat format, std::string_view layer, std::string_view species, const Instance& p,
                bool first) {
  if (format == PlantFormat::csv) {
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{}\n", layer, species, p.x_m, p.y_m, p.height_m, p.scale,
                   degrees_of(p.rotation_rad), p.variant);
    return;
  }
  fmt::format_to(std::back_inserter(out),
                 "{}\n{{\"layer\":\"{}\",\"species\":{},\"x_east_m\":{},\"y_south_m\":{},\"height_m\":{},\"scale\":{},"
                 "\"rotation_deg\":{},\"variant\":{}}}",
                 first ? "" : ",", layer, species, p.x_m, p.y_m, p.height_m, p.scale, degrees_of(p.rotation_rad), p.variant);
}

void write_rows(detail::OutputFile& file, PlantFormat format, std::span<const Instance> trees, std::span<const Instance> ground,
                const PlantCatalogue& catalogue, const std::filesystem::path& path) {
  // Species names as they go into a row, made once per file rather than once per plant.
  std::vector<std::string> names;
  for (const std::string& species : catalogue.species) names.push_back(format == PlantFormat::csv ? species : dump_json(species));

  fmt::memory_buffer out;
  if (format == PlantFormat::csv)
    fmt::format_to(std::back_inserter(out), "{}\n", csv_header);
  else
    fmt::format_to(std::back_inserter(out), "{{\"sansui_plant_instances\":{},\"instances\":[", json_version);
  bool first = true;
  for (const auto& [layer, instances] : {std::pair{"tree", trees}, std::pair{"ground", ground}})
    for (const Instance& plant : instances) {
      if (plant.species >= names.size())
        fail("cannot write {}: species index {} is not allowed: the library has {} species", path.string(), plant.species, names.size());
      append_row(out, format, layer, names[plant.species], plant, first);
      first = false;
      if (out.size() > (std::size_t(1) << 20)) {  // streamed: a million plants would be a 100 MB string
        file.write(out.data(), out.size());
        out.clear();
      }
    }
  if (format == PlantFormat::json) fmt::format_to(std::back_inserter(out), "\n]}}\n");
  file.write(out.data(), out.size());
}

// ---- reading ----------------------------------------------------------------------------------

template <class T>
T number_in(std::string_view text, std::string_view what, const std::string& where) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) fail("{}: {} '{}' is not a number", where, what, text);
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) fail("{}: {} '{}' is not allowed: numbers must be finite", where, what, text);
  return value;
}

std::uint16_t species_index(const std::string& name, const PlantCatalogue& catalogue, const std::string& where) {
  for (std::size_t i = 0; i < catalogue.species.size(); ++i)
    if (catalogue.species[i] == name) return static_cast<std::uint16_t>(i);
  std::string names;
  for (const std::string& species : catalogue.species) names += (names.empty() ? "" : ", ") + species;
  fail("{}: species '{}' is not known: it must be one of {}", where, name, names);
}

void add_plant(PlantLayers& placement, std::string_view layer, Instance plant, const PlantCatalogue& catalogue, const std::string& where) {
  if (plant.variant >= catalogue.variants)
    fail("{}: variant {} is not allowed: it must be 0..{}", where, plant.variant, catalogue.variants - 1);
  if (layer == "tree")
    placement.trees.push_back(plant);
  else if (layer == "ground")
    placement.ground.push_back(plant);
  else
    fail("{}: layer '{}' is not allowed: it must be tree or ground", where, layer);
}

PlantLayers parse_csv(std::string_view text, const std::string& source, const PlantCatalogue& catalogue) {
  PlantLayers placement;
  int line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string where = fmt::format("{}:{}", source, line_number);
    if (line_number == 1) {
      if (line != csv_header) fail("{}: the header must be {}", where, csv_header);
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string_view> fields;
    for (std::size_t from = 0;;) {
      const std::size_t comma = line.find(',', from);
      fields.push_back(line.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from));
      if (comma == std::string_view::npos) break;
      from = comma + 1;
    }
    if (fields.size() != 8) fail("{}: {} fields, 8 expected ({})", where, fields.size(), csv_header);
    Instance plant;
    plant.species = species_index(std::string(fields[1]), catalogue, where);
    plant.x_m = number_in<float>(fields[2], "x_east_m", where);
    plant.y_m = number_in<float>(fields[3], "y_south_m", where);
    plant.height_m = number_in<float>(fields[4], "height_m", where);
    plant.scale = number_in<float>(fields[5], "scale", where);
    plant.rotation_rad = radians_of(number_in<float>(fields[6], "rotation_deg", where));
    plant.variant = number_in<std::uint16_t>(fields[7], "variant", where);
    add_plant(placement, fields[0], plant, catalogue, where);
  }
  if (line_number == 0) fail("{}: empty, the header {} expected", source, csv_header);
  return placement;
}

PlantLayers parse_json(std::string_view text, const std::string& source, const PlantCatalogue& catalogue) {
  const nlohmann::json root = io::parse_json(text, source);
  if (!root.is_object() || !root.contains("instances") || !root["instances"].is_array() || !root.contains("sansui_plant_instances"))
    fail("{}: not a sansui plant instance file (an object with sansui_plant_instances and an instances array)", source);
  if (root["sansui_plant_instances"] != json_version)
    fail("{}: sansui_plant_instances {} is not allowed: this version reads {}", source, root["sansui_plant_instances"].dump(),
         json_version);
  PlantLayers placement;
  std::size_t index = 0;
  for (const auto& row : root["instances"]) {
    const std::string where = fmt::format("{}: instance {}", source, index++);
    try {
      Instance plant;
      plant.species = species_index(row.at("species").get<std::string>(), catalogue, where);
      plant.x_m = row.at("x_east_m").get<float>();
      plant.y_m = row.at("y_south_m").get<float>();
      plant.height_m = row.at("height_m").get<float>();
      plant.scale = row.at("scale").get<float>();
      plant.rotation_rad = radians_of(row.at("rotation_deg").get<float>());
      const auto variant = whole_number_in(row.at("variant"), 0, catalogue.variants - 1);
      if (!variant) fail("{}: variant {} is not allowed: it must be 0..{}", where, row.at("variant").dump(), catalogue.variants - 1);
      plant.variant = static_cast<std::uint16_t>(*variant);
      for (float value : {plant.x_m, plant.y_m, plant.height_m, plant.scale, plant.rotation_rad})
        if (!std::isfinite(value)) fail("{}: the number {} is not allowed: numbers must be finite", where, value);
      add_plant(placement, row.at("layer").get<std::string>(), plant, catalogue, where);
    } catch (const nlohmann::json::exception& e) {
      fail("{}: not a plant instance ({})", where, json_error_text(e));
    }
  }
  return placement;
}

PlantFormat format_or_fail(const std::filesystem::path& path, std::string_view action) {
  const auto format = plant_format_for(path);
  if (!format)
    fail("cannot {} {}: unknown extension '{}': plant instances are {}", action, path.string(), path.extension().string(),
         fmt::join(extensions_of({"csv", "json"}), " "));
  return *format;
}

}  // namespace

std::optional<PlantFormat> plant_format_for(const std::filesystem::path& path) {
  const FileFormat* format = file_format_for(path, FormatData::table, Access::write);
  if (format && format->name == "csv") return PlantFormat::csv;
  if (format && format->name == "json") return PlantFormat::json;
  return std::nullopt;
}

void write_plant_instances(const std::filesystem::path& path, std::span<const PlacedPlant> trees, std::span<const PlacedPlant> ground,
                           const PlantCatalogue& catalogue, const std::optional<nlohmann::json>& provenance) {
  const PlantFormat format = format_or_fail(path, "write");
  std::optional<nlohmann::json> sidecar;
  if (provenance) {
    sidecar = detail::sidecar_head("plant instances", path);
    (*sidecar)["provenance"] = *provenance;
  }
  detail::write_with_sidecar(path, sidecar, [&](const std::filesystem::path& temporary) {
    detail::OutputFile file(temporary, path);
    write_rows(file, format, trees, ground, catalogue, path);
    file.close();
  });
}

PlantLayers read_plant_instances(const std::filesystem::path& path, const PlantCatalogue& catalogue) {
  const PlantFormat format = format_or_fail(path, "read");
  const std::string text = read_text_file(path);
  return format == PlantFormat::csv ? parse_csv(text, path.string(), catalogue) : parse_json(text, path.string(), catalogue);
}

}  // namespace sansui::io
