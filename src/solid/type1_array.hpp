// Type I of Okada, Taga, Yokoi, Toriwaki (1990; seeds/002, Sec. 2; SPEC 2): the whole lattice
// {0..2^R}^3 in one array, filled level by level. At level n every cube of the level-(n-1)
// lattice gets its 12 edge midpoints (eq. 1), then its 6 face centres (eq. 3), then its centre
// (eq. 4), each the mean of its parents plus g * L(n).
#pragma once

#include "core/context.hpp"
#include "solid/field.hpp"
#include "solid/volume.hpp"

namespace sansui::solid {

/// The field on every lattice point. Uses all threads of the parallel seam (core/parallel.hpp); the values
/// do not depend on how many. Throws InputError for bad parameters (see FieldParams), and
/// std::bad_alloc if the (2^R+1)^3 floats do not fit (check_fits says so beforehand).
Volume generate_type1(const FieldParams& params, const Context& context = quiet_context());

}  // namespace sansui::solid
