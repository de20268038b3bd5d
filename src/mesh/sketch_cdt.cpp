// The constrained Delaunay triangulation of a map sketch (see sketch.hpp), with CGAL
// (Chew, "Constrained Delaunay triangulations", 1989; Shewchuk's Delaunay refinement for the
// optional refinement). The only file that includes CGAL, so the rest of the library compiles
// fast and without -frounding-math.
#include <algorithm>
#include <cmath>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/exceptions.h>

#include "core/error.hpp"
#include "mesh/sketch.hpp"

namespace sansui::mesh {
namespace {

struct VertexInfo {
  double height_m = 0.0;
  bool known = false;  ///< false for points the refinement added
  bool locked = false;
  std::uint32_t index = 0;  ///< place in the output mesh
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel, CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Lines never cross (check_sketch), so no intersection needs constructing; any that slips
// through as a rounding case throws instead of inventing a point without a height.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Point = Kernel::Point_2;

/// Most triangles a refinement may make: the sketch is the coarse input of subdivision.
constexpr double max_refined_triangles = 1e6;

void insert_features(Cdt& cdt, const Sketch& sketch) {
  for (const SketchFeature& feature : sketch.features) {
    Cdt::Vertex_handle previous;
    for (const SketchPoint& p : feature.points) {
      const Cdt::Vertex_handle v = cdt.insert(Point(p.east_m, p.north_m));
      v->info().height_m = p.height_m;
      v->info().known = true;
      v->info().locked = v->info().locked || feature.locked;
      if (previous != Cdt::Vertex_handle()) cdt.insert_constraint(previous, v);
      previous = v;
    }
  }
}

void insert_frame(Cdt& cdt, const Sketch& sketch, const SketchParams& params) {
  double west = INFINITY, east = -INFINITY, south = INFINITY, north = -INFINITY, lowest = INFINITY;
  for (const SketchFeature& feature : sketch.features)
    for (const SketchPoint& p : feature.points) {
      west = std::min(west, p.east_m), east = std::max(east, p.east_m);
      south = std::min(south, p.north_m), north = std::max(north, p.north_m);
      lowest = std::min(lowest, p.height_m);
    }
  const double m = params.frame_margin_m;
  const Point corners[4] = {{west - m, south - m}, {east + m, south - m}, {east + m, north + m}, {west - m, north + m}};
  Cdt::Vertex_handle v[4];
  for (int k = 0; k < 4; ++k) {
    v[k] = cdt.insert(corners[k]);
    v[k]->info().height_m = params.frame_height_m.value_or(lowest);
    v[k]->info().known = true;
  }
  for (int k = 0; k < 4; ++k) cdt.insert_constraint(v[k], v[(k + 1) % 4]);
}

/// Height at p from the triangle of `coarse` that contains it (linear interpolation).
double height_in(const Cdt& coarse, const Point& p) {
  Cdt::Face_handle face = coarse.locate(p);
  if (coarse.is_infinite(face)) {
    // On the hull, by rounding: use the hull edge of the infinite face.
    const int i = face->index(coarse.infinite_vertex());
    const auto a = face->vertex(Cdt::cw(i)), b = face->vertex(Cdt::ccw(i));
    const double dx = b->point().x() - a->point().x(), dy = b->point().y() - a->point().y();
    const double length2 = dx * dx + dy * dy;
    const double t = std::clamp(((p.x() - a->point().x()) * dx + (p.y() - a->point().y()) * dy) / length2, 0.0, 1.0);
    return a->info().height_m + t * (b->info().height_m - a->info().height_m);
  }
  const Point &a = face->vertex(0)->point(), &b = face->vertex(1)->point(), &c = face->vertex(2)->point();
  const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  const double wb = ((p.x() - a.x()) * (c.y() - a.y()) - (p.y() - a.y()) * (c.x() - a.x())) / area;
  const double wc = ((b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x())) / area;
  const double ha = face->vertex(0)->info().height_m;
  return ha + wb * (face->vertex(1)->info().height_m - ha) + wc * (face->vertex(2)->info().height_m - ha);
}

void refine(Cdt& cdt, const Cdt& coarse, double max_edge_m) {
  // The mesher refines the regions closed by constraints: close the convex hull.
  std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> hull;
  for (auto edge = cdt.all_edges_begin(); edge != cdt.all_edges_end(); ++edge) {
    const auto face = edge->first;
    const auto other = face->neighbor(edge->second);
    if (cdt.is_infinite(*edge) || (!cdt.is_infinite(face) && !cdt.is_infinite(other))) continue;
    hull.emplace_back(face->vertex(Cdt::cw(edge->second)), face->vertex(Cdt::ccw(edge->second)));
  }
  double hull_area = 0.0;
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) hull_area += std::abs(cdt.triangle(face).area());
  const double expected = hull_area / (0.3 * max_edge_m * max_edge_m);
  if (expected > max_refined_triangles)
    fail(
        "sketch max edge {} m would make about {:.0f} triangles over {:.0f} m^2, more than {:.0f}: give a larger max edge "
        "(subdivision adds the detail)",
        max_edge_m, expected, hull_area, max_refined_triangles);
  for (const auto& [a, b] : hull) cdt.insert_constraint(a, b);

