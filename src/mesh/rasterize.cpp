// Mesh to DEM by point sampling with "highest surface wins" (see rasterize.hpp).
//
// Triangles are sorted into bands of rows (a counting sort per fixed chunk of triangles, so the
// lists are the same for any thread count); then bands are drawn in parallel, each by one
// thread, so a sample needs no atomics and a band's rows stay in cache. A sample keeps the
// maximum of the heights written to it, which does not depend on their order. Coverage is
// inclusive with a tiny tolerance, so a sample on an edge shared by two triangles is never
// missed (both write it).
#include "mesh/rasterize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::mesh {
namespace {

struct Footprint {
  double min_x, max_x, min_z, max_z;
};

Footprint footprint_of(const TriangleMesh& mesh) {
  if (mesh.indices.empty()) fail("the mesh is empty: there is nothing to rasterise");
  constexpr double infinity = std::numeric_limits<double>::infinity();
  // Minima and maxima over fixed chunks of corners, in parallel (the same for any order).
  constexpr std::size_t chunk = 1 << 16;
  const std::size_t chunks = (mesh.indices.size() + chunk - 1) / chunk;
  std::vector<Footprint> parts(chunks, Footprint{infinity, -infinity, infinity, -infinity});
  parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    Footprint f = parts[k];
    for (std::size_t i = k * chunk; i < std::min(mesh.indices.size(), (k + 1) * chunk); ++i) {
      const glm::vec3 p = mesh.positions[mesh.indices[i]];
      f.min_x = std::min(f.min_x, double(p.x)), f.max_x = std::max(f.max_x, double(p.x));
      f.min_z = std::min(f.min_z, double(p.z)), f.max_z = std::max(f.max_z, double(p.z));
    }
    parts[k] = f;
  });
  Footprint f{infinity, -infinity, infinity, -infinity};
  for (const Footprint& part : parts) {
    f.min_x = std::min(f.min_x, part.min_x), f.max_x = std::max(f.max_x, part.max_x);
    f.min_z = std::min(f.min_z, part.min_z), f.max_z = std::max(f.max_z, part.max_z);
  }
  if (!std::isfinite(f.min_x + f.max_x + f.min_z + f.max_z)) fail("the mesh has a coordinate that is not a finite number");
  return f;
}

/// A triangle in sample coordinates (u east, v south, in cells from the frame's origin).
struct Projected {
  double u[3], v[3];
  float y[3];
};

Projected project(const TriangleMesh& mesh, std::size_t t, const RasterFrame& frame, double inverse_cell) {
  Projected p;
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 corner = mesh.positions[mesh.indices[3 * t + k]];
    p.u[k] = (double(corner.x) - frame.origin_x_m) * inverse_cell;
    p.v[k] = (double(corner.z) - frame.origin_y_m) * inverse_cell;
    p.y[k] = corner.y;
  }
  return p;
}

/// x as an int clamped to [-1, limit]: far-away coordinates must not overflow the conversion.
int clamped(double x, int limit) {
  return int(std::clamp(x, -1.0, double(limit)));
}

/// The rows of samples the triangle may cover (first > last: none).
std::pair<int, int> rows_of(const Projected& p, const RasterFrame& frame) {
  return {std::max(0, clamped(std::ceil(std::min({p.v[0], p.v[1], p.v[2]}) - 1e-6), frame.height)),
          std::min(frame.height - 1, clamped(std::floor(std::max({p.v[0], p.v[1], p.v[2]}) + 1e-6), frame.height))};
}

