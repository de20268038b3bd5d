// Shaded relief for quick looks (see preview.hpp). Horn, "Hill shading and the reflectance
// map", Proc. IEEE 69(1), 1981: slopes from the 3 x 3 neighbourhood, Lambertian light.
#include "mesh/preview.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"

namespace sansui::mesh {
namespace {

struct Colour {
  double r, g, b;
};

/// Low green, through brown and grey rock, to white at the top.
Colour tint(double t) {
  constexpr Colour stops[] = {{0.32, 0.45, 0.25}, {0.55, 0.58, 0.32}, {0.58, 0.47, 0.33}, {0.55, 0.53, 0.50}, {0.95, 0.95, 0.97}};
  const double x = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, int(x));
  const double f = x - i;
  return {stops[i].r + f * (stops[i + 1].r - stops[i].r), stops[i].g + f * (stops[i + 1].g - stops[i].g),
          stops[i].b + f * (stops[i + 1].b - stops[i].b)};
}

}  // namespace

Image shaded_relief(const Heightfield& h, double exaggeration) {
  Image image = Image::uninitialized(h.width(), h.height());
  if (h.empty()) return image;
  const auto range = std::ranges::minmax(h.values());
  const float low = range.min, high = range.max;  // plain names: lambdas below use them
  const double span = high > low ? double(high) - low : 1.0;
  // Light from azimuth 315 (north-west), 45 degrees up; x east, y south, z up.
  const double lx = -0.5, ly = -0.5, lz = std::sqrt(0.5);
  const double scale = exaggeration / (8.0 * h.cell_size_m);
  parallel_for(0, h.height(), [&](int y) {
    auto at = [&](int x, int yy) { return double(h(std::clamp(x, 0, h.width() - 1), std::clamp(yy, 0, h.height() - 1))); };
    for (int x = 0; x < h.width(); ++x) {
      const double dzdx =
          ((at(x + 1, y - 1) + 2 * at(x + 1, y) + at(x + 1, y + 1)) - (at(x - 1, y - 1) + 2 * at(x - 1, y) + at(x - 1, y + 1))) * scale;
      const double dzdy =
          ((at(x - 1, y + 1) + 2 * at(x, y + 1) + at(x + 1, y + 1)) - (at(x - 1, y - 1) + 2 * at(x, y - 1) + at(x + 1, y - 1))) * scale;
      const double light = std::max(0.0, (-dzdx * lx - dzdy * ly + lz) / std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0));
      const Colour c = tint((at(x, y) - low) / span);
      const double shade = 0.3 + 0.85 * light;
      auto byte = [&](double v) { return std::uint8_t(std::clamp(v * shade * 255.0, 0.0, 255.0)); };
      image(x, y) = {byte(c.r), byte(c.g), byte(c.b), 255};
    }
  });
  return image;
}

}  // namespace sansui::mesh
