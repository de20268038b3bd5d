// Mesh to DEM by point sampling with "highest surface wins" (see rasterize.hpp).
//
// Triangles are drawn in parallel; a sample keeps the maximum of the heights written to it,
// with an atomic compare-and-swap. A maximum does not depend on the order of its arguments, so
// the bytes are the same for any thread count. Coverage tests are inclusive with a tiny
// tolerance, so a sample on an edge shared by two triangles is never missed (both write it).
#include "mesh/rasterize.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.hpp"

namespace sansui::mesh {
namespace {

struct Footprint {
  double min_x, max_x, min_z, max_z;
};

Footprint footprint_of(const TriangleMesh& mesh) {
  if (mesh.indices.empty()) fail("the mesh is empty: there is nothing to rasterise");
  Footprint f{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (std::uint32_t index : mesh.indices) {
    const glm::vec3 p = mesh.positions[index];
    f.min_x = std::min(f.min_x, double(p.x)), f.max_x = std::max(f.max_x, double(p.x));
    f.min_z = std::min(f.min_z, double(p.z)), f.max_z = std::max(f.max_z, double(p.z));
  }
  if (!std::isfinite(f.min_x + f.max_x + f.min_z + f.max_z)) fail("the mesh has a coordinate that is not a finite number");
  return f;
}

void atomic_max(float& target, float value) {
  std::atomic_ref<float> slot(target);
  float current = slot.load(std::memory_order_relaxed);
  while (value > current && !slot.compare_exchange_weak(current, value, std::memory_order_relaxed)) {
  }
}

/// Twice the signed area of (a, b, p) in the plane.
double orient(double ax, double ay, double bx, double by, double px, double py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/// Draws one triangle. Coordinates u, v are in samples from the frame's origin.
void draw_triangle(const glm::vec3 (&corner)[3], const RasterFrame& frame, Heightfield& grid) {
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = (double(corner[k].x) - frame.origin_x_m) / frame.cell_size_m;
    v[k] = (double(corner[k].z) - frame.origin_y_m) / frame.cell_size_m;
  }
  const double area = orient(u[0], v[0], u[1], v[1], u[2], v[2]);
  if (area == 0.0) return;  // seen edge-on: its neighbours cover the line it stands on
  // Inclusive tests: rounding in orient() is far below this, so shared edges are always covered.
  constexpr double tolerance = 1e-7;
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const int i0 = std::max(0, int(std::ceil(std::min({u[0], u[1], u[2]}) - 1e-6)));
  const int i1 = std::min(frame.width - 1, int(std::floor(std::max({u[0], u[1], u[2]}) + 1e-6)));
  const int j0 = std::max(0, int(std::ceil(std::min({v[0], v[1], v[2]}) - 1e-6)));
  const int j1 = std::min(frame.height - 1, int(std::floor(std::max({v[0], v[1], v[2]}) + 1e-6)));
  if (i0 > i1 || j0 > j1) return;
  const double y0 = corner[0].y, dy1 = double(corner[1].y) - y0, dy2 = double(corner[2].y) - y0;

  auto rows = [&](int first, int last) {
    for (int j = first; j <= last; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double pu = i, pv = j;
        const double w0 = sign * orient(u[1], v[1], u[2], v[2], pu, pv);
        const double w1 = sign * orient(u[2], v[2], u[0], v[0], pu, pv);
        const double w2 = sign * orient(u[0], v[0], u[1], v[1], pu, pv);
        if (w0 < -tolerance || w1 < -tolerance || w2 < -tolerance) continue;
        // Relative to corner 0: exact at corner 0, and w1 = w2 = 0 there exactly.
        const double height = y0 + (w1 * dy1 + w2 * dy2) / (sign * area);
        atomic_max(grid(i, j), float(height));
      }
  };
  // Big triangles (a coarse mesh on a fine grid) are split by rows, so a few of them still
  // keep every thread busy.
  constexpr int rows_per_task = 32;
  if (j1 - j0 < 2 * rows_per_task) {
    rows(j0, j1);
  } else {
    tbb::parallel_for(j0, j1 + 1, rows_per_task, [&](int j) { rows(j, std::min(j1, j + rows_per_task - 1)); });
  }
}

void check_frame(const RasterFrame& frame) {
  if (!(frame.cell_size_m > 0.0) || !std::isfinite(frame.cell_size_m))
    fail("cell size {} m is not allowed: it must be > 0", frame.cell_size_m);
  if (frame.width < 1 || frame.height < 1 || frame.width > max_raster_side || frame.height > max_raster_side)
    fail("a DEM of {} x {} samples is not allowed: each side must be 1..{}", frame.width, frame.height, max_raster_side);
}

}  // namespace

RasterFrame frame_with_cell(const TriangleMesh& mesh, double cell_size_m) {
  if (!(cell_size_m > 0.0) || !std::isfinite(cell_size_m)) fail("cell size {} m is not allowed: it must be > 0", cell_size_m);
  const Footprint f = footprint_of(mesh);
  const double width = std::floor((f.max_x - f.min_x) / cell_size_m + 1e-6) + 1.0;
  const double height = std::floor((f.max_z - f.min_z) / cell_size_m + 1e-6) + 1.0;
  if (width > max_raster_side || height > max_raster_side)
    fail("cell size {} m would make a DEM of {:.0f} x {:.0f} samples over {:.0f} x {:.0f} m, more than {} per side: give "
         "a larger cell size",
         cell_size_m, width, height, f.max_x - f.min_x, f.max_z - f.min_z, max_raster_side);
  return {f.min_x, f.min_z, cell_size_m, int(width), int(height)};
}

RasterFrame square_frame(const TriangleMesh& mesh, int samples) {
  if (samples < 2 || samples > max_raster_side)
    fail("a DEM of {} samples per side is not allowed: it must be 2..{}", samples, max_raster_side);
  const Footprint f = footprint_of(mesh);
  const double side = std::max(f.max_x - f.min_x, f.max_z - f.min_z);
  if (!(side > 0.0)) fail("the mesh has no extent seen from above: there is nothing to rasterise");
  const double cell = side / double(samples - 1);
  return {f.min_x - 0.5 * (side - (f.max_x - f.min_x)), f.min_z - 0.5 * (side - (f.max_z - f.min_z)), cell, samples,
          samples};
}

Heightfield rasterize(const TriangleMesh& mesh, const RasterFrame& frame, std::optional<float> fill_m,
                      const Context& context) {
  check_frame(frame);
  if (mesh.indices.empty()) fail("the mesh is empty: there is nothing to rasterise");
  Heightfield grid(frame.width, frame.height, -std::numeric_limits<float>::infinity(), frame.cell_size_m);
  grid.origin_x_m = frame.origin_x_m;
  grid.origin_y_m = frame.origin_y_m;

  const std::size_t triangles = mesh.triangle_count();
  constexpr std::size_t chunk = 1 << 15;
  tbb::parallel_for(std::size_t{0}, (triangles + chunk - 1) / chunk, [&](std::size_t k) {
    context.check_cancelled();
    for (std::size_t t = k * chunk; t < std::min(triangles, (k + 1) * chunk); ++t) {
      const glm::vec3 corner[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                                   mesh.positions[mesh.indices[3 * t + 2]]};
      draw_triangle(corner, frame, grid);
    }
  });

  float fill = 0.0f;
  if (fill_m) {
    fill = *fill_m;
  } else {
    fill = std::numeric_limits<float>::infinity();
    for (std::uint32_t index : mesh.indices) fill = std::min(fill, mesh.positions[index].y);
  }
  for (float& value : grid.values())
    if (value == -std::numeric_limits<float>::infinity()) value = fill;
  context.report("rasterise", 1.0);
  return grid;
}

}  // namespace sansui::mesh
