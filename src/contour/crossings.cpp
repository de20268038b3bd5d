#include "contour/crossings.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sansui::contour {
namespace {

/// Segments of one or two rings, bucketed by a uniform grid over their common bounds.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<const Ring*>& rings) : rings_(rings) {
    std::size_t total = 0;
    for (const Ring* ring : rings) {
      box_ = merge(box_, bounds(*ring));
      total += ring->size();
    }
    const double side = std::max({box_.width(), box_.height(), 1e-9});
    cells_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(total))), 1, 2048);
    cell_size_ = side / cells_ * (1.0 + 1e-9);
    cell_x_ = std::max(1, static_cast<int>(box_.width() / cell_size_) + 1);
    cell_y_ = std::max(1, static_cast<int>(box_.height() / cell_size_) + 1);
    std::vector<int> counts(static_cast<std::size_t>(cell_x_) * cell_y_ + 1, 0);
    for_each_entry([&](std::size_t cell, int, int) { ++counts[cell + 1]; });
    for (std::size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
    starts_ = counts;
    entries_.resize(static_cast<std::size_t>(counts.back()));
    for_each_entry([&](std::size_t cell, int ring, int segment) { entries_[static_cast<std::size_t>(counts[cell]++)] = {ring, segment}; });
  }

  struct Entry {
    int ring, segment;
  };

  /// Calls visit(entry_a, entry_b) once for every pair whose boxes overlap (in the cell holding
  /// the low corner of the overlap).
  template <class Visit>
  void for_each_pair(Visit visit) const {
    for (int cy = 0; cy < cell_y_; ++cy)
      for (int cx = 0; cx < cell_x_; ++cx) {
        const std::size_t cell = static_cast<std::size_t>(cy) * cell_x_ + cx;
        const int begin = starts_[cell], end = starts_[cell + 1];
        for (int i = begin; i < end; ++i)
          for (int j = i + 1; j < end; ++j) {
            const Entry a = entries_[static_cast<std::size_t>(i)], b = entries_[static_cast<std::size_t>(j)];
            const Box ba = box_of(a), bb = box_of(b);
            const double low_x = std::max(ba.min_x, bb.min_x), low_y = std::max(ba.min_y, bb.min_y);
            if (low_x > std::min(ba.max_x, bb.max_x) || low_y > std::min(ba.max_y, bb.max_y)) continue;
            if (cell_of(low_x, cell_x_, box_.min_x) != cx || cell_of(low_y, cell_y_, box_.min_y) != cy) continue;
            visit(a, b);
          }
      }
  }

  Point start(Entry e) const { return (*rings_[static_cast<std::size_t>(e.ring)])[static_cast<std::size_t>(e.segment)]; }
  Point end(Entry e) const {
    const Ring& ring = *rings_[static_cast<std::size_t>(e.ring)];
    return ring[(static_cast<std::size_t>(e.segment) + 1) % ring.size()];
  }

 private:
  static Box merge(Box a, const Box& b) {
    if (!b.empty()) {
      a.add({b.min_x, b.min_y});
      a.add({b.max_x, b.max_y});
    }
    return a;
  }
  Box box_of(Entry e) const {
    Box box;
    box.add(start(e));
    box.add(end(e));
    return box;
  }
  int cell_of(double v, int count, double origin) const { return std::clamp(static_cast<int>((v - origin) / cell_size_), 0, count - 1); }
  template <class F>
  void for_each_entry(F f) const {
    for (std::size_t r = 0; r < rings_.size(); ++r) {
      const Ring& ring = *rings_[r];
      for (std::size_t s = 0; s < ring.size(); ++s) {
        const Box box = box_of({static_cast<int>(r), static_cast<int>(s)});
        const int x0 = cell_of(box.min_x, cell_x_, box_.min_x), x1 = cell_of(box.max_x, cell_x_, box_.min_x);
        const int y0 = cell_of(box.min_y, cell_y_, box_.min_y), y1 = cell_of(box.max_y, cell_y_, box_.min_y);
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) f(static_cast<std::size_t>(y) * cell_x_ + x, static_cast<int>(r), static_cast<int>(s));
      }
    }
  }

  std::vector<const Ring*> rings_;
  Box box_;
  int cells_ = 1, cell_x_ = 1, cell_y_ = 1;
  double cell_size_ = 1.0;
  std::vector<int> starts_;
  std::vector<Entry> entries_;
};

/// Proper or end-touching crossing of p->p2 with q->q2, half-open at the ends (t, u in [0, 1)).
std::optional<std::pair<double, double>> cross_segments(Point p, Point p2, Point q, Point q2) {
  const Point r = p2 - p, s = q2 - q;
  const double denominator = cross(r, s);
  if (denominator == 0.0) return std::nullopt;
  const Point qp = q - p;
  const double t = cross(qp, s) / denominator, u = cross(qp, r) / denominator;
  if (t < 0.0 || t >= 1.0 || u < 0.0 || u >= 1.0) return std::nullopt;
  return std::pair{t, u};
}

}  // namespace

std::vector<Crossing> self_crossings(const Ring& ring) {
  const int n = static_cast<int>(ring.size());
  std::vector<Crossing> out;
  if (n < 4) return out;
  SegmentGrid grid({&ring});
  grid.for_each_pair([&](SegmentGrid::Entry a, SegmentGrid::Entry b) {
    if (a.segment > b.segment) std::swap(a, b);
    if (b.segment == a.segment + 1 || (a.segment == 0 && b.segment == n - 1)) return;
    const Point p = grid.start(a), q = grid.start(b);
    if (auto hit = cross_segments(p, grid.end(a), q, grid.end(b)))
      out.push_back({a.segment, b.segment, hit->first, hit->second, p + hit->first * (grid.end(a) - p)});
  });
  std::sort(out.begin(), out.end(), [](const Crossing& x, const Crossing& y) {
    return x.segment_a != y.segment_a ? x.segment_a < y.segment_a : x.segment_b != y.segment_b ? x.segment_b < y.segment_b : x.t_a < y.t_a;
  });
  return out;
}

std::vector<Crossing> crossings_between(const Ring& first, const Ring& second) {
  std::vector<Crossing> out;
  if (first.size() < 2 || second.size() < 2) return out;
  SegmentGrid grid({&first, &second});
  grid.for_each_pair([&](SegmentGrid::Entry a, SegmentGrid::Entry b) {
    if (a.ring == b.ring) return;
    if (a.ring > b.ring) std::swap(a, b);
    const Point p = grid.start(a), q = grid.start(b);
    if (auto hit = cross_segments(p, grid.end(a), q, grid.end(b)))
      out.push_back({a.segment, b.segment, hit->first, hit->second, p + hit->first * (grid.end(a) - p)});
  });
  std::sort(out.begin(), out.end(), [](const Crossing& x, const Crossing& y) {
    return x.segment_a != y.segment_a ? x.segment_a < y.segment_a : x.segment_b < y.segment_b;
  });
  return out;
}

}  // namespace sansui::contour
