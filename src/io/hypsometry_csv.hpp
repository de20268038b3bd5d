// Hypsometric (altitude-area) curves from text: "area,height" lines of fractions in [0, 1]
// (io/number_pairs.hpp: '#' comments, an optional header), for contour::apply_hypsometry
// (contour::Hypsometry holds the points).
#pragma once

#include <string_view>
#include <utility>
#include <vector>

namespace sansui::io {

/// (area fraction, height fraction) pairs, height rising and area falling strictly.
using HypsometryPoints = std::vector<std::pair<double, double>>;

/// Throws InputError naming the file and line for a bad line, or if the curve is not monotone.
HypsometryPoints parse_hypsometry(std::string_view text, std::string_view source);

}  // namespace sansui::io
