#include "tests/fuzz/structured_mutator.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "core/params.hpp"
#include "look/render_params.hpp"
#include "scene/node_kinds.hpp"
#include "scene/recipe.hpp"
#include "vegetation/species.hpp"

namespace sansui::test {
namespace {

using Json = nlohmann::ordered_json;

/// splitmix64: the same numbers with every standard library (no std::*_distribution).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  /// 0 .. n-1 (0 when n is 0).
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
  bool chance(int one_in) { return below(static_cast<std::size_t>(one_in)) == 0; }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[below(items.size())];
  }

 private:
  std::uint64_t state_;
};

// ---- text <-> tree ---------------------------------------------------------------------------

/// Strings starting with this byte are written without quotes, as they are: tokens that neither
/// format's value types hold (nan, inf, 1e999, 18446744073709551615, dates).
constexpr char raw_mark = '\x01';

Json raw(std::string text) {
  return std::string(1, raw_mark) + text;
}

bool is_raw(const Json& value) {
  return value.is_string() && !value.get_ref<const std::string&>().empty() && value.get_ref<const std::string&>()[0] == raw_mark;
}

/// Deepest bracket nesting of the text (quotes ignored): deeper inputs are left to byte
/// mutations, so that the harness's own recursion stays shallow.
int bracket_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  for (char c : text) {
    if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    if (c == ']' || c == '}') depth = std::max(0, depth - 1);
  }
  return deepest;
}
constexpr int max_parsed_depth = 300;

Json from_toml(const toml::node& node) {
  if (const auto* table = node.as_table()) {
    Json object = Json::object();
    for (const auto& [key, value] : *table) object[std::string(key.str())] = from_toml(value);
    return object;
  }
  if (const auto* array = node.as_array()) {
    Json list = Json::array();
    for (const auto& value : *array) list.push_back(from_toml(value));
    return list;
  }
  if (const auto* text = node.as_string()) return text->get();
  if (const auto* integer = node.as_integer()) return integer->get();
  if (const auto* boolean = node.as_boolean()) return boolean->get();
  if (const auto* real = node.as_floating_point()) {
    const double v = real->get();
    if (std::isnan(v)) return raw("nan");
    if (std::isinf(v)) return raw(v > 0 ? "inf" : "-inf");
    return v;
  }
  std::ostringstream text;  // dates and times
  node.visit([&](auto&& value) { text << value; });
  return raw(text.str());
}

