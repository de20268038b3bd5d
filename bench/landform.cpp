// Prints the landform measures of heightmaps (water/landform.hpp), one line each:
//   build/bench/landform [--sea M] FILE...
// What the closing notes and docs/erosion.md quote: channel/hillslope slope ratio, spectral
// exponent, relief, mean slope, land fraction, and whether the edges look like the land inside
// (edge_slope_distance). A plain program, not a benchmark.
#include "water/landform.hpp"

#include <cstdio>
#include <optional>
#include <string>

#include "io/heightmap_io.hpp"

int main(int argc, char** argv) {
  std::optional<double> sea;
  std::printf("%-40s %6s %8s %7s %7s %6s %9s %8s %6s\n", "file", "land", "relief", "slope", "ratio", "beta", "curv", "pits", "edge");
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--sea" && i + 1 < argc) {
      sea = std::stod(argv[++i]);
      continue;
    }
    try {
      const sansui::Heightfield h = sansui::io::read_heightmap(arg);
      const auto m = sansui::water::measure_landform(h, sea);
      std::printf("%-40s %6.3f %8.1f %7.3f %7.3f %6.2f %9.4f %8lld %6.2f\n", arg.c_str(), m.land_fraction, m.relief_m, m.mean_slope,
                  m.channel_ratio, m.spectral_beta, m.curvature_spread, m.pits, m.edge_distance);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", arg.c_str(), e.what());
      return 2;
    }
  }
  return 0;
}
