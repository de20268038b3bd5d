#include "recipe_source.hpp"

#include <algorithm>
#include <regex>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/error.hpp"
#include "core/one_line.hpp"
#include "scene/recipe_file.hpp"
#include "scene/recipe_table.hpp"

namespace sansui::python {

namespace {

/// Deepest nesting of dicts and lists in a recipe: as deep as a recipe file may nest
/// (core/toml_nesting.hpp), far below what would exhaust the stack.
constexpr int deepest_nesting = 64;

/// The containers being converted, outermost first: a dict or list met again inside itself is
/// a cycle, which no recipe can hold.
struct Nesting {
  std::vector<PyObject*> open;

  /// Enters `container` (at `where`); ValueError for a cycle or nesting past the limit.
  void enter(py::handle container, const std::string& where) {
    if (std::ranges::find(open, container.ptr()) != open.end())
      throw py::value_error(fmt::format("recipe: {} contains itself (a dict or list that holds itself cannot be a recipe)",
                                        where.empty() ? "the recipe" : where));
    if (static_cast<int>(open.size()) >= deepest_nesting)
      throw py::value_error(fmt::format("recipe: {} is nested more than {} deep: a recipe's dicts and lists nest at most {} deep",
                                        utf8_prefix(where, 200), deepest_nesting, deepest_nesting));
    open.push_back(container.ptr());
  }
  void leave() { open.pop_back(); }
};

/// A Python value as TOML, for recipes given as dicts. Throws TypeError for what TOML cannot hold.
toml::table to_toml_table(py::handle dict, const std::string& where, Nesting& nesting);

void append_toml(toml::array& array, py::handle value, const std::string& where, Nesting& nesting);

template <class Insert>
void insert_toml(py::handle value, const std::string& where, Nesting& nesting, Insert&& insert) {
  if (py::isinstance<py::bool_>(value))
    insert(value.cast<bool>());
  else if (PyLong_Check(value.ptr()) != 0) {
    int overflow = 0;
    const long long number = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow != 0)
      throw py::value_error(fmt::format("recipe: {} {} is not allowed: a recipe's whole numbers lie between -2^63 and 2^63 - 1", where,
                                        py::str(value).cast<std::string>().substr(0, 40)));
    insert(static_cast<std::int64_t>(number));
  } else if (PyFloat_Check(value.ptr()) != 0)
    insert(value.cast<double>());
  else if (py::isinstance<py::str>(value))
    insert(value.cast<std::string>());
  else if (PyObject_HasAttrString(value.ptr(), "__fspath__") != 0)
    insert(py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>());
  else if (py::isinstance<py::dict>(value))
    insert(to_toml_table(value, where, nesting));
  else if (py::isinstance<scene::WorldParams>(value))
    insert(to_toml_table(value.attr("to_dict")(), where, nesting));
  else if (PyObject_HasAttrString(value.ptr(), "tolist") != 0)
    insert_toml(value.attr("tolist")(), where, nesting, insert);
  else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nesting.enter(value, where);
    toml::array array;
    for (py::handle item : value) append_toml(array, item, where, nesting);
    nesting.leave();
    insert(std::move(array));
  } else {
    throw py::type_error(fmt::format("recipe: {} is a {}; a recipe holds numbers, text, lists and dicts", where,
                                     py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
  }
}

void append_toml(toml::array& array, py::handle value, const std::string& where, Nesting& nesting) {
  insert_toml(value, where, nesting, [&](auto&& v) { array.push_back(std::forward<decltype(v)>(v)); });
}

toml::table to_toml_table(py::handle dict, const std::string& where, Nesting& nesting) {
  if (!py::isinstance<py::dict>(dict)) throw py::type_error(fmt::format("recipe: {} must be a dict", where.empty() ? "the recipe" : where));
  nesting.enter(dict, where);
  toml::table table;
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(dict)) {
    if (!py::isinstance<py::str>(key))
      throw py::type_error(fmt::format("recipe: the keys of {} must be str", where.empty() ? "the recipe" : where));
    const auto name = key.cast<std::string>();
    if (value.is_none()) continue;  // None: unset, as a key left out
    // An empty list: none, as a key left out ([[output]] tables that are not there).
    if ((py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) && py::len(value) == 0) continue;
    std::string inner = where;
    if (!inner.empty()) inner += '.';
    inner += name;
    insert_toml(value, inner, nesting, [&](auto&& v) { table.insert_or_assign(name, std::forward<decltype(v)>(v)); });
  }
  nesting.leave();
  return table;
}

/// Messages about a recipe made from a dict name no line of the TOML text it went through.
[[noreturn]] void rethrow_without_line(const InputError& error, const std::string& source) {
  static const std::regex line(R"(^recipe:\d+(:\d+)?: )");
  throw py::value_error(one_line(std::regex_replace(std::string(error.what()), line, source + ": ")));
}

}  // namespace

PyRecipe recipe_from_dict(py::handle dict, const std::filesystem::path& base_dir) {
  Nesting nesting;
  const toml::table table = to_toml_table(dict, "", nesting);
  try {
    scene::LoadedRecipe loaded = scene::parse_recipe_table(table, "recipe", base_dir);
    return {std::move(loaded.recipe), std::move(loaded.warnings)};
  } catch (const InputError& error) {
    rethrow_without_line(error, "recipe");
  }
}

py::object json_to_python(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

PyRecipe recipe_from(py::handle source) {
  if (source.is_none()) return recipe_from_dict(py::dict(), std::filesystem::current_path());
  if (py::isinstance<py::dict>(source)) return recipe_from_dict(source, std::filesystem::current_path());
  if (py::isinstance<PyRecipe>(source)) return source.cast<PyRecipe>();
  if (py::isinstance<py::str>(source) || PyObject_HasAttrString(source.ptr(), "__fspath__") != 0) {
    const auto path = py::str(py::module_::import("os").attr("fspath")(source)).cast<std::string>();
    scene::LoadedRecipe loaded = scene::load_recipe(path);
    return {std::move(loaded.recipe), std::move(loaded.warnings)};
  }
  throw py::type_error(fmt::format("a recipe is a scene file's path, a dict or a sansui.Recipe; got {}",
                                   py::str(py::type::of(source).attr("__name__")).cast<std::string>()));
}

}  // namespace sansui::python