std::optional<Json> parse(std::string_view text, bool json) {
  if (bracket_depth(text) > max_parsed_depth) return std::nullopt;
  if (json) {
    Json doc = Json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
    return doc;
  }
  try {
    return from_toml(toml::parse(text));
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

std::string toml_string(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\')
      out += '\\', out += static_cast<char>(c);
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else
      out += static_cast<char>(c);
  }
  return out + "\"";
}

std::string toml_key(const std::string& key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
  return bare ? key : toml_string(key);
}

void toml_inline(std::string& out, const Json& value) {
  if (is_raw(value)) {
    out += value.get_ref<const std::string&>().substr(1);
  } else if (value.is_string()) {
    out += toml_string(value.get_ref<const std::string&>());
  } else if (value.is_object()) {
    out += "{";
    const char* comma = " ";
    for (const auto& [key, item] : value.items()) {
      out += comma + toml_key(key) + " = ";
      toml_inline(out, item);
      comma = ", ";
    }
    out += value.empty() ? "}" : " }";
  } else if (value.is_array()) {
    out += "[";
    const char* comma = "";
    for (const auto& item : value) {
      out += comma;
      toml_inline(out, item);
      comma = ", ";
    }
    out += "]";
  } else if (value.is_null()) {
    out += "\"\"";  // TOML has no null
  } else {
    out += value.dump();  // numbers (floats keep their ".0"), booleans
  }
}

bool is_table_array(const Json& value) {
  return value.is_array() && !value.empty() && std::all_of(value.begin(), value.end(), [](const Json& v) { return v.is_object(); });
}

/// Tables nested deeper than this are written inline ({ a = { a = ... } }), so that deepening
/// grows the text linearly, not by a header of every depth.
constexpr int max_header_depth = 12;

void toml_table(std::string& out, const Json& table, const std::string& path, bool entry, int level) {
  if (!path.empty()) out += (entry ? "\n[[" : "\n[") + path + (entry ? "]]\n" : "]\n");
  const bool inline_all = level >= max_header_depth;
  for (const auto& [key, value] : table.items())
    if (inline_all || (!value.is_object() && !is_table_array(value))) {
      out += toml_key(key) + " = ";
      toml_inline(out, value);
      out += "\n";
    }
  if (inline_all) return;
  for (const auto& [key, value] : table.items()) {
    const std::string inner = path.empty() ? toml_key(key) : path + "." + toml_key(key);
    if (value.is_object())
      toml_table(out, value, inner, false, level + 1);
    else if (is_table_array(value))
      for (const Json& item : value) toml_table(out, item, inner, true, level + 1);
  }
}

std::string to_text(const Json& doc, bool json) {
  if (!json) {
    std::string out;
    toml_table(out, doc, "", false, 0);
    return out;
  }
  std::string out = doc.dump(1, ' ', false, Json::error_handler_t::replace);
  // Raw tokens: "\u0001TOKEN" -> TOKEN (tokens hold no quote).
  for (std::size_t at = out.find("\"\\u0001"); at != std::string::npos; at = out.find("\"\\u0001", at)) {
    const std::size_t end = out.find('"', at + 7);
    if (end == std::string::npos) break;
    out.replace(at, end + 1 - at, out.substr(at + 7, end - at - 7));
  }
  return out;
}

// ---- where values are, and what their rows allow ----------------------------------------------

/// One value of the tree: the container holding it (null for the root) and its place there.
struct Site {
  Json* parent = nullptr;
  std::string key;        ///< in an object
  std::size_t index = 0;  ///< in an array
  /// Keys from the root of the entry it belongs to: the recipe's root, or an [[array]] entry's.
  std::vector<std::string> path;
  std::string array_root;  ///< the top-level [[array]] it is inside ("output", "species", ...), or ""
  Json* entry = nullptr;   ///< that [[array]] entry

  Json& value() const { return parent->is_object() ? (*parent)[key] : (*parent)[index]; }
};

void collect(Json& value, const Site& here, int depth, std::vector<Site>& sites) {
  if (depth > 40) return;
  if (value.is_object()) {
    for (auto& [key, item] : value.items()) {
      Site site = here;
      site.parent = &value, site.key = key;
      site.path.push_back(key);
      if (depth == 0 && is_table_array(item)) {
        sites.push_back(site);  // the array itself
        for (std::size_t i = 0; i < item.size(); ++i) {
          Site entry;
          entry.parent = &item, entry.index = i, entry.array_root = key, entry.entry = &item[i];
          sites.push_back(entry);
          collect(item[i], entry, depth + 1, sites);
        }
        continue;
      }
      sites.push_back(site);
      collect(item, site, depth + 1, sites);
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      Site site = here;
      site.parent = &value, site.key.clear(), site.index = i;
      sites.push_back(site);
      collect(value[i], site, depth + 1, sites);
    }
  }
}

std::vector<const params::ParamInfo*> rows_of_table(const auto& table) {
  std::vector<const params::ParamInfo*> rows;
  for (const auto& row : table.rows) rows.push_back(&row);
  return rows;
}

/// The rows that may stand in an entry (or the root) of `array_root`.
std::vector<const params::ParamInfo*> rows_for(Grammar grammar, const std::string& array_root, const Json* entry) {
  if (grammar == Grammar::species) {
    if (array_root == "species") return rows_of_table(params::table_of<vegetation::Species>());
    return {};
  }
  if (array_root.empty()) return rows_of_table(scene::recipe_table());
  if (array_root == "shape") return rows_of_table(params::table_of<scene::ShapeStep>());
  if (array_root == "output") return rows_of_table(params::table_of<scene::Output>());
  if (array_root == "camera") return rows_of_table(params::table_of<look::Camera>());
  if (array_root == "node" && entry != nullptr && entry->is_object() && entry->contains("kind") && (*entry)["kind"].is_string())
    if (const scene::NodeKind* kind = scene::find_node_kind((*entry)["kind"].get<std::string>())) {
      std::vector<const params::ParamInfo*> rows;
      for (const auto& row : kind->rows) rows.push_back(&row);
      return rows;
    }
  return {};
}

std::string joined(const std::vector<std::string>& path) {
  std::string text;
  for (const auto& key : path) text += (text.empty() ? "" : ".") + key;
  return text;
}

/// The row of the value at `site` (an element of a list of numbers: the list's row).
const params::ParamInfo* row_of(Grammar grammar, const Site& site) {
  std::vector<std::string> path = site.path;
  if (path.empty()) return nullptr;
  const std::string key = joined(path);
  for (const params::ParamInfo* row : rows_for(grammar, site.array_root, site.entry))
    if (row->key == key) return row;
  return nullptr;
}

// ---- values ---------------------------------------------------------------------------------

/// Every string of the tree (ids, file names), to reuse as values.
void strings_of(const Json& value, std::vector<std::string>& out, int depth = 0) {
  if (depth > 40) return;
  if (value.is_string() && !is_raw(value)) out.push_back(value.get<std::string>());
  if (value.is_structured())
    for (const Json& item : value) strings_of(item, out, depth + 1);
}

std::vector<std::string> output_files(const Json& recipe) {
  std::vector<std::string> files;
  if (recipe.is_object() && recipe.contains("output") && recipe["output"].is_array())
    for (const Json& output : recipe["output"])
      if (output.is_object() && output.contains("file") && output["file"].is_string()) files.push_back(output["file"].get<std::string>());
  return files;
}

std::vector<std::string> node_ids(const Json& recipe) {
  std::vector<std::string> ids;
  if (recipe.is_object() && recipe.contains("node") && recipe["node"].is_array())
    for (const Json& node : recipe["node"])
      if (node.is_object() && node.contains("id") && node["id"].is_string()) ids.push_back(node["id"].get<std::string>());
  return ids;
}

Json hostile_number(Random& random) {
  static const std::vector<Json> numbers{0,
                                         -1,
                                         1,
                                         2,
                                         Json(std::numeric_limits<std::int64_t>::max()),
                                         Json(std::numeric_limits<std::int64_t>::min()),
                                         Json(std::numeric_limits<std::uint64_t>::max()),
                                         raw("9223372036854775808"),
                                         raw("18446744073709551615"),
                                         raw("-9223372036854775809"),
                                         raw("nan"),
                                         raw("inf"),
                                         raw("-inf"),
                                         raw("1e999"),
                                         raw("-1e999"),
                                         1e308,
                                         -1e308,
                                         5e-324,
                                         -0.0,
                                         1e-300,
                                         2147483647,
                                         2147483648,
                                         -2147483649,
                                         4294967296,
                                         65535,
                                         65536,
                                         16385,
                                         1048577,
                                         1e9,
                                         3.0e7,
                                         0.5,
                                         -0.5};
  return random.pick(numbers);
}

/// A number for `row`: at a bound, just past one, inside, at the type's ends, or hostile.
Json number_for(const params::ParamInfo& row, Random& random, bool whole) {
  const params::Limits& limits = row.limits;
  const double low = limits.min.value_or(limits.type_min.value_or(-1e6));
  const double high = limits.max.value_or(limits.type_max.value_or(1e6));
  const double step = whole ? 1.0 : std::max(1e-9, std::abs(high - low) * 1e-6);
  double v = 0;
  switch (random.below(12)) {
    case 0:
      v = low;
      break;
    case 1:
      v = high;
      break;
    case 2:
      v = whole ? low - 1 : std::nextafter(low, -INFINITY);
      break;
    case 3:
      v = whole ? high + 1 : std::nextafter(high, INFINITY);
      break;
    case 4:
      v = low - step;
      break;
    case 5:
      v = high + step;
      break;
    case 6:
      v = limits.type_min.value_or(low);
      break;
    case 7:
      v = limits.type_max.value_or(high);
      break;
    case 8:
      return hostile_number(random);
    default:
      v = low + random.unit() * (high - low);
      break;
  }
  if (whole || row.kind == params::Kind::integer) {
    v = std::round(v);
    if (!(v >= -9.2e18 && v <= 9.2e18)) return hostile_number(random);
    if (row.kind == params::Kind::integer) return static_cast<std::int64_t>(v);
  }
  return v;
}

std::string file_name_for(const Json& recipe, Random& random) {
  static const std::vector<std::string> extensions{".png",  ".r32", ".raw",     ".tif", ".tiff", ".glb", ".gltf", ".obj", ".json",
                                                   ".toml", ".exr", ".geojson", ".csv", ".asc",  ".ply", ".stl",  ".jpg", ""};
  const std::vector<std::string> files = output_files(recipe);
  std::string other = files.empty() ? std::string("t.png") : random.pick(files);
  switch (random.below(18)) {
    case 0:
      return other;  // two outputs, one file
    case 1:
      return other + ".json";  // another output's sidecar
    case 2:
      return "../" + other;  // out of the folder
    case 3:
      return "a/../../" + other;  // out of the folder, in disguise
    case 4:
      return other + std::string(1, '\0') + ".png";  // a NUL inside
    case 5:
      return "";
    case 6:
      return ".";
    case 7:
      return "..";
    case 8:
      return "/";
    case 9:
      return "out/" + other;  // a folder that does not exist
    case 10:
      return std::string(300, 'a') + ".png";
    case 11:
      return "dir/";
    case 12:
      return "山水" + random.pick(extensions);
    case 13:
      return "-o" + random.pick(extensions);
    case 14:
      return other.substr(0, other.rfind('.')) + random.pick(extensions);  // same stem, another kind
    case 15:
      return "x" + random.pick(extensions) + random.pick(extensions);
    case 16:
      return std::string(".") + random.pick(extensions);
    default:
      return std::string("t") + std::to_string(random.below(4)) + random.pick(extensions);
  }
}

Json value_for(const params::ParamInfo& row, const Json& recipe, Random& random) {
  if (random.chance(10)) return hostile_number(random);
  switch (row.kind) {
    case params::Kind::flag:
      return random.chance(2);
    case params::Kind::integer:
      if (row.key == "sansui_recipe") return static_cast<std::int64_t>(random.below(scene::recipe_version + 2));
      return number_for(row, random, true);
    case params::Kind::real:
      return number_for(row, random, false);
    case params::Kind::choice: {
      if (row.limits.choices.empty() || random.chance(8)) return random.pick(std::vector<std::string>{"", "NONE", " ", "x", "oak "});
      std::string name = random.pick(row.limits.choices);
      if (random.chance(10)) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
      return name;
    }
    case params::Kind::path:
      return file_name_for(recipe, random);
    case params::Kind::text: {
      std::vector<std::string> texts{"",    "a",     "EPSG:4326", "EPSG:32633",         "EPSG:0",
                                     "oak", "birch", "main",      std::string(1, '\0'), std::string(5000, 'x')};
      strings_of(recipe, texts);
      return random.pick(texts);
    }
    case params::Kind::reals: {
      const std::size_t most = std::min<std::size_t>(row.limits.max_count, row.limits.min_count + 6);
      std::size_t count = row.limits.min_count + random.below(most - row.limits.min_count + 1);
      if (random.chance(6)) count = random.chance(2) && count > 0 ? count - 1 : count + 1;
      Json list = Json::array();
      for (std::size_t i = 0; i < count; ++i) list.push_back(number_for(row, random, row.limits.whole));
      return list;
    }
  }
  return 0;
}

/// Another value of the same JSON type as `value` (no row known).
Json perturbed(const Json& value, const Json& recipe, Random& random) {
  if (value.is_boolean()) return !value.get<bool>();
  if (value.is_number_integer()) {
    // A neighbour, wrapping at the ends (in unsigned arithmetic, where that is defined).
    const auto v = static_cast<std::uint64_t>(value.get<std::int64_t>());
    return random.chance(2) ? hostile_number(random) : Json(static_cast<std::int64_t>(v + random.below(5) - 2));
  }
  if (value.is_number()) return random.chance(2) ? hostile_number(random) : Json(value.get<double>() * (random.unit() * 4 - 2));
  if (value.is_string()) {
    std::vector<std::string> texts{"", "x", std::string(1, '\0'), "../x", std::string(2000, 'y')};
    strings_of(recipe, texts);
    return random.pick(texts);
  }
  return hostile_number(random);
}

/// Sets `value` at the dotted `key` inside `object`, making the tables between.
void set_dotted(Json& object, const std::string& key, Json value) {
  Json* at = &object;
  std::size_t from = 0;
  for (std::size_t dot = key.find('.'); dot != std::string::npos; from = dot + 1, dot = key.find('.', from)) {
    Json& inner = (*at)[key.substr(from, dot - from)];
    if (!inner.is_object()) inner = Json::object();
    at = &inner;
  }
  (*at)[key.substr(from)] = std::move(value);
}

/// A new [[array]] entry of `array_root` that has what it needs to be read.
Json new_entry(Grammar grammar, const std::string& array_root, const Json& recipe, Random& random) {
  Json entry = Json::object();
  if (grammar == Grammar::species) {
    entry["name"] = random.pick(std::vector<std::string>{"oak", "fuzz_tree", "birch", "x", "pine"});
    entry["form"] = value_for(*params::table_of<vegetation::Species>().find("form"), recipe, random);
  } else if (array_root == "output") {
    entry["file"] = file_name_for(recipe, random);
  } else if (array_root == "node") {
    const auto& kinds = scene::all_node_kinds();
    const auto ids = node_ids(recipe);
    entry["id"] = std::string("n") + std::to_string(random.below(1000));
    entry["kind"] = kinds[random.below(kinds.size())].name;
    if (!ids.empty()) entry["inputs"] = Json::array({random.pick(ids)});
  }
  for (const params::ParamInfo* row : rows_for(grammar, array_root, &entry))
    if (random.chance(4)) set_dotted(entry, row->key, value_for(*row, recipe, random));
  return entry;
}

Json nested(Json value, int depth, bool arrays) {
  for (int i = 0; i < depth; ++i) value = arrays ? Json::array({std::move(value)}) : Json{{"a", std::move(value)}};
  return value;
}

// ---- one mutation -----------------------------------------------------------------------------

class Mutator {
 public:
  Mutator(Grammar grammar, Json& doc, bool json, Random& random) : grammar_(grammar), doc_(doc), json_(json), random_(random) {}

  void mutate() {
    Json& recipe = recipe_root();
    std::vector<Site> sites;
    Site root;
    collect(recipe, root, 0, sites);
    if (json_ && random_.chance(10)) {  // anywhere in the sidecar, not only its recipe
      sites.clear();
      collect(doc_, root, 0, sites);
    }
    switch (random_.below(16)) {
      case 0:
      case 1:
      case 2:
        change_value(sites, recipe);
        break;
      case 3:
        remove(sites);
        break;
      case 4:
      case 5:
        add_row(sites, recipe);
        break;
      case 6:
      case 7:
        array_entries(recipe);
        break;
      case 8:
        output_files_collide(recipe);
        break;
      case 9:
        nodes(recipe);
        break;
      case 10:
        deepen(sites);
        break;
      case 11:
        change_type(sites, recipe);
        break;
      case 12:
        move_key(sites);
        break;
      case 13:
        unknown_key(sites);
        break;
      case 14:
        cameras(recipe);
        break;
      default:
        change_value(sites, recipe);
        break;
    }
  }

  /// The recipe inside a sidecar (provenance.recipe), else the whole document.
  Json& recipe_root() {
    if (json_ && doc_.contains("provenance") && doc_["provenance"].is_object() && doc_["provenance"].contains("recipe") &&
        doc_["provenance"]["recipe"].is_object())
      return doc_["provenance"]["recipe"];
    return doc_;
  }

 private:
  void change_value(const std::vector<Site>& sites, const Json& recipe) {
    std::vector<const Site*> leaves;
    for (const Site& site : sites)
      if (!site.value().is_structured() || (site.value().is_array() && !is_table_array(site.value()))) leaves.push_back(&site);
    if (leaves.empty()) return;
    const Site& site = *leaves[random_.below(leaves.size())];
    // A number in a list has the path, and so the row, of its list.
    const params::ParamInfo* row = row_of(grammar_, site);
    if (row != nullptr && site.parent->is_array() && row->kind == params::Kind::reals) {
      site.value() = number_for(*row, random_, row->limits.whole);
      return;
    }
    site.value() = row != nullptr ? value_for(*row, recipe, random_) : perturbed(site.value(), recipe, random_);
  }

  void remove(const std::vector<Site>& sites) {
    if (sites.empty()) return;
    const Site& site = random_.pick(sites);
    if (site.parent->is_object())
      site.parent->erase(site.key);
    else
      site.parent->erase(site.index);
  }

  /// A row of the table of a random entry (or the root), set at its place: new keys and sections.
  void add_row(const std::vector<Site>& sites, const Json& recipe) {
    std::vector<const Site*> entries;
    for (const Site& site : sites)
      if (site.entry != nullptr && site.path.empty()) entries.push_back(&site);
    Json* target = &recipe_root();
    std::string array_root;
    if (!entries.empty() && (grammar_ == Grammar::species || random_.chance(2))) {
      const Site& site = *entries[random_.below(entries.size())];
      target = site.entry, array_root = site.array_root;
    }
    const auto rows = rows_for(grammar_, array_root, target);
    if (rows.empty()) return;
    const params::ParamInfo& row = *rows[random_.below(rows.size())];
    if (!target->is_object()) return;
    set_dotted(*target, row.key, value_for(row, recipe, random_));
  }

  /// Many numbers of one entry (or of the recipe's root) at their upper bounds at once: what
  /// grows with each of them (branches times depth times leaves, width times height) grows
  /// with their product, which one bound at a time never reaches.
  void extremes(const std::vector<Site>& sites) {
    std::vector<const Site*> entries;
    for (const Site& site : sites)
      if (site.entry != nullptr && site.path.empty()) entries.push_back(&site);
    Json* target = &recipe_root();
    std::string array_root;
    if (!entries.empty() && (grammar_ == Grammar::species || random_.chance(2))) {
      const Site& site = *entries[random_.below(entries.size())];
      target = site.entry, array_root = site.array_root;
    }
    if (!target->is_object()) return;
    const bool upper = !random_.chance(4);
    for (const params::ParamInfo* row : rows_for(grammar_, array_root, target)) {
      if ((row->kind != params::Kind::integer && row->kind != params::Kind::real) || !random_.chance(2)) continue;
      const std::optional<double> bound = upper ? row->limits.max : row->limits.min;
      if (!bound) continue;
      const double v = *bound + (row->limits.max_exclusive && upper ? -1e-9 : 0) + (row->limits.min_exclusive && !upper ? 1e-9 : 0);
      set_dotted(*target, row->key, row->kind == params::Kind::integer ? Json(static_cast<std::int64_t>(v)) : Json(v));
    }
  }

  /// Repeats, drops, swaps, appends or empties [[array]] entries.
  void array_entries(const Json& recipe) {
    const std::vector<std::string> names =
        grammar_ == Grammar::species ? std::vector<std::string>{"species"} : std::vector<std::string>{"output", "shape", "camera", "node"};
    const std::string& name = random_.pick(names);
    Json& root = recipe_root();
    Json& array = root[name];
    if (!array.is_array()) array = Json::array();
    const std::size_t size = array.size();
    switch (random_.below(6)) {
      case 0:
        if (size > 0) array.push_back(array[random_.below(size)]);
        break;
      case 1:
        if (size > 0) array.erase(random_.below(size));
        break;
      case 2:
        if (size > 1) std::swap(array[random_.below(size)], array[random_.below(size)]);
        break;
      case 3:
        if (size > 0)
          for (std::size_t i = 0, n = 2 + random_.below(60); i < n; ++i) array.push_back(array[random_.below(size)]);
        break;
      case 4:
        array = Json::array();
        break;
      default:
        array.push_back(new_entry(grammar_, name, recipe, random_));
        break;
    }
    if (array.empty() && random_.chance(2)) root.erase(name);
  }

  /// Output file names that collide, climb out, hold a NUL or name another output's sidecar.
  void output_files_collide(const Json& recipe) {
    Json& root = recipe_root();
    if (grammar_ == Grammar::species || !root.contains("output") || !root["output"].is_array() || root["output"].empty()) {
      if (grammar_ == Grammar::recipe) root["output"] = Json::array({new_entry(grammar_, "output", recipe, random_)});
      return;
    }
    Json& outputs = root["output"];
    Json& output = outputs[random_.below(outputs.size())];
    if (!output.is_object()) return;
    output["file"] = file_name_for(recipe, random_);
    if (random_.chance(3)) {  // and its twin
      Json twin = output;
      twin["file"] =
          random_.chance(2) ? output["file"] : Json(output["file"].is_string() ? output["file"].get<std::string>() + ".json" : "");
      outputs.push_back(std::move(twin));
    }
  }

  /// [[node]] graphs: inputs that name missing nodes, themselves or each other; duplicate ids;
  /// another kind.
  void nodes(const Json& recipe) {
    Json& root = recipe_root();
    if (grammar_ == Grammar::species) return;
    if (!root.contains("node") || !root["node"].is_array() || root["node"].empty()) {
      root["node"] = Json::array({new_entry(grammar_, "node", recipe, random_)});
      return;
    }
    Json& graph = root["node"];
    Json& node = graph[random_.below(graph.size())];
    if (!node.is_object()) return;
    std::vector<std::string> ids = node_ids(root);
    ids.push_back("missing");
    switch (random_.below(5)) {
      case 0:
        node["inputs"] = Json::array({random_.pick(ids), random_.pick(ids)});
        break;
      case 1:
        node["inputs"] = Json::array({node.value("id", Json("x"))});
        break;  // itself
      case 2:
        node["id"] = random_.pick(ids);
        break;
      case 3: {
        const auto& kinds = scene::all_node_kinds();
        node["kind"] = kinds[random_.below(kinds.size())].name;
        break;
      }
      default: {
        Json inputs = Json::array();
        for (std::size_t i = 0, n = random_.below(9); i < n; ++i) inputs.push_back(random_.pick(ids));
        node["inputs"] = inputs;
        break;
      }
    }
  }

  void deepen(const std::vector<Site>& sites) {
    if (sites.empty()) return;
    static const std::vector<int> depths{2, 3, 8, 40, 120, 250};
    const Site& site = random_.pick(sites);
    site.value() = nested(site.value(), random_.pick(depths), random_.chance(2));
  }

  void change_type(const std::vector<Site>& sites, const Json& recipe) {
    if (sites.empty()) return;
    const Site& site = random_.pick(sites);
    Json& value = site.value();
    switch (random_.below(6)) {
      case 0:
        value = value.dump(-1, ' ', false, Json::error_handler_t::replace);  // as text
        break;
      case 1:
        value = Json::array({value});
        break;
      case 2:
        value = Json::object();
        break;
      case 3:
        value = Json::array();
        break;
      case 4:
        value = json_ && random_.chance(3) ? Json(nullptr) : Json(random_.chance(2));
        break;
      default:
        value = perturbed(value, recipe, random_);
        break;
    }
  }

  /// A key put into another table (a key of [render] in [[output]], ...), or copied there.
  void move_key(const std::vector<Site>& sites) {
    std::vector<const Site*> keyed;
    for (const Site& site : sites)
      if (site.parent->is_object()) keyed.push_back(&site);
    if (keyed.empty()) return;
    const Site& from = *keyed[random_.below(keyed.size())];
    const Json moved = from.value();
    const std::string key = from.key;
    if (random_.chance(2)) from.parent->erase(key);
    // The sites are stale now: find the tables again.
    std::vector<Site> now;
    collect(recipe_root(), Site{}, 0, now);
    std::vector<Json*> tables{&recipe_root()};
    for (const Site& site : now)
      if (site.value().is_object()) tables.push_back(&site.value());
    (*tables[random_.below(tables.size())])[key] = moved;
  }

  /// A misspelt key, or a key no table has.
  void unknown_key(const std::vector<Site>& sites) {
    std::vector<Json*> tables{&recipe_root()};
    for (const Site& site : sites)
      if (site.value().is_object()) tables.push_back(&site.value());
    Json& target = *tables[random_.below(tables.size())];
    std::string key = "x";
    if (!target.empty()) {
      auto it = target.begin();
      std::advance(it, static_cast<std::ptrdiff_t>(random_.below(target.size())));
      key = it.key();
    }
    switch (random_.below(4)) {
      case 0:
        key += "s";
        break;
      case 1:
        key = key.empty() ? key : key.substr(1);
        break;
      case 2:
        key = key + "." + key;
        break;
      default:
        key = random_.pick(std::vector<std::string>{"", "sansui_recipe", "source", "__proto__", "x y", "\xff"});
        break;
    }
    target[key] = random_.chance(2) ? Json(1) : Json::object();
  }

  /// [camera] as a table, as [[camera]] entries, or both named by outputs.
  void cameras(const Json& recipe) {
    if (grammar_ == Grammar::species) return;
    Json& root = recipe_root();
    Json& camera = root["camera"];
    if (camera.is_object())
      camera = Json::array({camera, camera});
    else if (camera.is_array() && !camera.empty() && random_.chance(2))
      camera = camera[0];
    else
      camera = Json::array({new_entry(grammar_, "camera", recipe, random_), new_entry(grammar_, "camera", recipe, random_)});
    if (camera.is_array())
      for (Json& entry : camera)
        if (entry.is_object() && random_.chance(2)) entry["name"] = random_.pick(std::vector<std::string>{"a", "b", "", "a"});
    if (root.contains("output") && root["output"].is_array())
      for (Json& output : root["output"])
        if (output.is_object() && random_.chance(2)) output["camera"] = random_.pick(std::vector<std::string>{"a", "b", "", "missing"});
  }

  Grammar grammar_;
  Json& doc_;
  bool json_;
  Random& random_;
};

}  // namespace

