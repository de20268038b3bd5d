// Where the slice picture of a solid texture cuts the block: "AXIS=V", V in lattice units
// (0..2^R) or a percentage of the block ("z=50%").
#pragma once

#include <string>
#include <string_view>

namespace sansui::scene {

struct SliceSpec {
  int axis = 2;           ///< 0 x, 1 y, 2 z
  double position = 0.0;  ///< [Units: lattice units]
};

/// "" when `text` has the form AXIS=V, else what is allowed.
std::string slice_problem(std::string_view text);

/// The slice of a block of 2^levels lattice units. Throws InputError naming `text` when it is
/// not AXIS=V or lies outside the block.
SliceSpec parse_slice(std::string_view text, int levels);

}  // namespace sansui::scene
