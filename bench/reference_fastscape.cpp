// The benchmark's in-tree reference for one landscape-evolution step: FastScape as Braun & Willett
// (Geomorphology 180, 2013) print it, serial and plain. D8 receivers (pits drain nowhere: no
// depression routing), donor lists, the stack built depth first from the base levels, drainage
// area upstream first, implicit incision (n = 1) downstream first. No deposition, no diffusion, no
// threads: what one careful page of code does, so that Sansui's step is measured against it.
#include "reference_fastscape.hpp"

#include <cmath>
#include <vector>

namespace sansui::reference {

void fastscape_step(std::vector<float>& z, int width, int height, double cell_m, double k_dt, double m, double sea_level) {
  const std::size_t n = z.size();
  const int dx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, dy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  const double length[8] = {1, std::sqrt(2.0), 1, std::sqrt(2.0), 1, std::sqrt(2.0), 1, std::sqrt(2.0)};
  std::vector<int> receiver(n);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int i = y * width + x;
      receiver[static_cast<std::size_t>(i)] = i;
      if (x == 0 || y == 0 || x == width - 1 || y == height - 1 || z[static_cast<std::size_t>(i)] <= sea_level) continue;
      double steepest = 0.0;
      for (int k = 0; k < 8; ++k) {
        const int j = (y + dy[k]) * width + x + dx[k];
        const double slope = (z[static_cast<std::size_t>(i)] - z[static_cast<std::size_t>(j)]) / length[k];
        if (slope > steepest) steepest = slope, receiver[static_cast<std::size_t>(i)] = j;
      }
    }
  std::vector<int> donor_count(n + 1, 0), donors(n);
  for (std::size_t i = 0; i < n; ++i)
    if (receiver[i] != static_cast<int>(i)) ++donor_count[static_cast<std::size_t>(receiver[i]) + 1];
  for (std::size_t i = 0; i < n; ++i) donor_count[i + 1] += donor_count[i];
  std::vector<int> fill(donor_count.begin(), donor_count.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    if (receiver[i] != static_cast<int>(i))
      donors[static_cast<std::size_t>(fill[static_cast<std::size_t>(receiver[i])]++)] = static_cast<int>(i);
  std::vector<int> stack, todo;
  stack.reserve(n);
  for (std::size_t root = 0; root < n; ++root) {
    if (receiver[root] != static_cast<int>(root)) continue;
    todo.push_back(static_cast<int>(root));
    while (!todo.empty()) {
      const int c = todo.back();
      todo.pop_back();
      stack.push_back(c);
      for (int d = donor_count[static_cast<std::size_t>(c)]; d < donor_count[static_cast<std::size_t>(c) + 1]; ++d)
        todo.push_back(donors[static_cast<std::size_t>(d)]);
    }
  }
  std::vector<double> area(n, cell_m * cell_m);
  for (std::size_t k = n; k-- > 0;) {
    const auto i = static_cast<std::size_t>(stack[k]);
    if (receiver[i] != static_cast<int>(i)) area[static_cast<std::size_t>(receiver[i])] += area[i];
  }
  for (const int c : stack) {
    const auto i = static_cast<std::size_t>(c);
    const auto r = static_cast<std::size_t>(receiver[i]);
    if (r == i) continue;
    const bool diagonal =
        (static_cast<int>(i) % width != static_cast<int>(r) % width) && (static_cast<int>(i) / width != static_cast<int>(r) / width);
    const double f = k_dt * std::pow(area[i], m) / (cell_m * (diagonal ? std::sqrt(2.0) : 1.0));
    z[i] = static_cast<float>((z[i] + f * z[r]) / (1.0 + f));
  }
}

}  // namespace sansui::reference
