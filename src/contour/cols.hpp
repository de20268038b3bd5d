// Cols that dip between summits (issue 17 item 3). The contour-line method grows every level
// inside the one below, so two peaks part where their common contour pinches: the saddle between
// them is never below that split level. A real col is lower, and the levels just below it are
// already two rings, pinched at the col.
//
// dip_cols carves that: at every split (a contour with two or more rising children), the col
// lies halfway between the two largest children A and B at their closest points, and its line
// crosses the neck there, perpendicular to AB. The `levels` contours from the split contour down
// are cut along that line (its chord through the lowest of them), and so are the contours above
// them that come near it: a contour `k` levels above the lowest cut loses a strip of half-width
// (k + 1) d / 2 around the line, a V-shaped notch twice as steep as the mountain's mean slope. So
// the split contour and the levels - 1 below it become two rings each, and the saddle falls from
// the split level z to between z - levels dz and z - (levels - 1) dz.
//
// Nesting holds by construction: a contour one level up loses a strip d / 2 wider than its
// parent's (at least the clearance), so the pieces of nested contours stay nested and apart;
// each piece becomes a node, its parent the piece of the parent contour that holds it. Pieces
// smaller than the smallest contour are dropped (with whatever would lie inside them, which is
// smaller still). The seed and the outward contours are never cut (a col dips at most to the
// first level above the seed), nor is a crater's inside.
#pragma once

#include "contour/contour_tree.hpp"

namespace sansui::contour {

struct ColParams {
  /// Contour levels cut below each split: the col's depth in intervals. [Range: >= 1]
  int levels = 1;
  /// d, the contour offset: the notch widens by d / 2 per level. [Units: m] [Range: > 0]
  double offset_m = 10.0;
  /// Pieces smaller than this are dropped. [Units: m^2] [Range: >= 0]
  double min_area_m2 = 25.0;
};

/// Carves a col at every split of `tree` (see above). The tree stays valid: every contour inside
/// its parent and apart from its siblings, levels one apart.
void dip_cols(ContourTree& tree, const ColParams& params);

}  // namespace sansui::contour
