// The scale of a seed contour: see scale.hpp.
#include "contour/scale.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace sansui::contour {

double inradius(const Ring& ring) {
  if (ring.size() < 3) return 0.0;
  const Box box = bounds(ring);
  constexpr int cells = 96;  // along the longer side
  const double step = std::max(box.width(), box.height()) / cells;
  if (!(step > 0.0)) return 0.0;
  double best = 0.0;
  Point centre{0.5 * (box.min_x + box.max_x), 0.5 * (box.min_y + box.max_y)};
  for (double y = box.min_y + 0.5 * step; y < box.max_y; y += step)
    for (double x = box.min_x + 0.5 * step; x < box.max_x; x += step) {
      const Point p{x, y};
      if (!contains(ring, p)) continue;
      const double r = distance_to_ring(ring, p);
      if (r > best) best = r, centre = p;
    }
  // Refine around the best cell: a local pattern search down to 1/64 of a cell.
  for (double h = 0.5 * step; h > step / 64.0; h *= 0.5) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (const Point dir :
           {Point{h, 0}, Point{-h, 0}, Point{0, h}, Point{0, -h}, Point{h, h}, Point{-h, h}, Point{h, -h}, Point{-h, -h}}) {
        const Point p{centre.x + dir.x, centre.y + dir.y};
        if (!contains(ring, p)) continue;
        const double r = distance_to_ring(ring, p);
        if (r > best) best = r, centre = p, moved = true;
      }
    }
  }
  return best;
}

double target_relief_m(double inradius_m) {
  return std::min(5000.0, 150.0 * std::pow(std::max(inradius_m, 1e-3) / 500.0, 0.65));
}

double derived_offset_m(const Ring& seed, double interval_m) {
  const double r = inradius(seed);
  if (!(r > 0.0)) return 10.0;
  return r * interval_m / target_relief_m(r);
}

WorkEstimate estimate_work(const Ring& seed, const GenerationParams& params) {
  WorkEstimate e;
  const double r = inradius(seed);
  // Inward: levels until the offsets add up to the inradius (the schedule's last d repeats).
  double reached = 0.0;
  int level = 0;
  const int scheduled = static_cast<int>(params.offset_schedule_m.size());
  while (reached < r && level < scheduled) reached += params.offset_for_level(++level);
  double inward = level;
  if (reached < r) inward += (r - reached) / params.offset_for_level(level + 1);
  e.inward_levels = inward;  // not capped by max_levels: the estimate says what was asked
  e.outward_levels = params.resolved_outward_levels();
  e.levels = e.inward_levels + e.outward_levels;
  // Vertices of one contour: the seed's; the Fourier step resamples to n and the revised method
  // thins that again by about half.
  e.vertices = static_cast<double>(seed.size());
  if (params.method == Method::fourier) e.vertices = std::max(e.vertices, static_cast<double>(params.samples));
  if (params.method == Method::revised) e.vertices = std::max(e.vertices, 0.5 * params.samples);
  // Measured (bench_contour): about 2 microseconds per vertex and level, contours shrinking on
  // the way up; outward contours grow and cost about twice.
  e.seconds = 2e-6 * e.vertices * (e.inward_levels + 2.0 * e.outward_levels);
  return e;
}

void check_work(const WorkEstimate& estimate, const GenerationParams& params) {
  // Even with force: every level's contour is kept (16 bytes a vertex, and as much again while
  // it is clipped), so a runaway level count is refused before the first level, not by the OOM
  // killer.
  check_memory(32.0 * estimate.vertices * estimate.levels, fmt::format("contour.offset {:.6g} m (about {:.0f} levels of {:.0f} vertices)",
                                                                       params.resolved_offset_m(), estimate.levels, estimate.vertices));
  if (params.force) return;
  if (estimate.levels <= level_limit && estimate.seconds <= seconds_limit) return;
  fail(
      "contour.offset {:.6g} m would make about {:.0f} levels ({:.0f} m of relief at dz = {:.6g} m) and take about {:.0f} s, over the "
      "limit of {:.0f} levels or {:.0f} s: give a larger offset or interval, or pass force (--force) to run it",
      params.resolved_offset_m(), estimate.levels, estimate.inward_levels * params.interval_m, params.interval_m, estimate.seconds,
      level_limit, seconds_limit);
}

}  // namespace sansui::contour
