// The registry of node kinds (see node_kinds.hpp).
#include "scene/node_kinds.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace sansui::scene {

std::string_view value_type_name(ValueType type) {
  return type == ValueType::mask ? "a mask" : "heights";
}

std::string GraphWorld::key() const {
  std::string key = has_grid() ? fmt::format("grid {}x{} cell {}", width, height, params::format_number(cell_m)) : "the source's grid";
  if (origin_x_m != 0.0 || origin_y_m != 0.0)
    key += fmt::format(" origin {} {}", params::format_number(origin_x_m), params::format_number(origin_y_m));
  key += " sea " + params::format_number(sea_level_m);
  // Only what a chain before version 3 adds:
  if (midpoint_datum_m) key += fmt::format(" midpoint datum {}", params::format_number(*midpoint_datum_m));
  if (version != 0) key += fmt::format(" version {}", version);
  if (base_level_m) key += " base level " + params::format_number(*base_level_m);
  return key;
}

std::filesystem::path GraphWorld::resolve(const std::string& name) const {
  const std::filesystem::path path(name);
  return path.is_absolute() || base_dir.empty() ? path : std::filesystem::path(base_dir) / path;
}

const params::ParamInfo* NodeKind::row(std::string_view key) const {
  for (const auto& r : rows)
    if (r.key == key) return &r;
  return nullptr;
}

nlohmann::json NodeKind::to_json(const std::any& params) const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& r : rows) {
    const params::Value value = get(params, r.key);
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (!std::is_same_v<V, std::monostate>) out[r.key] = v;
        },
        value);
  }
  return out;
}

std::size_t NodeKind::required_inputs() const {
  return static_cast<std::size_t>(std::count_if(inputs.begin(), inputs.end(), [](const InputSlot& s) { return !s.optional; }));
}

const std::vector<NodeKind>& all_node_kinds() {
  static const std::vector<NodeKind> kinds = [] {
    std::vector<NodeKind> all;
    add_terrain_kinds(all);
    add_mesh_kinds(all);
    add_mask_kinds(all);
    add_flow_kinds(all);
    return all;
  }();
  return kinds;
}

const NodeKind* find_node_kind(std::string_view name) {
  for (const NodeKind& kind : all_node_kinds())
    if (kind.name == name) return &kind;
  return nullptr;
}

}  // namespace sansui::scene
