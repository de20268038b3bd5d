// Python values and the parameter tables' values (core/params.hpp), both ways, with the CLI's
// checks and messages: a value of the wrong Python type is a TypeError, one the table does not
// allow a ValueError naming the key, the value and what is allowed, as `sansui` says it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/params.hpp"

namespace sansui::python {

namespace py = pybind11;

/// `object` as the value of `row`, checked against it (params::require_allowed). Throws
/// TypeError or ValueError naming `name`.
params::Value to_value(const params::ParamInfo& row, py::handle object, std::string_view name);

/// A value as Python's: None, bool, int, float, str or a list of floats.
py::object to_python(const params::Value& value);

/// Throws TypeError: "FUNCTION() got an unexpected keyword argument 'KEY'; did you mean 'NEAR'?"
[[noreturn]] void unknown_keyword(std::string_view function, std::string_view key, const std::vector<std::string>& known);

}  // namespace sansui::python
