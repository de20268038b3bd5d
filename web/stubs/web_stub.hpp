// What the browser build says where the native build would call a library it leaves out
// (cmake/SansuiWeb.cmake): one line naming what is missing and where to do it instead.
#pragma once

#include <string_view>

#include "core/error.hpp"

namespace sansui::web {

[[noreturn]] inline void not_in_browser(std::string_view what, std::string_view library) {
  fail("{} is not available in the browser build (it needs {}): run the same recipe with the sansui command-line tool", what, library);
}

}  // namespace sansui::web
