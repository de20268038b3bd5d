// A coarse mountain from a map sketch: ridge and valley lines (and spot heights) with heights,
// triangulated by a constrained Delaunay triangulation (CGAL) so that every drawn line is made
// of triangle edges. This is the "rough triangles along the terrain lines" (地勢線) that
// Nishimura and Sakata draw by hand before fractal subdivision (seeds/004, Fig. 5a), made
// without a modelling tool.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/sketch.hpp"
#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

// The sketch's data (core/sketch.hpp), under the names mesh has always used.
using SketchPoint = sansui::SketchPoint;
using SketchFeature = sansui::SketchFeature;
using Sketch = sansui::Sketch;

/// Table: mesh_params.cpp (section [sketch]).
/// The frame's margin as a multiple of the sketch's larger extent: at least, at most.
inline constexpr double min_frame_ratio = 0.01, max_frame_ratio = 100.0;

struct SketchParams {
  /// Refine until no triangle edge is longer than this (CGAL Delaunay mesher, angles >= 20.7
  /// degrees); new points take their height from the unrefined triangulation. 0: no refinement.
  /// [Units: m] [Range: >= 0] [Default: 0]
  double max_edge_m = 0.0;
  /// Add a rectangular frame this far outside the sketch's bounding box. 0: no frame (the mesh
  /// ends at the convex hull of the points). [Units: m] [Range: 0, or min_frame_ratio to
  /// max_frame_ratio times the sketch's size] [Default: 0]
  double frame_margin_m = 0.0;
  /// Height of the frame's corners. [Units: m] [Default: the lowest height of the sketch]
  std::optional<double> frame_height_m;
};
const params::Table<SketchParams>& parameter_table(const SketchParams*);

/// The sketch's triangulation as a mesh (x east, y up = height, z south = -north), triangles
/// facing up, and one lock flag per vertex.
struct SketchMesh {
  TriangleMesh mesh;
  std::vector<std::uint8_t> locked;
};

/// Throws InputError naming the feature for: no features, a non-finite number, two lines that
/// cross (or touch) away from a shared vertex, one map point given two different heights, a
/// line with a zero-length segment, fewer than three distinct points or all points on one line,
/// and bad parameters.
void check_sketch(const Sketch& sketch, const SketchParams& params);

/// check_sketch(), then the constrained Delaunay triangulation (refined and framed as asked).
SketchMesh triangulate_sketch(const Sketch& sketch, const SketchParams& params = {});

}  // namespace sansui::mesh
