// Seed contours from a file's text: io reads the outlines (io/seed_files.hpp), contour checks and
// normalises each (contour::normalise_seed) and refuses seeds that overlap. One mountain grows
// from each seed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contour/seed_input.hpp"
#include "io/seed_files.hpp"

namespace sansui::scene {

/// The seed contours of one file, in file order, with the notes of their repairs.
struct SeedContours {
  std::vector<contour::Ring> rings;  ///< each counter-clockwise and simple, disjoint, metres
  std::vector<std::string> notes;
};

/// Every seed in `text` (the contents of `source`, named in messages) in `format`.
/// `metres_per_unit` scales SVG coordinates. [Units: m] [Range: > 0] [Default: 1]
SeedContours parse_seeds(std::string_view text, io::SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

/// The same for a file that must hold exactly one seed (refused otherwise, naming the count).
contour::SeedContour parse_seed(std::string_view text, io::SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

}  // namespace sansui::scene
