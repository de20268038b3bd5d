// Polygon shrinking and expansion: the offset step of
//   M. Misawa, N. Chiba, N. Saito, "Simulation of natural scenes: procedure modeling for
//   mountains" (IPSJ, 1987; seeds/000), Sec. 2, "polygon shrinking algorithm", Figs. 2-8.
// Step 1 offsets every edge by d to its left (inward for a counter-clockwise ring); Step 2 fills
// the gap at every vertex where the offset edges part with one of four joins (Fig. 5a-c, Fig. 7);
// Steps 3-4 (intersect all pieces, keep every counter-clockwise cycle) are the region of positive
// winding number of that raw curve, computed by Clipper (see clipping.hpp). Each resulting ring is
// a new contour; several rings are islands (peaks) split at a narrow neck (Fig. 4).
#pragma once

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

/// How the offset edges are joined where they leave a gap (SPEC 1.1).
enum class Join {
  extended,  ///< Fig. 5a: extend both offset lines to their intersection (a miter).
  straight,  ///< Fig. 5b: connect the two offset end points (a bevel).
  arc,       ///< Fig. 5c: a circular arc of radius d around the vertex (the equidistant curve).
  clipped,   ///< Fig. 7: the point on the bisector at min(c*d, miter distance), joined to both ends.
};

/// "extended", "straight", "arc", "clipped"; nullopt for anything else.
std::optional<Join> join_from_name(std::string_view name);
std::string_view name_of(Join join);

struct OffsetParams {
  /// Distance between the ring and its offset. [Units: m] [Range: > 0]
  double distance_m = 10.0;
  /// Join where the offset edges leave a gap. [Default: clipped]
  Join join = Join::clipped;
  /// c of the clipped join: the bisector point lies at min(c*d, miter distance). [Range: >= 1] [Default: 1.4]
  double clip_factor = 1.4;
  /// Largest angle of one segment of an arc join. [Units: degrees] [Range: 1..45] [Default: 15]
  double arc_step_deg = 15.0;
  /// true: offset to the right of a counter-clockwise ring (expansion, toward the foot).
  bool outward = false;
  /// The offset of the edge from a to b, when it varies along the ring (--offset-variation);
  /// empty: distance_m everywhere. [Units: m] [Range: > 0]
  std::function<double(Point a, Point b)> edge_distance;
};

/// The raw offset curve of a counter-clockwise ring (Steps 1-2): offset edges with joins in the
/// gaps, and the original vertex between overlapping offset edges (as Clipper's own offset does,
/// so that the positive-winding region is exact on both sides). It crosses itself in general.
Ring raw_offset_curve(const Ring& ring, const OffsetParams& params);

/// The offset contours (Steps 1-4): counter-clockwise rings, several if the ring splits into
/// islands, none if nothing is left. Outward offsets return their outer boundary.
std::vector<Ring> offset_ring(const Ring& ring, const OffsetParams& params);

struct PrecleanParams {
  /// Segments shorter than this lose one end point. [Units: m] [Range: >= 0]
  double min_segment_m = 0.0;
  /// Vertices whose inner or outer angle is sharper than this are dropped (spikes and cracks).
  /// [Units: degrees] [Range: 0..60] [Default: 5]
  double min_angle_deg = 5.0;
};

/// The paper's workaround for Fig. 8: removes very short segments and very sharp vertices before
/// shrinking. Never removes so much that fewer than 3 vertices remain.
Ring preclean(const Ring& ring, const PrecleanParams& params);

}  // namespace sansui::contour
