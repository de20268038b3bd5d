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

/// The surface voxels in raster order (x fastest, then y, then z). On a surface that order is not
/// coherent: a row of the lattice meets the sphere's surface at its two ends only, far apart.
/// [Range: 1 <= levels <= 20]
std::vector<SurfaceVoxel> digital_sphere_surface(int levels);

/// Sorts voxels along the octree (Morton or Z order: interleaved coordinate bits), so that
/// consecutive voxels share their cubes down to the deepest possible level: the order in which
/// a walk along the surface meets them, and the coherent order for Types III and IV.
void sort_along_octree(std::vector<SurfaceVoxel>& voxels);

}  // namespace sansui::solid
