#include "scene/recipe_file.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/error.hpp"
#include "core/params_toml.hpp"
#include "core/toml_nesting.hpp"
#include "io/json_text.hpp"
#include "io/sidecar.hpp"
#include "io/text_file.hpp"
#include "scene/recipe_table.hpp"
#include "scene/sources.hpp"

namespace sansui::scene {
namespace {

// ---- writing ---------------------------------------------------------------------------------

/// A value as TOML spells it. Numbers in the fewest digits that read back to the same double.
std::string toml_text(const params::ParamInfo& row, const params::Value& value) {
  struct Visitor {
    const params::ParamInfo& row;
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const {
      std::string text = params::format_number(v);
      if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // a float, not an integer
      return text;
    }
    std::string operator()(const std::string& v) const {
      std::ostringstream out;
      out << toml::value<std::string>(v);
      return out.str();
    }
    std::string operator()(const std::vector<double>& v) const {
      std::string text = "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        text += (i > 0 ? ", " : "") + (row.limits.whole ? params::format_number(v[i]) : (*this)(v[i]));
      return text + "]";
    }
  };
  return std::visit(Visitor{row}, value);
}

std::string comment_for(const params::ParamInfo& row, const params::Value& value) {
  std::string comment = row.help;
  const std::string allowed = params::allowed_text(row);
  if (!allowed.empty())
    comment += " [" + allowed + "]";
  else if (!row.unit.empty())
    comment += " [" + row.unit + "]";
  if (std::holds_alternative<std::monostate>(value)) comment += " (unset: " + params::default_text(row, value) + ")";
  return comment;
}

/// Lines "key = value  # comment" of one table, aligned.
class TomlBlock {
 public:
  void add(std::string key, const params::ParamInfo& row, const params::Value& value) {
    const bool unset = std::holds_alternative<std::monostate>(value);
    lines_.push_back({unset ? "# " + key + " =" : key + " = " + toml_text(row, value), comment_for(row, value)});
  }
  void write(std::string& out) const {
    std::size_t width = 0;
    for (const auto& line : lines_) width = std::max(width, std::min<std::size_t>(line.first.size(), 40));
    for (const auto& [text, comment] : lines_) out += fmt::format("{:<{}}  # {}\n", text, width, comment);
  }

