// Polygon Boolean operations through Clipper 1 (Angus Johnson, libpolyclipping), which works in
// integer coordinates: metres are scaled by a fixed factor (clipper_units_per_metre) and rounded,
// so every result is exact on a 1 mm lattice. The region of positive winding number of a
// self-intersecting curve (the paper's Steps 3-4: intersect all pieces, keep the
// counter-clockwise cycles) is Clipper's union with the positive fill rule.
#pragma once

#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

/// Clipper integer units per metre: results lie on a 1 mm lattice. Coordinates up to about
/// 1000 km stay in Clipper's fast 32-bit range; beyond, Clipper switches to 128-bit arithmetic.
inline constexpr double clipper_units_per_metre = 1000.0;

/// The outer boundaries (counter-clockwise) of the region where the winding number of `curve`
/// is positive. Holes of that region are dropped (an inward offset of a simple polygon has none).
/// Strictly simple (the default): where the region pinches to a point, it becomes two rings
/// rather than one that touches itself; that costs about twice the time, which the offset step
/// saves (its results are clipped again, strictly, when they are perturbed).
std::vector<Ring> positive_region(const Ring& curve, bool strictly_simple = true);
/// The same for several curves together (winding numbers add up).
std::vector<Ring> positive_region(const std::vector<Ring>& curves);
/// The outer boundaries of a ∩ b (each a set of counter-clockwise rings). All results below are
/// strictly simple.
std::vector<Ring> intersection(const std::vector<Ring>& a, const std::vector<Ring>& b);
/// The outer boundaries of a \ b.
std::vector<Ring> difference(const std::vector<Ring>& a, const std::vector<Ring>& b);
/// Area of a ∩ b. [Units: m^2]
double intersection_area(const Ring& a, const Ring& b);
/// Rings grown (delta > 0) or shrunk (delta < 0) by |delta| with round joins: Clipper's own
/// offset, used for the small clearance between nested contours. [Units: m]
std::vector<Ring> inflate(const std::vector<Ring>& rings, double delta_m);
/// True if the ring is simple (no self-crossing) as Clipper sees it: its non-zero region is one
/// ring with the same area.
bool is_simple(const Ring& ring);

}  // namespace sansui::contour
