// Parameter tables of the mesh subsystem (see core/params.hpp).
#include "core/error.hpp"
#include "core/params.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"

namespace sansui::mesh {

const params::Table<SubdivideParams>& parameter_table(const SubdivideParams*) {
  using P = SubdivideParams;
  static const auto table =
      params::Table<P>("subdivide", "Fractal subdivision of a triangle mesh (Nishimura and Sakata)")
          .add(params::field("seed", &P::seed).doc("Random seed: the same seed gives the same surface, byte for byte"))
          .add(params::field("h", &P::h)
                   .above(0)
                   .at_most(1)
                   .no_unit()
                   .doc("Decay exponent h: S(n) = S(n-1) 0.5^h; larger is smoother (fractal dimension 3 - h)"))
          .add(params::field("roughness", &P::roughness)
                   .at_most(100)
                   .at_least(0)
                   .no_unit()
                   .doc("S(0) as a multiple of the input's mean edge length (a ratio, no unit)"))
          .add(params::field("min_edge", &P::min_edge_m)
                   .at_most(1e7)
                   .above(0)
                   .units("m")
                   .unset("none")
                   .doc("Stop once every edge is shorter than this"))
          .add(params::field("steps", &P::steps)
                   .at_most(30)
                   .at_least(0)
                   .unset("5 when min_edge is unset too")
                   .doc("Stop after this many steps (with min_edge: whichever comes first)"))
          .add(params::choice("boundary", &P::boundary,
                              {{"free", BoundaryMode::free}, {"vertical", BoundaryMode::vertical}, {"fixed", BoundaryMode::fixed}})
                   .doc("Boundary midpoints: free (along their triangle's normal, as the paper), vertical (up and down only), fixed"))
          .add(params::choice("direction", &P::direction, {{"normal", Direction::normal}, {"vertical", Direction::vertical}})
                   .doc("Which way midpoints move: normal (the paper; may overhang) or vertical (a heightfield)"))
          .add(params::field("max_triangles", &P::max_triangles)
                   .at_most(1e10)
                   .at_least(1)
                   .doc("Refuse to make more triangles than this unless force (50 M: about 7 GB)"))
          .add(params::field("force", &P::force).doc("Subdivide beyond max_triangles"));
  return table;
}

void SubdivideParams::validate() const {
  params::validate(*this);
  if (!min_edge_m && !steps) fail("no stop rule: give a minimum edge length or a number of steps");
}

const params::Table<SketchParams>& parameter_table(const SketchParams*) {
  using P = SketchParams;
  static const auto table =
      params::Table<P>("sketch", "A coarse mountain from a map sketch of ridge and valley lines (constrained Delaunay, CGAL)")
          .add(params::field("refine", &P::max_edge_m)
                   .at_most(1e7)
                   .at_least(0)
                   .units("m")
                   .doc("Refine the triangulation until no edge is longer than this; 0: no refinement"))
          .add(params::field("frame", &P::frame_margin_m)
                   .at_most(1e7)
                   .at_least(0)
                   .units("m")
                   .doc("Add a rectangular frame this far around the sketch; 0: no frame, else 1 % to 100 times the sketch's size"))
          .add(params::field("frame_height", &P::frame_height_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("the lowest height drawn")
                   .doc("Height of the frame's corners"));
  return table;
}

}  // namespace sansui::mesh
