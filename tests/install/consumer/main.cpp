// A user of the installed library: a small fractal terrain from the public headers. Prints its
// size and height range; exits 1 if the terrain is flat.
#include <algorithm>
#include <cstdio>

#include "terrain/midpoint.hpp"

int main() {
  sansui::terrain::MidpointParams params;
  params.seed = 7;
  const sansui::Heightfield terrain = sansui::terrain::generate_midpoint(params, 33);
  const auto [low, high] = std::minmax_element(terrain.values().begin(), terrain.values().end());
  std::printf("%dx%d, %.1f to %.1f m\n", terrain.width(), terrain.height(), *low, *high);
  return terrain.width() == 33 && *high > *low ? 0 : 1;
}