 private:
  std::vector<std::pair<std::string, std::string>> lines_;
};

template <class S>
void write_entry(std::string& out, const std::string& header, const params::Table<S>& table, const S& object, int version) {
  out += "\n[[" + header + "]]\n";
  TomlBlock block;
  for (const auto& row : table.rows)
    if (row.exposed && row.current_in(version)) block.add(row.key, row, row.get(object));
  block.write(out);
}

void write_node(std::string& out, const GraphNode& node) {
  const NodeKind& kind = node.node_kind();
  out += "\n[[node]]\n";
  out += fmt::format("id = {}\nkind = {}\n", toml_text({}, node.id), toml_text({}, node.kind));
  if (!node.inputs.empty()) {
    std::vector<std::string> quoted;
    for (const std::string& input : node.inputs) quoted.push_back(toml_text({}, input));
    out += fmt::format("inputs = [{}]\n", fmt::join(quoted, ", "));
  }
  TomlBlock block;
  for (const auto& row : kind.rows) block.add(row.key, row, kind.get(node.params, row.key));
  block.write(out);
}

nlohmann::json json_of_node(const GraphNode& node) {
  nlohmann::json entry = node.node_kind().to_json(node.params);
  entry["id"] = node.id;
  entry["kind"] = node.kind;
  if (!node.inputs.empty()) entry["inputs"] = node.inputs;
  return entry;
}

void write_section(std::string& out, const Section& section, const Recipe& recipe) {
  const auto& table = recipe_table();
  const std::string prefix = section.name + ".";
  // Keys of the section itself first, then each nested table ([render.camera]) in turn: TOML
  // puts every key after a table header into that table.
  std::vector<std::string> subtables{""};
  for (const auto& row : table.rows) {
    if (!row.exposed || !row.current_in(recipe.version) || section_of(row.key) != section.name) continue;
    const std::string rest = row.key.substr(prefix.size());
    const auto dot = rest.rfind('.');
    const std::string sub = dot == std::string::npos ? "" : rest.substr(0, dot);
    if (std::find(subtables.begin(), subtables.end(), sub) == subtables.end()) subtables.push_back(sub);
  }
  for (const std::string& sub : subtables) {
    const std::string header = sub.empty() ? section.name : section.name + "." + sub;
    out += "\n[" + header + "]\n";
    TomlBlock block;
    for (const auto& row : table.rows) {
      if (!row.exposed || !row.current_in(recipe.version) || section_of(row.key) != section.name) continue;
      const std::string rest = row.key.substr(prefix.size());
      const auto dot = rest.rfind('.');
      if ((dot == std::string::npos ? "" : rest.substr(0, dot)) != sub) continue;
      block.add(dot == std::string::npos ? rest : rest.substr(dot + 1), row, row.get(recipe));
    }
    block.write(out);
  }
}

nlohmann::json json_value(const params::ParamInfo& row, const params::Value& value) {
  struct Visitor {
    const params::ParamInfo& row;
    nlohmann::json operator()(std::monostate) const { return nullptr; }
    nlohmann::json operator()(bool v) const { return v; }
    nlohmann::json operator()(std::int64_t v) const { return v; }
    nlohmann::json operator()(double v) const { return v; }
    nlohmann::json operator()(const std::string& v) const { return v; }
    nlohmann::json operator()(const std::vector<double>& v) const {
      nlohmann::json array = nlohmann::json::array();
      for (double x : v) array.push_back(row.limits.whole ? nlohmann::json(static_cast<std::int64_t>(x)) : nlohmann::json(x));
      return array;
    }
  };
  return std::visit(Visitor{row}, value);
}

template <class S>
nlohmann::json json_entry(const params::Table<S>& table, const S& object, int version) {
  nlohmann::json entry = nlohmann::json::object();
  for (const auto& row : table.rows) {
    if (!row.exposed || !row.current_in(version)) continue;
    const params::Value value = row.get(object);
    if (!std::holds_alternative<std::monostate>(value)) entry[row.key] = json_value(row, value);
  }
  return entry;
}

// ---- reading ---------------------------------------------------------------------------------

/// Where a node stands, for messages: "scene.toml:12" (just the name when the node has no line).
std::string where(const std::string& source, const toml::node& node) {
  const auto line = node.source().begin.line;
  return line > 0 ? fmt::format("{}:{}", source, line) : source;
}

/// A value as the file gave it, on one line, for messages. Numbers are written here, not by
/// toml++'s printer, which overflows on some of them (-2^63, inf, 1e-06: the recipe fuzz
/// target's findings under UBSan).
std::string node_text(const toml::node& node) {
  std::string text;
  if (const toml::array* array = node.as_array()) {
    const std::size_t shown = array->size() > 4 ? 3 : array->size();  // a long list: its first values and its length
    text = "[";
    for (std::size_t i = 0; i < shown; ++i) text += (i > 0 ? ", " : "") + node_text(*array->get(i));
    text += shown < array->size() ? fmt::format(", ... ({} values)]", array->size()) : "]";
  } else if (node.is_table()) {
    text = "{...}";
  } else if (const auto* integer = node.as_integer()) {
    text = std::to_string(integer->get());
  } else if (const auto* real = node.as_floating_point()) {
    text = params::format_number(real->get());
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // 2.0, as written
  } else if (const auto* flag = node.as_boolean()) {
    text = flag->get() ? "true" : "false";
  } else {  // a string, a date or a time
    std::ostringstream out;
    node.visit([&](const auto& n) { out << n; });
    text = out.str();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

std::string kind_words(const params::ParamInfo& row) {
  switch (row.kind) {
    case params::Kind::flag:
      return "true or false";
    case params::Kind::integer:
      return "a whole number";
    case params::Kind::real:
      return "a number";
    case params::Kind::text:
      return "a string";
    case params::Kind::choice:
      return "a string, " + params::allowed_text(row);
    case params::Kind::path:
      return "a file name (a string)";
    case params::Kind::reals:
      return "an array: " + params::allowed_text(row);
  }
  return "?";
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// A key set in the file, to warn about those no one reads.
struct SetKey {
  std::string section, key, where;
};

class Reader {
 public:
  Reader(std::string source, std::filesystem::path base_dir) : source_(std::move(source)), base_dir_(std::move(base_dir)) {}

  LoadedRecipe read(const toml::table& root) {
    version_ = check_version(root);
    LoadedRecipe loaded;
    loaded.recipe = default_recipe(source_kind(root), version_);
    loaded.recipe.base_dir = base_dir_;
    Recipe& recipe = loaded.recipe;
    for (const auto& [key, node] : root) {
      const std::string name(key.str());
      if (name == "sansui_recipe" || name == "source") continue;
      if (name == "shape")
        read_entries<ShapeStep>(name, node, recipe.shape);
      else if (name == "output")
        read_entries<Output>(name, node, recipe.outputs);
      else if (name == "node")
        read_nodes(node, recipe);
      else if (name == "camera" && node.is_array())
        read_cameras(node, recipe);
      else if (find_section(name))
        read_section(name, node, recipe);
      else
        unknown_top_level(name, node);
    }
    check_inputs_exist(recipe);
    settle_world(recipe);
    for (std::string& warning : check_graph(recipe)) loaded.warnings.push_back(std::move(warning));
    for (const SetKey& set : set_)
      for (const Section& section : recipe_sections())
        if (section.name == set.section && !section_used(recipe, section))
          loaded.warnings.push_back(fmt::format("{}: [{}] {} is set but never used: the {} source and the outputs do not read [{}]",
                                                set.where, set.section, set.key, source_name(recipe.source), set.section));
    return loaded;
  }

 private:
  static const Section* find_section(std::string_view name) {
    for (const Section& section : recipe_sections())
      if (section.name == name) return &section;
    return nullptr;
  }

  /// The file's recipe version: its sansui_recipe, or the current one when it has none.
  int check_version(const toml::table& root) const {
    const toml::node* node = root.get("sansui_recipe");
    if (node == nullptr) return recipe_version;
    const auto* version = node->as_integer();
    if (version == nullptr || version->get() < 1)
      fail("{}: sansui_recipe = {} is not allowed: it must be the recipe version, a whole number from 1", where(source_, *node),
           node_text(*node));
    if (version->get() > recipe_version)
      fail("{}: this recipe has version {}, newer than this sansui reads ({}): run it with a newer sansui", where(source_, *node),
           version->get(), recipe_version);
    return static_cast<int>(version->get());
  }

  /// The source the file names, or the one whose sections it sets (none for a graph).
  SourceKind source_kind(const toml::table& root) const {
    if (root.get("node") != nullptr && root.get("source") == nullptr) return SourceKind::none;
    const auto& row = *recipe_table().find("source");
    if (const toml::node* node = root.get("source")) {
      const auto value = params::value_of(row, *node);
      if (!value) fail("{}: source = {} has the wrong type: it must be {}", where(source_, *node), node_text(*node), kind_words(row));
      const std::string problem = params::check(row, *value);
      if (!problem.empty()) fail("{}: source = {} is not allowed: it must be {}", where(source_, *node), node_text(*node), problem);
      return *source_from_name(std::get<std::string>(*value));
    }
    std::vector<std::pair<SourceKind, std::string>> found;
    for (const auto& [key, node] : root) {
      const Section* section = find_section(key.str());
      if (section == nullptr || section->sources.size() != 1) continue;  // [dem] serves two sources
      const SourceKind kind = section->sources.front();
      if (std::none_of(found.begin(), found.end(), [&](const auto& f) { return f.first == kind; })) found.emplace_back(kind, section->name);
    }
    if (found.size() > 1)
      fail("{}: two sources: [{}] belongs to the {} source and [{}] to the {} source; say which with source = \"...\"", source_,
           found[0].second, source_name(found[0].first), found[1].second, source_name(found[1].first));
    return found.empty() ? SourceKind::none : found.front().first;
  }

  /// Sets the row's field from `node`, or fails naming the place, the key and what is allowed.
  template <class S>
  void set_value(const params::Param<S>& row, const std::string& label, const toml::node& node, S& object) {
    if (row.introduced_in > version_)
      fail("{}: {} is a key of recipes of version {} on (this one has version {}): write sansui_recipe = {} to use it",
           where(source_, node), label, row.introduced_in, version_, row.introduced_in);
    if (!row.current_in(version_))
      fail("{}: {} is a key of recipes before version {} (this one has version {}): give {} instead", where(source_, node), label,
           row.superseded_in, version_, row.superseded_by);
    const auto value = params::value_of(row, node);
    if (!value) fail("{}: {} = {} has the wrong type: it must be {}", where(source_, node), label, node_text(node), kind_words(row));
    const std::string problem = params::check(row, *value);
    if (!problem.empty()) fail("{}: {} = {} is not allowed: it must be {}", where(source_, node), label, node_text(node), problem);
    row.set(object, *value);
  }

  void read_section(const std::string& section, const toml::node& node, Recipe& recipe) {
    const auto* table = node.as_table();
    if (table == nullptr) fail("{}: {} must be a table: [{}]", where(source_, node), section, section);
    read_keys(section, "", *table, recipe);
  }

  void read_keys(const std::string& section, const std::string& prefix, const toml::table& table, Recipe& recipe) {
    for (const auto& [key, node] : table) {
      const std::string name = prefix + std::string(key.str());
      std::string key_path = section;
      key_path += '.';
      key_path += name;
      const auto* row = recipe_table().find(key_path);
      if (row == nullptr && node.is_table()) {
        read_keys(section, name + ".", *node.as_table(), recipe);
        continue;
      }
      if (row == nullptr || !row->exposed) unknown_key(section, name, node);
      set_value(*row, fmt::format("[{}] {}", section, name), node, recipe);
      set_.push_back({section, name, where(source_, node)});
    }
  }

  template <class S>
  void read_entries(const std::string& name, const toml::node& node, std::vector<S>& entries) {
    const auto* array = node.as_array();
    if (array == nullptr || !array->is_array_of_tables())
      fail("{}: {} must be an array of tables: [[{}]]", where(source_, node), name, name);
    check_count(name, node, array->size());
    const params::Table<S>& table = params::table_of<S>();
    for (const toml::node& element : *array) {
      S entry{};
      if constexpr (std::is_same_v<S, ShapeStep>) entry = default_shape_step(version_);
      for (const auto& [key, value] : *element.as_table()) {
        const std::string k(key.str());
        const auto* row = table.find(k);
        if (row == nullptr || !row->exposed) {
          std::vector<std::string> keys;
          for (const auto& r : table.rows)
            if (r.exposed && r.current_in(version_)) keys.push_back(r.key);
          const auto near = nearest_key(k, keys);
          fail("{}: unknown key {} in [[{}]]{}: allowed are {}", where(source_, value), k, name,
               near ? fmt::format(" (did you mean `{}`?)", *near) : "", fmt::join(keys, ", "));
        }
        set_value(*row, fmt::format("[[{}]] {}", name, k), value, entry);
      }
      entries.push_back(std::move(entry));
    }
  }

  /// Refuses a list longer than its limit (scene/recipe.hpp) before reading any of it.
  void check_count(const std::string& name, const toml::node& node, std::size_t count) const {
    const std::size_t limit = name == "output"   ? max_outputs
                              : name == "camera" ? max_cameras
                              : name == "shape"  ? max_shape_steps
                                                 : max_nodes;
    if (count > limit) fail("{}: {} [[{}]] tables: a recipe may have at most {}", where(source_, node), count, name, limit);
  }

  /// [[node]] tables: id, kind, inputs, and the kind's own keys (scene/node_kinds.hpp).
  void read_nodes(const toml::node& node, Recipe& recipe) {
    const auto* array = node.as_array();
    if (array == nullptr || !array->is_array_of_tables()) fail("{}: node must be an array of tables: [[node]]", where(source_, node));
    check_count("node", node, array->size());
    for (const toml::node& element : *array) {
      const toml::table& table = *element.as_table();
      GraphNode graph_node;
      graph_node.where = where(source_, element);
      const toml::node* id = table.get("id");
      if (id == nullptr || !id->is_string())
        fail("{}: a [[node]] needs id = \"...\": the name other nodes and outputs take it by", graph_node.where);
      graph_node.id = id->value<std::string>().value_or("");
      const bool id_ok =
          !graph_node.id.empty() && graph_node.id.size() <= 64 &&
          std::all_of(graph_node.id.begin(), graph_node.id.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
      if (!id_ok) fail("{}: node id {} is not allowed: 1 to 64 letters, digits, _ or -", where(source_, *id), node_text(*id));
      const toml::node* kind_node = table.get("kind");
      std::vector<std::string> kinds;
      for (const NodeKind& kind : all_node_kinds()) kinds.push_back(kind.name);
      if (kind_node == nullptr || !kind_node->is_string())
        fail("{}: node `{}` needs kind = \"...\": one of {}", graph_node.where, graph_node.id, fmt::join(kinds, ", "));
      graph_node.kind = kind_node->value<std::string>().value_or("");
      const NodeKind* kind = find_node_kind(graph_node.kind);
      if (kind == nullptr) {
        const auto near = nearest_key(graph_node.kind, kinds);
        fail("{}: node `{}` has the unknown kind `{}`{}: allowed are {}", where(source_, *kind_node), graph_node.id, graph_node.kind,
             near ? fmt::format(" (did you mean `{}`?)", *near) : "", fmt::join(kinds, ", "));
      }
      graph_node.params = kind->make();
      for (const auto& [key, value] : table) {
        const std::string k(key.str());
        if (k == "id" || k == "kind") continue;
        if (k == "inputs") {
          const auto* inputs = value.as_array();
          if (inputs == nullptr || !std::all_of(inputs->begin(), inputs->end(), [](const toml::node& n) { return n.is_string(); }))
            fail("{}: node `{}`: inputs must be an array of node ids, [\"a\", \"b\"]", where(source_, value), graph_node.id);
          for (const toml::node& input : *inputs) graph_node.inputs.push_back(input.value<std::string>().value_or(""));
          continue;
        }
        const params::ParamInfo* row = kind->row(k);
        if (row == nullptr) unknown_node_key(*kind, graph_node.id, k, value);
        const auto parsed = params::value_of(*row, value);
        const std::string label = fmt::format("node `{}` {}", graph_node.id, k);
        if (!parsed)
          fail("{}: {} = {} has the wrong type: it must be {}", where(source_, value), label, node_text(value), kind_words(*row));
        const std::string problem = params::check(*row, *parsed);
        if (!problem.empty()) fail("{}: {} = {} is not allowed: it must be {}", where(source_, value), label, node_text(value), problem);
        kind->set(graph_node.params, k, *parsed);
      }
      recipe.nodes.push_back(std::move(graph_node));
    }
  }

  [[noreturn]] void unknown_node_key(const NodeKind& kind, const std::string& id, const std::string& key, const toml::node& node) const {
    std::vector<std::string> keys{"id", "kind", "inputs"};
    for (const auto& row : kind.rows) keys.push_back(row.key);
    // A fact of the world given again in a node: one place only.
    if (params::table_of<WorldParams>().find(key) != nullptr)
      fail("{}: node `{}` sets `{}`, a key of [world]: the world is set once, in [world], and every node takes it", where(source_, node),
           id, key);
    const auto near = nearest_key(key, keys);
    fail("{}: unknown key `{}` in node `{}` ({}){}: its keys are {}", where(source_, node), key, id, kind.name,
         near ? fmt::format(" (did you mean `{}`?)", *near) : "", fmt::join(keys, ", "));
  }

  /// Several cameras: [[camera]] tables, the first one render.camera.
  void read_cameras(const toml::node& node, Recipe& recipe) {
    std::vector<look::Camera> cameras;
    read_entries<look::Camera>("camera", node, cameras);
    if (cameras.empty())
      fail("{}: camera = [] names no camera: give one [camera] table or several [[camera]] tables", where(source_, node));
    recipe.render.camera = cameras.front();
    recipe.more_cameras.assign(cameras.begin() + 1, cameras.end());
  }

  [[noreturn]] void unknown_key(const std::string& section, const std::string& key, const toml::node& node) const {
    std::vector<std::string> keys;
    const std::string prefix = section + ".";
    for (const auto& row : recipe_table().rows)
      if (row.exposed && row.current_in(version_) && section_of(row.key) == section) keys.push_back(row.key.substr(prefix.size()));
    std::string hint;
    if (const auto near = nearest_key(key, keys)) hint = fmt::format(": did you mean `{}`?", *near);
    for (const auto& row : recipe_table().rows) {
      const auto dot = row.key.find('.');
      if (row.exposed && row.current_in(version_) && dot != std::string::npos && row.key.substr(dot + 1) == key &&
          row.key.substr(0, dot) != section) {
        hint = fmt::format(": `{}` belongs in [{}]", key, row.key.substr(0, dot));
        break;
      }
    }
    fail("{}: unknown key `{}` in [{}]{} (its keys: {})", where(source_, node), key, section, hint, fmt::join(keys, ", "));
  }

  [[noreturn]] void unknown_top_level(const std::string& name, const toml::node& node) const {
    std::vector<std::string> names{"sansui_recipe", "source", "shape", "output", "node"};
    for (const Section& section : recipe_sections()) names.push_back(section.name);
    std::string hint;
    if (const auto near = nearest_key(name, names)) hint = fmt::format(": did you mean `{}`?", *near);
    for (const auto& row : recipe_table().rows) {
      const auto dot = row.key.find('.');
      if (row.exposed && row.current_in(version_) && dot != std::string::npos && row.key.substr(dot + 1) == name) {
        hint = fmt::format(": `{}` belongs in [{}]", name, row.key.substr(0, dot));
        break;
      }
    }
    fail("{}: unknown {} `{}`{}", where(source_, node), node.is_table() ? "section" : "key", name, hint);
  }

  /// Every input file a used section names must exist: said here, with its line.
  void check_inputs_exist(const Recipe& recipe) const {
    for (const Section& section : recipe_sections()) {
      if (!section_used(recipe, section)) continue;
      for (const SetKey& set : set_) {
        if (set.section != section.name) continue;
        const auto* row = recipe_table().find(set.section + "." + set.key);
        if (row == nullptr || row->kind != params::Kind::path) continue;
        const std::string name = std::get<std::string>(row->get(recipe));
        if (name.empty()) continue;
        const std::filesystem::path path = std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : base_dir_ / name;
        std::error_code error;
        if (!std::filesystem::is_regular_file(path, error))
          fail("{}: [{}] {} = \"{}\": no such file ({})", set.where, set.section, set.key, name, path.string());
      }
    }
  }

  std::string source_;
  std::filesystem::path base_dir_;
  int version_ = recipe_version;
  std::vector<SetKey> set_;
};

/// A sidecar's recipe (JSON) as a TOML table, so one reader serves both. A JSON value TOML has
/// no word for is refused here, naming its key, rather than dropped: a dropped `"size": null`
/// would take the default silently, and a whole number past 2^63 - 1 would wrap to a negative.
class JsonToToml {
 public:
  explicit JsonToToml(std::string source) : source_(std::move(source)) {}

  toml::table table(const nlohmann::json& object, const std::string& path) const {
    toml::table table;
    if (!object.is_object()) return table;
    for (const auto& item : object.items()) {
      const std::string& key = item.key();
      const nlohmann::json& value = item.value();
      const std::string inner = path.empty() ? key : fmt::format("{}.{}", path, key);
      if (value.is_object())
        table.insert(key, this->table(value, inner));
      else if (value.is_array())
        table.insert(key, array(value, inner));
      else
        scalar(value, inner, [&](auto v) { table.insert(key, std::move(v)); });
    }
    return table;
  }

 private:
  toml::array array(const nlohmann::json& list, const std::string& path) const {
    toml::array array;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const nlohmann::json& value = list[i];
      const std::string inner = fmt::format("{}[{}]", path, i);
      if (value.is_object())
        array.push_back(table(value, inner));
      else if (value.is_array())
        array.push_back(this->array(value, inner));
      else
        scalar(value, inner, [&](auto v) { array.push_back(std::move(v)); });
    }
    return array;
  }

  /// Gives `add` a string, a boolean, a whole number or a number, as TOML holds it.
  template <class Add>
  void scalar(const nlohmann::json& value, const std::string& path, Add&& add) const {
    switch (value.type()) {
      case nlohmann::json::value_t::string:
        return add(value.get<std::string>());
      case nlohmann::json::value_t::boolean:
        return add(value.get<bool>());
      case nlohmann::json::value_t::number_integer:
        return add(value.get<std::int64_t>());
      case nlohmann::json::value_t::number_unsigned:
        if (value.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
          fail("{}: {} = {} is too large: a whole number in a recipe is at most 2^63 - 1", source_, path, value.dump());
        return add(value.get<std::int64_t>());
      case nlohmann::json::value_t::number_float:
        return add(value.get<double>());
      default:
        break;
    }
    fail("{}: {} is null: give it a value, or leave the key out to take its default", source_, path);
  }

  std::string source_;
};

/// How deeply arrays and objects nest (a recipe needs 4): checked before converting, so that a
/// hostile file cannot exhaust the stack.
int depth_of(const nlohmann::json& value) {
  int deepest = 0;
  std::vector<std::pair<const nlohmann::json*, int>> stack{{&value, 1}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    if (depth > 64) break;
    if (node->is_structured())
      for (const auto& child : *node) stack.emplace_back(&child, depth + 1);
  }
  return deepest;
}

/// Where a recipe file really is, links resolved: its relative names lead from there, as the
/// system resolves them (a "../x" in a folder reached through a link leads out of the link's
/// target, not back out of the link).
std::filesystem::path real_path_of(const std::filesystem::path& file) {
  std::error_code error;
  std::filesystem::path real = std::filesystem::weakly_canonical(std::filesystem::absolute(file), error);
  return error ? std::filesystem::absolute(file).lexically_normal() : real;
}

LoadedRecipe load_sidecar(const std::filesystem::path& file, const std::string& text) {
  const nlohmann::json sidecar = io::parse_json(text, file.string());
  if (!sidecar.is_object()) fail("{}: not a recipe: neither a TOML scene file nor a JSON sidecar", file.string());
  const auto version = sidecar.find("sansui_sidecar");
  if (version == sidecar.end() || !version->is_number_integer())
    fail("{}: not a Sansui sidecar (no \"sansui_sidecar\" version): a recipe is a .toml scene file or an output's .json sidecar",
         file.string());
  if (version->get<std::int64_t>() > io::sidecar_version)
    fail("{}: this sidecar has version {}, newer than this sansui reads ({}): run it with a newer sansui", file.string(), version->dump(),
         io::sidecar_version);
  const nlohmann::json* recipe = nullptr;
  if (auto provenance = sidecar.find("provenance"); provenance != sidecar.end() && provenance->is_object())
    if (auto found = provenance->find("recipe"); found != provenance->end()) recipe = &*found;
  if (recipe == nullptr || !recipe->is_object())
    fail("{}: this sidecar holds no recipe (sidecar version {}; recipes came with version 2): run the command that wrote it again",
         file.string(), version->dump());
  if (depth_of(*recipe) > 8) fail("{}: its recipe is nested deeper than a recipe can be", file.string());
  const std::filesystem::path base = real_path_of(file).parent_path();
  const std::string source = file.string() + " (its recipe)";
  LoadedRecipe loaded = Reader(source, base).read(JsonToToml(source).table(*recipe, ""));
  // Terrains of 0.2 draw their random numbers as Box-Muller pairs (issue 16): a midpoint terrain
  // (or a contour mountain's foothills) recorded by 0.1 is rebuilt, but not byte for byte. Say so
  // rather than let it look the same.
  const nlohmann::json& provenance = sidecar.at("provenance");
  const auto version_of = provenance.find("version");
  const std::string written_by = version_of != provenance.end() && version_of->is_string() ? version_of->get<std::string>() : "0.1";
  const bool has_terrain = loaded.recipe.source == SourceKind::midpoint || loaded.recipe.source == SourceKind::contour;  // foothills
  if (written_by.rfind("0.1", 0) == 0 && has_terrain)
    loaded.warnings.push_back(fmt::format(
        "{}: written by sansui {}, whose midpoint terrains drew other random numbers: this sansui ({}) rebuilds a terrain of the same "
        "recipe, not the same bytes",
        file.string(), written_by, SANSUI_VERSION));
  return loaded;
}

}  // namespace

std::optional<std::string> nearest_key(std::string_view key, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(key, candidate);
    if (distance < best_distance) best = candidate, best_distance = distance;
  }
  return best;
}

LoadedRecipe parse_recipe_toml(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
  check_toml_nesting(text, source);
  toml::table root;
  try {
    root = toml::parse(text, std::string_view(source));
  } catch (const toml::parse_error& e) {
    fail("{}:{}: not valid TOML: {}", source, e.source().begin.line, e.description());
  }
  return Reader(source, base_dir).read(root);
}

LoadedRecipe parse_recipe_table(const toml::table& root, const std::string& source, const std::filesystem::path& base_dir) {
  return Reader(source, base_dir).read(root);
}

LoadedRecipe load_recipe(const std::filesystem::path& file) {
  const std::string text = io::read_text_file(file, std::size_t(64) << 20);
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  LoadedRecipe loaded =
      extension == ".json" ? load_sidecar(file, text) : parse_recipe_toml(text, file.string(), real_path_of(file).parent_path());
  // A recipe file may have come from anyone: it writes only inside its folder, and never over itself.
  loaded.recipe.output_rules.recipe_file = real_path_of(file);
  loaded.recipe.output_rules.confined_to = real_path_of(file).parent_path();
  return loaded;
}

std::string recipe_to_toml(const Recipe& recipe, std::string_view heading) {
  std::string out;
  if (!heading.empty()) out += std::string(heading);
  out +=
      "# A Sansui recipe: a source, shaping steps and outputs. Run it with `sansui run FILE`.\n"
      "# File names are relative to this file. Every key of the sections this recipe reads is listed;\n"
      "# unset keys are commented out. docs/params.md explains every key.\n\n";
  out += fmt::format("sansui_recipe = {}\n", recipe.version);
  const auto& source_row = *recipe_table().find("source");
  out += fmt::format("source = {}  # {}\n", toml_text(source_row, source_row.get(recipe)), comment_for(source_row, source_row.get(recipe)));
  for (const Section& section : recipe_sections())
    if (section_used(recipe, section)) {
      out += "\n# " + section.title;
      if (section.name == "camera" && !recipe.more_cameras.empty()) {
        // TOML has no [camera] beside [[camera]]: with several cameras, all are [[camera]].
        write_entry(out, "camera", params::table_of<look::Camera>(), recipe.render.camera, recipe.version);
        for (const look::Camera& camera : recipe.more_cameras)
          write_entry(out, "camera", params::table_of<look::Camera>(), camera, recipe.version);
        continue;
      }
      write_section(out, section, recipe);
    }
  for (const ShapeStep& step : recipe.shape) write_entry(out, "shape", params::table_of<ShapeStep>(), step, recipe.version);
  for (const GraphNode& node : recipe.nodes) write_node(out, node);
  for (const Output& output : recipe.outputs) write_entry(out, "output", params::table_of<Output>(), output, recipe.version);
  return out;
}

nlohmann::json recipe_to_json(const Recipe& recipe) {
  nlohmann::json json = {{"sansui_recipe", recipe.version}, {"source", source_name(recipe.source)}};
  const auto& table = recipe_table();
  for (const Section& section : recipe_sections()) {
    if (!section_used(recipe, section)) continue;
    nlohmann::json entry = nlohmann::json::object();
    for (const auto& row : table.rows) {
      if (!row.exposed || !row.current_in(recipe.version) || section_of(row.key) != section.name) continue;
      const params::Value value = row.get(recipe);
      if (std::holds_alternative<std::monostate>(value)) continue;
      // Nested tables become nested objects: "camera.azimuth" -> {"camera": {"azimuth": ...}}.
      nlohmann::json* place = &entry;
      std::string rest = row.key.substr(section.name.size() + 1);
      for (auto dot = rest.find('.'); dot != std::string::npos; dot = rest.find('.')) {
        place = &(*place)[rest.substr(0, dot)];
        rest = rest.substr(dot + 1);
      }
      (*place)[rest] = json_value(row, value);
    }
    json[section.name] = entry;
    if (section.name == "camera" && !recipe.more_cameras.empty()) {
      json["camera"] = nlohmann::json::array({entry});
      for (const look::Camera& camera : recipe.more_cameras)
        json["camera"].push_back(json_entry(params::table_of<look::Camera>(), camera, recipe.version));
    }
  }
  if (!recipe.shape.empty()) {
    json["shape"] = nlohmann::json::array();
    for (const ShapeStep& step : recipe.shape) json["shape"].push_back(json_entry(params::table_of<ShapeStep>(), step, recipe.version));
  }
  if (!recipe.nodes.empty()) {
    json["node"] = nlohmann::json::array();
    for (const GraphNode& node : recipe.nodes) json["node"].push_back(json_of_node(node));
  }
  json["output"] = nlohmann::json::array();
  for (const Output& output : recipe.outputs) json["output"].push_back(json_entry(params::table_of<Output>(), output, recipe.version));
  return json;
}

Recipe with_outputs_in(Recipe recipe, const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  // A tiled world checks its folder on every rank at once (tiled_world.hpp), so that every rank
  // stops alike.
  if (error && !recipe.world.tiled) fail("cannot make the output folder {}: {}", dir.string(), error.message());
  const std::filesystem::path absolute = std::filesystem::absolute(dir).lexically_normal();
  for (auto& output : recipe.outputs)
    if (!output.file.empty())
      // Against the base folder written without ".." (../recipes from another folder): the
      // relative name then leads where it is meant to.
      output.file = (absolute / std::filesystem::path(output.file).filename())
                        .lexically_relative(std::filesystem::absolute(recipe.base_dir).lexically_normal())
                        .string();
  recipe.output_rules.confined_to = absolute;
  return recipe;
}

Recipe rebased(Recipe recipe, const std::filesystem::path& base_dir) {
  const std::filesystem::path old_base =
      std::filesystem::absolute(recipe.base_dir.empty() ? std::filesystem::current_path() : recipe.base_dir);
  const std::filesystem::path new_base = std::filesystem::absolute(base_dir).lexically_normal();
  auto move = [&](std::string& name) {
    if (name.empty() || std::filesystem::path(name).is_absolute()) return;
    name = (old_base / name).lexically_normal().lexically_relative(new_base).generic_string();
  };
  const auto& table = recipe_table();
  for (const auto& row : table.rows) {
    if (row.kind != params::Kind::path) continue;
    std::string name = std::get<std::string>(row.get(recipe));
    move(name);
    row.set(recipe, name);
  }
  for (Output& output : recipe.outputs) move(output.file);
  for (GraphNode& node : recipe.nodes) {
    const NodeKind& kind = node.node_kind();
    for (const auto& row : kind.rows) {
      if (row.kind != params::Kind::path) continue;
      std::string name = std::get<std::string>(kind.get(node.params, row.key));
      move(name);
      kind.set(node.params, row.key, name);
    }
  }
  recipe.base_dir = new_base;
  return recipe;
}

Recipe restricted(Recipe recipe, std::size_t index) {
  Output only = recipe.outputs.at(index);
  // A render output's recipe keeps only the camera it draws with.
  if (const look::Camera* camera = camera_for(recipe, only); camera != nullptr && !recipe.more_cameras.empty()) {
    recipe.render.camera = *camera;
    recipe.more_cameras.clear();
    only.camera.clear();
  }
  if (!recipe.nodes.empty()) {
    // A graph's output keeps the nodes it takes, and names its node.
    only.node = output_node(recipe, index).id;
    const std::vector<std::string> needed = ancestors(recipe.nodes, only.node);
    std::erase_if(recipe.nodes, [&](const GraphNode& node) { return std::find(needed.begin(), needed.end(), node.id) == needed.end(); });
  }
  recipe.outputs = {std::move(only)};
  return recipe;
}

void save_recipe(const std::filesystem::path& file, const Recipe& recipe) {
  const Recipe here = rebased(recipe, std::filesystem::absolute(file).parent_path());
  io::write_text_file(file, recipe_to_toml(here), "recipe");
}

std::string default_recipe_text(SourceKind source) {
  Recipe recipe = default_recipe(source);
  const detail::SourceEntry& entry = detail::source_entry(source);
  entry.example(recipe);
  return recipe_to_toml(recipe, fmt::format("# Defaults of the {} source ({}).\n", entry.name, entry.example_note));
}

}  // namespace sansui::scene
