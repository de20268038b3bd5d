#include "bench/reference_midpoint.hpp"

#include "core/random.hpp"
#include "terrain/midpoint_rules.hpp"

namespace sansui::reference {

using terrain::rules::HalfStep;
using terrain::rules::Operation;

Heightfield midpoint_displacement(const terrain::MidpointParams& params, int size) {
  const int levels = terrain::levels_for_size(size);
  const int n = size - 1;
  const auto scales = terrain::rules::displacement_scales(params.sigma(), params.hurst, levels);
  auto key = [&](int stage, HalfStep half, Operation op) { return rng::stream_key(params.seed, terrain::rules::stream(stage, half, op)); };
  // Random numbers are indexed by the point's position in units of this stage's spacing.
  auto gauss = [](std::uint64_t k, int x, int y, int spacing) { return terrain::rules::gaussian(k, x / spacing, y / spacing); };

  Heightfield h(size, size);
  const std::uint64_t corner_key = rng::stream_key(params.seed, 0);
  for (int y : {0, n})
    for (int x : {0, n}) h(x, y) = scales[0] * terrain::rules::corner_gaussian(corner_key, x / n, y / n);

  int big = n, d = n / 2;  // spacing of the old points, and of the new ones
  for (int stage = 1; stage <= levels; ++stage, big /= 2, d /= 2) {
    float delta = terrain::rules::scale_of(scales, stage, HalfStep::square);
    std::uint64_t create = key(stage, HalfStep::square, Operation::create);
    for (int y = d; y < n; y += big)
      for (int x = d; x < n; x += big)
        h(x, y) =
            terrain::rules::mean4(h(x - d, y - d), h(x + d, y - d), h(x - d, y + d), h(x + d, y + d)) + delta * gauss(create, x, y, d);
    if (params.additions) {
      const std::uint64_t add = key(stage, HalfStep::square, Operation::add);
      for (int y = 0; y <= n; y += big)
        for (int x = 0; x <= n; x += big) h(x, y) += delta * gauss(add, x, y, d);
    }

    delta = terrain::rules::scale_of(scales, stage, HalfStep::diamond);
    create = key(stage, HalfStep::diamond, Operation::create);
    for (int y = 0; y <= n; y += d) {
      const int first = (y % big == 0) ? d : 0;  // rows of old points: odd columns; others: even
      for (int x = first; x <= n; x += big) {
        float mean;
        if (y == 0)
          mean = terrain::rules::mean3(h(x - d, y), h(x + d, y), h(x, y + d));
        else if (y == n)
          mean = terrain::rules::mean3(h(x - d, y), h(x + d, y), h(x, y - d));
        else if (x == 0)
          mean = terrain::rules::mean3(h(x, y - d), h(x, y + d), h(x + d, y));
        else if (x == n)
          mean = terrain::rules::mean3(h(x, y - d), h(x, y + d), h(x - d, y));
        else
          mean = terrain::rules::mean4(h(x - d, y), h(x + d, y), h(x, y - d), h(x, y + d));
        h(x, y) = mean + delta * gauss(create, x, y, d);
      }
    }
    if (params.additions) {
      const std::uint64_t add = key(stage, HalfStep::diamond, Operation::add);
      for (int y = 0; y <= n; y += big)
        for (int x = 0; x <= n; x += big) h(x, y) += delta * gauss(add, x, y, d);
      for (int y = d; y < n; y += big)
        for (int x = d; x < n; x += big) h(x, y) += delta * gauss(add, x, y, d);
    }
  }
  return h;
}

}  // namespace sansui::reference
