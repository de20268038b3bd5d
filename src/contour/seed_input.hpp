// Seed contours: checking and normalising a ring read from a file (io/seed_files.hpp) or taken
// from a DEM: finite coordinates no larger than max_seed_coordinate_m, at least 3 distinct
// vertices, non-zero area, counter-clockwise, no self-crossing. What can be repaired unambiguously (an almost closed line, a small
// self-crossing loop) is repaired and said in `notes`; anything else throws InputError.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

/// Largest |x| and |y| of a seed vertex: 100,000 km, more than any projected CRS uses (UTM
/// northings stop at 10,000 km, Web Mercator at 20,000 km), and far inside what the polygon
/// clipping (contour/clipping.hpp, a 1 mm integer lattice) can represent. [Units: m]
inline constexpr double max_seed_coordinate_m = 1e8;

struct SeedContour {
  Ring ring;                       ///< counter-clockwise, simple, metres
  std::vector<std::string> notes;  ///< repairs and choices made, one line each
};

/// Checks and normalises a ring (see above). `closed` says whether the input closed it itself
/// (a GeoJSON LineString may not); an open ring whose ends are close is closed with a note.
SeedContour normalise_seed(Ring ring, bool closed, std::string_view source);

/// Several seeds of one file must lie apart: each is one mountain's outline, and mountains do not
/// overlap. Throws InputError naming `source` and the two seeds if one crosses or holds another.
void check_seeds_apart(const std::vector<Ring>& seeds, std::string_view source);

}  // namespace sansui::contour
