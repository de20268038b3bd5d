// Dropping nearly collinear points (Misawa, Chiba, Saito 1987, Sec. 4.3): see decimate.hpp.
#include "contour/decimate.hpp"

#include <cmath>
#include <queue>
#include <vector>

namespace sansui::contour {

Ring drop_collinear_points(const Ring& ring, const DecimateParams& params) {
  const int n = static_cast<int>(ring.size());
  if (n <= params.min_vertices) return ring;
  std::vector<int> previous(static_cast<std::size_t>(n)), next(static_cast<std::size_t>(n));
  std::vector<int> version(static_cast<std::size_t>(n), 0);
  std::vector<bool> removed(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    previous[static_cast<std::size_t>(i)] = (i + n - 1) % n;
    next[static_cast<std::size_t>(i)] = (i + 1) % n;
  }
  auto at = [&](int i) { return ring[static_cast<std::size_t>(i)]; };
  // The local threshold of a segment is taken at its first vertex (once per vertex, not per test).
  std::vector<double> threshold(static_cast<std::size_t>(n), params.long_segment_m);
  if (params.scale)
    for (int i = 0; i < n; ++i) threshold[static_cast<std::size_t>(i)] *= params.scale(at(i));
  auto is_long = [&](int a, int b) { return distance(at(a), at(b)) > threshold[static_cast<std::size_t>(a)]; };
  auto area_at = [&](int i) {
    return std::fabs(cross(at(previous[static_cast<std::size_t>(i)]) - at(i), at(next[static_cast<std::size_t>(i)]) - at(i)));
  };
  struct Entry {
    double area;
    int index;
    int version;
    bool operator>(const Entry& o) const { return area != o.area ? area > o.area : index > o.index; }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  int long_segments = 0;
  for (int i = 0; i < n; ++i) {
    heap.push({area_at(i), i, 0});
    long_segments += is_long(i, (i + 1) % n) ? 1 : 0;
  }
  int segments = n;
  while (segments > params.min_vertices && long_segments < params.long_fraction * segments && !heap.empty()) {
    const Entry top = heap.top();
    heap.pop();
    const auto i = static_cast<std::size_t>(top.index);
    if (removed[i] || top.version != version[i]) continue;
    const int a = previous[i], b = next[i];
    long_segments -= (is_long(a, top.index) ? 1 : 0) + (is_long(top.index, b) ? 1 : 0);
    long_segments += is_long(a, b) ? 1 : 0;
    removed[i] = true;
    next[static_cast<std::size_t>(a)] = b;
    previous[static_cast<std::size_t>(b)] = a;
    --segments;
    for (int neighbour : {a, b}) heap.push({area_at(neighbour), neighbour, ++version[static_cast<std::size_t>(neighbour)]});
  }
  Ring out;
  out.reserve(static_cast<std::size_t>(segments));
  for (int i = 0; i < n; ++i)
    if (!removed[static_cast<std::size_t>(i)]) out.push_back(at(i));
  return out;
}

}  // namespace sansui::contour