  // One point at a time, counted: the estimate above holds for the area, but points or a frame
  // very close to a line make the mesher add points without end (a 1 mm frame ran for minutes
  // and gigabytes); past the cap it is refused instead.
  CGAL::Delaunay_mesher_2<Cdt, CGAL::Delaunay_mesh_size_criteria_2<Cdt>> mesher(cdt, {0.125, max_edge_m});
  mesher.init();
  while (!mesher.is_refinement_done()) {
    if (static_cast<double>(cdt.number_of_vertices()) > 0.5 * max_refined_triangles)
      fail(
          "refining the sketch to edges of {} m makes more than {:.0f} triangles (points or lines very close to each other, or to "
          "the frame, need tiny triangles): give a larger refine length, a wider frame, or move them apart",
          max_edge_m, max_refined_triangles);
    mesher.step_by_step_refine_mesh();
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!v->info().known) v->info().height_m = height_in(coarse, v->point());
}

}  // namespace

namespace {

SketchMesh triangulate_checked(const Sketch& sketch, const SketchParams& params) {
  Cdt cdt;
  try {
    insert_features(cdt, sketch);
    if (params.frame_margin_m > 0.0) insert_frame(cdt, sketch, params);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    fail(
        "two lines of the sketch cross or touch away from a shared point (too close to tell exactly where): add the "
        "point to both lines");
  }
  if (cdt.dimension() < 2) fail("all points of the sketch lie on one line: a surface needs points off it");
  if (params.max_edge_m > 0.0) {
    const Cdt coarse = cdt;
    try {
      refine(cdt, coarse, params.max_edge_m);
    } catch (const Cdt::Intersection_of_constraints_exception&) {
      fail("refining the sketch met crossing lines: check that no two lines cross");
    }
  }

  SketchMesh out;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info().index = static_cast<std::uint32_t>(out.mesh.positions.size());
    // x east, y up, z south; CGAL's counter-clockwise (east, north) faces then face +y.
    out.mesh.positions.emplace_back(float(v->point().x()), float(v->info().height_m), float(-v->point().y()));
    out.locked.push_back(v->info().locked ? 1 : 0);
  }
  // After refinement only faces inside the closed hull: points the mesher put on a hull edge
  // are rounded, and may leave slivers just outside it.
  const bool refined = params.max_edge_m > 0.0;
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face)
    if (!refined || face->is_in_domain())
      for (int k = 0; k < 3; ++k) out.mesh.indices.push_back(face->vertex(k)->info().index);
  return out;
}

}  // namespace

SketchMesh triangulate_sketch(const Sketch& sketch, const SketchParams& params) {
  check_sketch(sketch, params);
  try {
    return triangulate_checked(sketch, params);
  } catch (const CGAL::Failure_exception& e) {
    // A CGAL precondition or assertion that a checked sketch still trips (points too close to
    // tell apart in floating point): the sketch's fault more likely than ours, so a message.
    fail("the sketch cannot be triangulated (CGAL: {} failed): some points or lines are too close to tell apart; move them apart",
         e.expression());
  }
}

}  // namespace sansui::mesh
