#include "io/gdal_api.hpp"

#include <mutex>
#include <string>

#include <dlfcn.h>

#include "core/error.hpp"

namespace sansui::io::detail {
namespace {

struct Loaded {
  GdalApi api;
  std::string problem;  ///< why it could not be loaded; empty when it was
};

Loaded load() {
  Loaded loaded;
  void* library = ::dlopen(SANSUI_GDAL_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = ::dlerror();
    loaded.problem = fmt::format("GDAL ({}) cannot be loaded: {}; install it (apt-get install libgdal32, or scripts/setup)",
                                 SANSUI_GDAL_SONAME, why != nullptr ? why : "no reason given");
    return loaded;
  }
#define SANSUI_GDAL_LOAD(name)                                                    \
  loaded.api.name = reinterpret_cast<decltype(&::name)>(::dlsym(library, #name)); \
  if (loaded.api.name == nullptr && loaded.problem.empty())                       \
    loaded.problem = fmt::format("GDAL ({}) lacks the function {}: it is older than Sansui needs", SANSUI_GDAL_SONAME, #name);
  SANSUI_GDAL_FUNCTIONS(SANSUI_GDAL_LOAD)
#undef SANSUI_GDAL_LOAD
  loaded.api.CPLGetXMLNode = reinterpret_cast<CPLXMLNode* (*)(CPLXMLNode*, const char*)>(::dlsym(library, "CPLGetXMLNode"));
  if (loaded.api.CPLGetXMLNode == nullptr && loaded.problem.empty())
    loaded.problem = fmt::format("GDAL ({}) lacks the function CPLGetXMLNode", SANSUI_GDAL_SONAME);
  return loaded;  // the library stays open for the life of the process
}

}  // namespace

const GdalApi& gdal_api() {
  static const Loaded loaded = load();
  if (!loaded.problem.empty()) fail("{}", loaded.problem);
  return loaded.api;
}

}  // namespace sansui::io::detail