bool looks_like_json(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && text[first] == '{';
}

std::optional<std::string> mutate_structured(Grammar grammar, std::string_view input, std::uint64_t seed) {
  const bool json = grammar == Grammar::recipe && looks_like_json(input);
  std::optional<Json> doc = parse(input, json);
  if (!doc) return std::nullopt;
  Random random(seed);
  Mutator mutator(grammar, *doc, json, random);
  try {
    for (std::size_t i = 0, n = 1 + random.below(3); i < n; ++i) mutator.mutate();
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a value the tree cannot hold (text that is not UTF-8): mutate bytes
  }
  return to_text(*doc, json);
}

std::optional<std::string> cross_over_structured(Grammar grammar, std::string_view first, std::string_view second, std::uint64_t seed) {
  const bool json = grammar == Grammar::recipe && looks_like_json(first);
  if (json != (grammar == Grammar::recipe && looks_like_json(second))) return std::nullopt;
  std::optional<Json> a = parse(first, json), b = parse(second, json);
  if (!a || !b) return std::nullopt;
  Random random(seed);
  Json& into = Mutator(grammar, *a, json, random).recipe_root();
  const Json& from = Mutator(grammar, *b, json, random).recipe_root();
  if (!from.is_object() || from.empty() || !into.is_object()) return std::nullopt;
  auto it = from.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(random.below(from.size())));
  if (is_table_array(it.value()) && into.contains(it.key()) && into[it.key()].is_array() && random.chance(2))
    into[it.key()].push_back(it.value()[random.below(it.value().size())]);  // one entry more
  else
    into[it.key()] = it.value();  // the whole table, key or array
  return to_text(*a, json);
}

}  // namespace sansui::test
