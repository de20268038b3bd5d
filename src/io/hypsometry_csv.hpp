// Hypsometric (altitude-area) curves from text: "area,height" lines of fractions in [0, 1]
// (io/number_pairs.hpp: '#' comments, an optional header), for contour::apply_hypsometry.
#pragma once

#include <string_view>

#include "contour/elevations.hpp"

namespace sansui::io {

/// Throws InputError naming the file and line for a bad line, or if the curve is not monotone.
contour::Hypsometry parse_hypsometry(std::string_view text, std::string_view source);

}  // namespace sansui::io
