// The extension sansui._sansui (docs/python.md): pybind11 over the library, thin. Every function
// here runs a node kind from its table (nodes.cpp), reads a file or a CRS (geo.cpp), routes water
// (water.cpp), runs a whole recipe (recipes.cpp) or makes a scene's parts (scenery.cpp); no
// algorithm lives in python/. The package around it (python/sansui/*.py) makes the public
// functions: keyword arguments and signatures from the tables, arrays that keep their world.
#include <fmt/format.h>
#include <pybind11/pybind11.h>

#include "calls.hpp"
#include "core/one_line.hpp"
#include "geo.hpp"
#include "nodes.hpp"
#include "recipes.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"
#include "scenery.hpp"
#include "water.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_sansui, module) {
  using namespace sansui;
  module.doc() = "Sansui: deterministic natural terrain, water, plants and scenes (docs/python.md)";
  module.attr("__version__") = SANSUI_VERSION;
  scene::set_painter(&render::render_image);  // pictures of recipes' render outputs: headless EGL

  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, one_line(e.what()).c_str());
    } catch (const Cancelled& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });

  module.def(
      "set_threads",
      [](int threads) {
        if (threads < 0) throw py::value_error(fmt::format("threads {} is not allowed: it must be 0 (all cores) or more", threads));
        python::set_thread_count(threads);
      },
      py::arg("threads"), "set_threads(threads): at most this many threads work in each call (0: all cores). Results never depend on it.");
  module.def("threads", &python::thread_count, "The thread count set_threads() gave (0: all cores)");

  python::add_world(module);
  python::add_node_functions(module);  // what sansui/_nodes.py makes the node functions from
  python::add_geo(module);
  python::add_water(module);
  python::add_recipes(module);
  python::add_scenery(module);
}
