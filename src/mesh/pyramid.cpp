// The quadrangular pyramid of Fig. 3 (seeds/004).
#include "mesh/pyramid.hpp"

#include <cmath>

#include "core/error.hpp"

namespace sansui::mesh {

TriangleMesh make_pyramid(double width_m, double height_m) {
  if (!(width_m > 0.0) || !std::isfinite(width_m)) fail("pyramid width {} m is not allowed: it must be > 0", width_m);
  if (!(height_m > 0.0) || !std::isfinite(height_m)) fail("pyramid height {} m is not allowed: it must be > 0", height_m);
  const auto w = static_cast<float>(width_m), h = static_cast<float>(height_m);
  TriangleMesh mesh;
  // Base corners going counter-clockwise seen from above (x east, z south), then the apex.
  mesh.positions = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, w}, {w, 0.0f, w}, {w, 0.0f, 0.0f}, {0.5f * w, h, 0.5f * w}};
  mesh.indices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  return mesh;
}

}  // namespace sansui::mesh
