#include "solid/sphere_surface.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>

namespace sansui::solid {
namespace {

/// Largest w >= 0 with w^2 <= v, or -1 if v < 0 (exact, whatever sqrt rounds to).
std::int64_t isqrt_or_minus_one(std::int64_t v) {
  if (v < 0) return -1;
  auto w = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (w * w > v) --w;
  while ((w + 1) * (w + 1) <= v) ++w;
  return w;
}

/// x, y, z bits interleaved: bit b of x goes to bit 3b, of y to 3b+1, of z to 3b+2.
std::uint64_t morton_key(const SurfaceVoxel& v) {
  std::uint64_t key = 0;
  for (int b = 0; b < 21; ++b) {
    key |= static_cast<std::uint64_t>((v.x >> b) & 1) << (3 * b);
    key |= static_cast<std::uint64_t>((v.y >> b) & 1) << (3 * b + 1);
    key |= static_cast<std::uint64_t>((v.z >> b) & 1) << (3 * b + 2);
  }
  return key;
}

}  // namespace

void sort_along_octree(std::vector<SurfaceVoxel>& voxels) {
  std::vector<std::pair<std::uint64_t, SurfaceVoxel>> keyed(voxels.size());
  for (std::size_t i = 0; i < voxels.size(); ++i) keyed[i] = {morton_key(voxels[i]), voxels[i]};
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < voxels.size(); ++i) voxels[i] = keyed[i].second;
}

std::vector<SurfaceVoxel> digital_sphere_surface(int levels) {
  assert(levels >= 1 && levels <= 20);
  const std::int64_t r = std::int64_t{1} << (levels - 1), last = 2 * r;
  // Half-width of the inside part of row (y, z): |x - r| <= half_width; -1 if the row is empty.
  auto half_width = [&](std::int64_t y, std::int64_t z) -> std::int64_t {
    if (y < 0 || y > last || z < 0 || z > last) return -1;
    return isqrt_or_minus_one(r * r - (y - r) * (y - r) - (z - r) * (z - r));
  };
  std::vector<SurfaceVoxel> voxels;
  voxels.reserve(static_cast<std::size_t>(13.0 * static_cast<double>(r * r)));
  for (std::int64_t z = 0; z <= last; ++z)
    for (std::int64_t y = 0; y <= last; ++y) {
      const std::int64_t w = half_width(y, z);
      if (w < 0) continue;
      // Inside points with a neighbour row that does not reach them are on the surface, and so
      // are the two ends of the row.
      const std::int64_t inner = std::min({half_width(y - 1, z), half_width(y + 1, z), half_width(y, z - 1), half_width(y, z + 1), w - 1});
      for (std::int64_t x = r - w; x <= r + w; ++x)
        if (std::abs(x - r) > inner) voxels.push_back({static_cast<int>(x), static_cast<int>(y), static_cast<int>(z)});
    }
  return voxels;
}

}  // namespace sansui::solid