/// Draws rows first..last of one triangle. The three edge functions w_k = a_k i + b_k j + c_k
/// bound each row's run of samples directly (edges with a_k > 0 from the left, a_k < 0 from
/// the right), so no sample outside is ever tested and the row loop has no data-dependent
/// branches.
void draw_rows(const Projected& p, const RasterFrame& frame, int first, int last, Heightfield& grid) {
  const double area = (p.u[1] - p.u[0]) * (p.v[2] - p.v[0]) - (p.v[1] - p.v[0]) * (p.u[2] - p.u[0]);
  if (area == 0.0) return;  // seen edge-on: its neighbours cover the line it stands on
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const double i_first = std::max(0, clamped(std::ceil(std::min({p.u[0], p.u[1], p.u[2]}) - 1e-6), frame.width));
  const double i_last = std::min(frame.width - 1, clamped(std::floor(std::max({p.u[0], p.u[1], p.u[2]}) + 1e-6), frame.width));
  if (i_first > i_last) return;

  // Edge k runs from corner k+1 to corner k+2; w_k >= 0 inside (after `sign`), and w_k is
  // twice the area of the sub-triangle opposite corner k. Inclusive, with a tolerance far above
  // rounding, so shared edges are always covered. Inside: a_k i >= -(b_k j + c_k), i.e.
  // i >= t_k(j) if a_k > 0, i <= t_k(j) if a_k < 0, with t_k(j) = (b_k j + c_k) / -a_k.
  constexpr double tolerance = 1e-7;
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double a[3], b[3], c[3];
  struct Bound {
    double slope = 0.0, offset = 0.0;  // t(j) = slope * j + offset
  };
  Bound left[2] = {{0.0, -infinity}, {0.0, -infinity}}, right[2] = {{0.0, infinity}, {0.0, infinity}};
  int lefts = 0, rights = 0;
  for (int k = 0; k < 3; ++k) {
    const int from = (k + 1) % 3, to = (k + 2) % 3;
    a[k] = -sign * (p.v[to] - p.v[from]);
    b[k] = sign * (p.u[to] - p.u[from]);
    c[k] = sign * ((p.v[to] - p.v[from]) * p.u[from] - (p.u[to] - p.u[from]) * p.v[from]);
    if (a[k] != 0.0) {
      const double inverse_a = 1.0 / a[k];
      (a[k] > 0.0 ? left[lefts++ & 1] : right[rights++ & 1]) = Bound{-b[k] * inverse_a, -(c[k] + tolerance) * inverse_a};
    } else if (b[k] > 0.0) {  // a horizontal edge bounds the rows: b j + c + tolerance >= 0
      first = std::max(first, clamped(std::ceil(-(c[k] + tolerance) / b[k]), frame.height));
    } else {
      last = std::min(last, clamped(std::floor(-(c[k] + tolerance) / b[k]), frame.height));
    }
  }
  const double y0 = p.y[0], dy1 = double(p.y[1]) - y0, dy2 = double(p.y[2]) - y0;
  const double inverse_area = 1.0 / (sign * area);
  const double height_per_i = (a[1] * dy1 + a[2] * dy2) * inverse_area;
  for (int j = first; j <= last; ++j) {
    const double low = std::max({i_first, std::ceil(left[0].slope * j + left[0].offset), std::ceil(left[1].slope * j + left[1].offset)});
    const double high =
        std::min({i_last, std::floor(right[0].slope * j + right[0].offset), std::floor(right[1].slope * j + right[1].offset)});
    if (!(low <= high)) continue;  // also keeps huge bounds out of the int conversions below
    const double height_at_0 = y0 + ((b[1] * j + c[1]) * dy1 + (b[2] * j + c[2]) * dy2) * inverse_area;
    float* samples = grid.row(j).data();
    for (int i = int(low); i <= int(high); ++i) samples[i] = std::max(samples[i], float(height_at_0 + height_per_i * i));
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
    fail(
        "cell size {} m would make a DEM of {:.0f} x {:.0f} samples over {:.0f} x {:.0f} m, more than {} per side: give "
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
  return {f.min_x - 0.5 * (side - (f.max_x - f.min_x)), f.min_z - 0.5 * (side - (f.max_z - f.min_z)), cell, samples, samples};
}

Heightfield rasterize(const TriangleMesh& mesh, const RasterFrame& frame, std::optional<float> fill_m, const Context& context) {
  check_frame(frame);
  if (mesh.indices.empty()) fail("the mesh is empty: there is nothing to rasterise");
  // Unset here: each band sets its own rows just before drawing them, so the first touch of this
  // memory happens in parallel and in cache.
  Heightfield grid = Heightfield::uninitialized(frame.width, frame.height, frame.cell_size_m);
  grid.origin_x_m = frame.origin_x_m;
  grid.origin_y_m = frame.origin_y_m;

  const std::size_t triangles = mesh.triangle_count();
  const double inverse_cell = 1.0 / frame.cell_size_m;
  constexpr int band_rows = 32;  // 32 rows of a 4097-wide grid: 512 KiB, stays in L2
  const std::size_t bands = std::size_t(frame.height + band_rows - 1) / band_rows;
  constexpr std::size_t chunk = 1 << 14;
  const std::size_t chunks = (triangles + chunk - 1) / chunk;

  // 1. Which bands each triangle touches, counted per (chunk, band); the lowest vertex too.
  std::vector<std::uint32_t> band_span(triangles);  // first band << 16 | last band; first > last: none
  std::vector<std::uint32_t> count(chunks * bands, 0);
  std::vector<float> lowest(chunks, std::numeric_limits<float>::infinity());
  std::vector<char> finite(chunks, 1);
  parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    context.check_cancelled();
    for (std::size_t t = k * chunk; t < std::min(triangles, (k + 1) * chunk); ++t) {
      const Projected p = project(mesh, t, frame, inverse_cell);
      if (!std::isfinite(p.u[0] + p.u[1] + p.u[2] + p.v[0] + p.v[1] + p.v[2] + p.y[0] + p.y[1] + p.y[2])) {
        finite[k] = 0;
        band_span[t] = 1u << 16;
        continue;
      }
      lowest[k] = std::min({lowest[k], p.y[0], p.y[1], p.y[2]});
      const auto [first, last] = rows_of(p, frame);
      if (first > last) {
        band_span[t] = 1u << 16;  // first band 1, last band 0
        continue;
      }
      const auto first_band = std::uint32_t(first / band_rows), last_band = std::uint32_t(last / band_rows);
      band_span[t] = first_band << 16 | last_band;
      for (std::uint32_t b = first_band; b <= last_band; ++b) ++count[k * bands + b];
    }
  });
  if (std::ranges::find(finite, 0) != finite.end()) fail("the mesh has a coordinate that is not a finite number");
  // 2. Lists per band, in triangle order: offsets band-major, then chunk by chunk.
  std::vector<std::size_t> band_start(bands + 1, 0);
  std::vector<std::size_t> offset(chunks * bands);
  std::size_t total = 0;
  for (std::size_t b = 0; b < bands; ++b) {
    band_start[b] = total;
    for (std::size_t k = 0; k < chunks; ++k) offset[k * bands + b] = total, total += count[k * bands + b];
  }
  band_start[bands] = total;
  std::vector<std::uint32_t> list(total);
  parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    for (std::size_t t = k * chunk; t < std::min(triangles, (k + 1) * chunk); ++t)
      for (std::uint32_t b = band_span[t] >> 16; b <= (band_span[t] & 0xFFFFu); ++b) list[offset[k * bands + b]++] = std::uint32_t(t);
  });
  // 3. Bands in parallel, each drawing its triangles' rows inside it, then filling the gaps.
  constexpr float nothing = -std::numeric_limits<float>::infinity();
  const float fill = fill_m ? *fill_m : *std::min_element(lowest.begin(), lowest.end());
  parallel_for(std::size_t{0}, bands, [&](std::size_t b) {
    context.check_cancelled();
    const int band_first = int(b) * band_rows, band_last = std::min(frame.height - 1, band_first + band_rows - 1);
    for (int j = band_first; j <= band_last; ++j) std::ranges::fill(grid.row(j), nothing);
    for (std::size_t n = band_start[b]; n < band_start[b + 1]; ++n) {
      const Projected p = project(mesh, list[n], frame, inverse_cell);
      const auto [first, last] = rows_of(p, frame);
      draw_rows(p, frame, std::max(first, band_first), std::min(last, band_last), grid);
    }
    for (int j = band_first; j <= band_last; ++j)
      for (float& value : grid.row(j))
        if (value == nothing) value = fill;
  });
  context.report("rasterise", 1.0);
  return grid;
}

}  // namespace sansui::mesh
