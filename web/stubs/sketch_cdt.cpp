// The browser build's mesh/sketch_cdt.cpp: no CGAL (cmake/SansuiWeb.cmake).
#include "mesh/sketch.hpp"
#include "web_stub.hpp"

namespace sansui::mesh {

SketchMesh triangulate_sketch(const Sketch&, const SketchParams&) {
  web::not_in_browser("triangulating a map sketch", "CGAL");
}

}  // namespace sansui::mesh
