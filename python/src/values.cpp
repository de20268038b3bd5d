#include "values.hpp"

#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "core/one_line.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::python {

namespace {

std::string type_name(py::handle object) {
  return py::str(py::type::of(object).attr("__name__")).cast<std::string>();
}

bool is_integer(py::handle object) {
  if (py::isinstance<py::bool_>(object)) return false;
  return PyLong_Check(object.ptr()) != 0 || PyObject_HasAttrString(object.ptr(), "__index__") != 0;
}

/// A scalar number: int, float, or a numpy scalar (not bool, not a sequence such as an array).
bool is_number(py::handle object) {
  return PyNumber_Check(object.ptr()) != 0 && !py::isinstance<py::str>(object) && PyObject_HasAttrString(object.ptr(), "__len__") == 0;
}

bool is_bool(py::handle object) {
  return py::isinstance<py::bool_>(object) || type_name(object) == "bool_";
}

/// The start of repr(object), for messages; "..." when it has none (a repr that raises, or one
/// too deep for Python's recursion limit).
std::string short_repr(py::handle object) {
  try {
    std::string text = py::repr(object).cast<std::string>();
    for (char& c : text)
      if (c == '\n' || c == '\r') c = ' ';
    return std::string(utf8_prefix(text, 60));
  } catch (py::error_already_set&) {
    return "...";
  }
}

[[noreturn]] void wrong_type(py::handle object, std::string_view name, std::string_view wanted) {
  throw py::type_error(fmt::format("{} must be {}; got {} {}", name, wanted, type_name(object), short_repr(object)));
}

/// A Python number as a Value: int64 for integers (a whole float too, for integer rows), else double.
params::Value number_value(const params::ParamInfo& row, py::handle object, std::string_view name) {
  if (is_integer(object)) {
    int overflow = 0;
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(object.ptr()));
    if (!index) throw py::error_already_set();
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow != 0) {
      // Beyond 64 bits: no row allows it; say what is allowed.
      std::string allowed = row.kind == params::Kind::integer ? params::allowed_text(row) : "a finite number";
      if (allowed.empty()) allowed = "a whole number between -2^63 and 2^63 - 1";
      throw py::value_error(
          fmt::format("{} {} is not allowed: it must be {}", name, py::str(object).cast<std::string>().substr(0, 40), allowed));
    }
    if (row.kind == params::Kind::integer) return static_cast<std::int64_t>(v);
    return static_cast<double>(v);
  }
  const double v = py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
  if (row.kind == params::Kind::integer && std::isfinite(v) && v == std::trunc(v) && std::abs(v) < 9.2e18)
    return static_cast<std::int64_t>(v);
  return v;
}

}  // namespace

params::Value to_value(const params::ParamInfo& row, py::handle object, std::string_view name) {
  params::Value value;
  if (object.is_none()) {
    value = std::monostate{};
  } else {
    switch (row.kind) {
      case params::Kind::flag:
        if (!is_bool(object)) wrong_type(object, name, "True or False");
        value = py::cast<bool>(py::bool_(py::reinterpret_borrow<py::object>(object)));
        break;
      case params::Kind::integer:
      case params::Kind::real:
        if (!is_number(object) || is_bool(object)) wrong_type(object, name, row.kind == params::Kind::integer ? "an int" : "a number");
        value = number_value(row, object, name);
        break;
      case params::Kind::text:
      case params::Kind::choice:
        if (!py::isinstance<py::str>(object)) wrong_type(object, name, "a str");
        value = object.cast<std::string>();
        break;
      case params::Kind::path:
        if (!py::isinstance<py::str>(object) && PyObject_HasAttrString(object.ptr(), "__fspath__") == 0)
          wrong_type(object, name, "a str or os.PathLike");
        value = py::str(py::module_::import("os").attr("fspath")(object)).cast<std::string>();
        break;
      case params::Kind::reals: {
        if (is_number(object) && !is_bool(object) && row.limits.min_count <= 1) {
          value = std::vector<double>{py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>()};
          break;
        }
        if (py::isinstance<py::str>(object) || PyObject_HasAttrString(object.ptr(), "__iter__") == 0)
          wrong_type(object, name, "a sequence of numbers");
        std::vector<double> numbers;
        // numpy arrays of any shape give their numbers in order (an (N, 2) array of points).
        auto flat = py::reinterpret_borrow<py::object>(object);
        if (PyObject_HasAttrString(object.ptr(), "ravel") != 0) flat = object.attr("ravel")();
        for (py::handle item : flat) {
          if (!is_number(item) || is_bool(item)) wrong_type(item, name, "a sequence of numbers");
          numbers.push_back(py::float_(py::reinterpret_borrow<py::object>(item)).cast<double>());
        }
        value = std::move(numbers);
        break;
      }
    }
  }
  try {
    params::require_allowed(row, value, name);
  } catch (const InputError& error) {
    throw py::value_error(one_line(error.what()));
  }
  return value;
}

py::object to_python(const params::Value& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return py::none();
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          py::list list;
          for (double x : v) list.append(x);
          return py::object(std::move(list));
        } else {
          return py::cast(v);
        }
      },
      value);
}

void unknown_keyword(std::string_view function, std::string_view key, const std::vector<std::string>& known) {
  std::string message = fmt::format("{}() got an unexpected keyword argument '{}'", function, key);
  if (const auto near = scene::nearest_key(key, known))
    message += fmt::format("; did you mean '{}'?", *near);
  else
    message += fmt::format("; it takes {}", fmt::join(known, ", "));
  throw py::type_error(message);
}

}  // namespace sansui::python
