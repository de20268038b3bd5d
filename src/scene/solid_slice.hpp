// Where the slice picture of a solid texture cuts the block: "AXIS=V", V in lattice units
// (0..2^R) or a percentage of the block ("z=50%"); and the field as a volume file's planes.
#pragma once

#include <string>
#include <string_view>

#include "io/volume_file.hpp"
#include "solid/evaluator.hpp"

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

/// The field's lattice as a volume file's planes, with its parameters for the sidecar.
io::Volume field_volume(solid::FieldEvaluator& field);

}  // namespace sansui::scene
