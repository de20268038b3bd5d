// Removing the loops ("twists", Fig. 18) that midpoint displacement and phase randomisation put
// into a contour (Misawa, Chiba, Saito 1987, seeds/000, Sec. 4.4):
//  - method 1: build the planar graph of the curve (its self-crossings are vertices), find its
//    faces, drop the faces bounded by fewer than `threshold` segments, and keep the outline of the
//    remaining faces of positive winding number;
//  - method 2: insert the crossings into the point sequence, start on a stretch between crossings
//    that has at least `threshold` points (the longest one), walk forward, and at the first visit
//    of a crossing jump to its second visit, cutting out the excursion between them.
// The paper knows no complete method; where method 2 still leaves a crossing or a clockwise curve
// (rare), we fall back to the positive-winding outline (Clipper), which never fails.
#pragma once

#include <vector>

#include "contour/geometry.hpp"
#include "core/params.hpp"

namespace sansui::contour {

struct LoopRemovalParams {
  /// 1 or 2 (see above). [Default: 2]
  int method = 2;
  /// Faces (method 1) or stretches (method 2) with fewer segments than this are loops.
  /// [Range: >= 3] [Default: 16]
  int threshold = 16;
};
/// Table: contour_params.cpp (flattened into [contour] as loop_removal, loop_threshold).
const params::Table<LoopRemovalParams>& parameter_table(const LoopRemovalParams*);

/// Simple counter-clockwise rings without self-crossings: usually one; several when a crossing
/// cuts the contour into large parts (method 1). Empty when nothing positive is left.
std::vector<Ring> remove_loops(const Ring& ring, const LoopRemovalParams& params);

/// Method 1 alone (see above).
std::vector<Ring> remove_loops_by_faces(const Ring& ring, int threshold);
/// Method 2 alone, without the fallback: the walked ring (may be clockwise in odd cases).
Ring remove_loops_by_walk(const Ring& ring, int threshold);

}  // namespace sansui::contour
