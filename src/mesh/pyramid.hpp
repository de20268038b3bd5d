// The quadrangular pyramid of Fig. 3 of Nishimura and Sakata (seeds/004): the simplest input
// that shows what fractal subdivision does to a clean shape.
#pragma once

#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

/// Four triangles from the corners of a square base (y = 0, x and z from 0 to width) to an apex
/// above its centre; open at the bottom. Throws InputError unless both sizes are > 0.
/// `width_m`: side of the base. [Units: m] [Range: > 0]
/// `height_m`: height of the apex. [Units: m] [Range: > 0]
TriangleMesh make_pyramid(double width_m, double height_m);

}  // namespace sansui::mesh
