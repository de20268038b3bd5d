// A heightfield as an indexed triangle mesh: vertex (i, j) at (origin_x + i * cell, height,
// origin_y + j * cell) in Sansui's axes (x east, y up, z south), two triangles per cell, wound
// counter-clockwise seen from above (+y), so the geometric normals point up. Vertex normals come
// from central differences of the heights (one-sided at the border), the usual heightfield normal
// n = normalize(-dh/dx, 1, -dh/dz); they are smoother than averaged face normals and need no
// adjacency. Texture coordinates run 0 to 1 over the terrain's extent: u = i / (width - 1) east,
// v = j / (height - 1) south (row 0, the north row, at the top of the texture). Rows are independent, so they run in parallel with
// identical results.
#include "mesh/heightfield_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"

namespace sansui::mesh {
namespace {

/// The height derivative along one axis at `index` of `count` samples, by central differences
/// inside and one-sided differences at the two ends. [Units: m/m]
template <class HeightAt>
float slope(const HeightAt& height_at, int index, int count, double cell_size_m) {
  if (count < 2) return 0.0f;
  const int before = index > 0 ? index - 1 : index;
  const int after = index < count - 1 ? index + 1 : index;
  return static_cast<float>((height_at(after) - height_at(before)) / ((after - before) * cell_size_m));
}

}  // namespace

TriangleMesh heightfield_to_mesh(const Heightfield& heights) {
  const int width = heights.width(), height = heights.height();
  if (width < 2 || height < 2) fail("a heightfield of {} x {} samples has no cells to make a mesh of", width, height);
  if (heights.size() > std::numeric_limits<std::uint32_t>::max())
    fail("a heightfield of {} x {} samples has too many vertices for a mesh with 32-bit indices", width, height);
  if (!(heights.cell_size_m > 0.0)) fail("cell size {} m is not allowed: it must be > 0", heights.cell_size_m);

  TriangleMesh mesh;
  mesh.positions.resize(heights.size());
  mesh.normals.resize(heights.size());
  mesh.uvs.resize(heights.size());
  mesh.indices.resize(static_cast<std::size_t>(width - 1) * static_cast<std::size_t>(height - 1) * 6);
  const double cell = heights.cell_size_m;

  parallel_for(0, height, [&](int j) {
    const auto z = static_cast<float>(heights.origin_y_m + j * cell);
    for (int i = 0; i < width; ++i) {
      const std::size_t v = static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i);
      mesh.positions[v] = {static_cast<float>(heights.origin_x_m + i * cell), heights(i, j), z};
      const float dx = slope([&](int x) { return double{heights(x, j)}; }, i, width, cell);
      const float dz = slope([&](int y) { return double{heights(i, y)}; }, j, height, cell);
      mesh.normals[v] = glm::normalize(glm::vec3(-dx, 1.0f, -dz));
      mesh.uvs[v] = {static_cast<float>(static_cast<double>(i) / (width - 1)), static_cast<float>(static_cast<double>(j) / (height - 1))};
    }
    if (j == height - 1) return;
    // Cell (i, j) to (i + 1, j + 1): a = (i, j), b = (i + 1, j), c = (i, j + 1), d = (i + 1, j + 1).
    // (a, c, b) and (b, c, d) are counter-clockwise seen from +y, because +x then +z turns clockwise.
    std::uint32_t* out = mesh.indices.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(width - 1) * 6;
    for (int i = 0; i < width - 1; ++i) {
      const auto a = static_cast<std::uint32_t>(j * width + i), b = a + 1;
      const auto c = a + static_cast<std::uint32_t>(width), d = c + 1;
      *out++ = a, *out++ = c, *out++ = b;
      *out++ = b, *out++ = c, *out++ = d;
    }
  });
  return mesh;
}

void set_uvs_over_grid(TriangleMesh& mesh, const Heightfield& grid) {
  const double span_x = (grid.width() - 1) * grid.cell_size_m, span_z = (grid.height() - 1) * grid.cell_size_m;
  if (!(span_x > 0.0) || !(span_z > 0.0))
    fail("a grid of {} x {} samples has no extent to lay texture coordinates over", grid.width(), grid.height());
  if (mesh.uvs.empty()) reserve_on_huge_pages(mesh.uvs, mesh.positions.size());
  mesh.uvs.resize(mesh.positions.size());
  parallel_for(std::size_t{0}, mesh.positions.size(), [&](std::size_t v) {
    const glm::vec3 p = mesh.positions[v];
    mesh.uvs[v] = {static_cast<float>(std::clamp((p.x - grid.origin_x_m) / span_x, 0.0, 1.0)),
                   static_cast<float>(std::clamp((p.z - grid.origin_y_m) / span_z, 0.0, 1.0))};
  });
}

}  // namespace sansui::mesh
