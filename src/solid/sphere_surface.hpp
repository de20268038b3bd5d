// The voxels of the paper's Experiment 2 (Okada et al. 1990, Sec. 7-3; seeds/002): the surface
// of the digital sphere inscribed in the lattice {0..2^R}^3, "with the smallest cell as the
// quantum". A lattice point is inside when its distance to the centre (2^(R-1), 2^(R-1),
// 2^(R-1)) is at most 2^(R-1); it is on the surface when it is inside and one of its six
// neighbours is not.
#pragma once

#include <vector>

namespace sansui::solid {

struct SurfaceVoxel {
  int x = 0, y = 0, z = 0;
};

/// The surface voxels in raster order (x fastest, then y, then z): the coherent order in which
/// a renderer meets them row by row. [Range: 1 <= levels <= 20]
std::vector<SurfaceVoxel> digital_sphere_surface(int levels);

}  // namespace sansui::solid
