// Seed contours: checking and normalising a ring read from a file (io/seed_files.hpp) or taken
// from a DEM: finite coordinates, at least 3 distinct vertices, non-zero area, counter-clockwise,
// no self-crossing. What can be repaired unambiguously (an almost closed line, a small
// self-crossing loop) is repaired and said in `notes`; anything else throws InputError.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct SeedContour {
  Ring ring;                       ///< counter-clockwise, simple, metres
  std::vector<std::string> notes;  ///< repairs and choices made, one line each
};

/// Checks and normalises a ring (see above). `closed` says whether the input closed it itself
/// (a GeoJSON LineString may not); an open ring whose ends are close is closed with a note.
SeedContour normalise_seed(Ring ring, bool closed, std::string_view source);

}  // namespace sansui::contour
