// One stage over a window, fused row by row (see midpoint_refine.hpp).
//
// Level-l sample (x, y), with P the parent values and W = 2^l the world's last index:
//   x, y even  old point   (P + square addition) + diamond addition
//   x, y odd   centre      mean4 of its four parent corners + square noise, + diamond addition
//   otherwise  edge point  mean4 of its west, east, north, south neighbours (old points after
//                          the square additions, centres before the diamond additions) + diamond
//                          noise; mean3 of the three there are on the world's border
// The rows of old points after the square additions ("P'") and of centres before the diamond
// additions ("C") are computed once each, on the columns the target needs, into a ring of four
// row buffers: output row y reads rows y-1, y and y+1.
#include "terrain/midpoint_refine.hpp"

#include <algorithm>
#include <array>
#include <cassert>

#include "core/gaussian_row.hpp"
#include "terrain/midpoint_rules.hpp"

namespace sansui::terrain::detail {

const float* fill_gaussians(std::uint64_t key, int x_first, int x_step, int y, int count, float scale, float* buffer) {
  if (count <= 0) return buffer;
  if (x_step != 2) {  // every 2^k-th point, k > 1 (later stages' additions at a coarser level): one lane each
    for (int t = 0; t < count; ++t) buffer[t] = scale * rules::gaussian(key, x_first + t * x_step, y);
    return buffer;
  }
  // Neighbouring points share a pair: whole pairs from the one holding the first point.
  const int q = x_first >> 1;
  const int pairs = ((q & 1) + count + 1) / 2;
  rng::gaussian_pair_row(key + rng::pack(q >> 1, y) * rng::golden_gamma, rng::golden_gamma, pairs, scale, buffer);
  return buffer + (q & 1);
}

Rect parent_rect(Rect target, int level) {
  const int last = 1 << (level - 1);  // last index at level l-1
  auto floor_half = [](int v) { return v >= 0 ? v / 2 : -((1 - v) / 2); };
  auto ceil_half = [&](int v) { return -floor_half(-v); };
  return {std::max(0, ceil_half(target.x0 - 2)), std::max(0, ceil_half(target.y0 - 2)), std::min(last, floor_half(target.x1 + 1)) + 1,
          std::min(last, floor_half(target.y1 + 1)) + 1};
}

namespace {

using rules::mean3;
using rules::mean4;

/// out[2t] = a[t], out[2t + 1] = b[t]: a vectorised interleave.
void interleave_pairs(const float* __restrict a, const float* __restrict b, int count, float* __restrict out) {
  for (int t = 0; t < count; ++t) {
    out[2 * t] = a[t];
    out[2 * t + 1] = b[t];
  }
}

/// out[2t + first] = a[t], out[2t + 1 - first] = b[t]: the two kinds of sample of a row, merged.
void interleave(const float* a, int count_a, const float* b, int count_b, int first, float* out) {
  const int both = std::min(count_a, count_b);
  if (first == 0)
    interleave_pairs(a, b, both, out);
  else
    interleave_pairs(b, a, both, out);
  if (count_a > both) out[2 * both + first] = a[both];
  if (count_b > both) out[2 * both + 1 - first] = b[both];
}

/// The samples of one kind in [x0, x1) of a row: the first at x0 or x0 + 1 (by parity), then
/// every second one.
struct Run {
  int first = 0;  ///< x of the first sample
  int count = 0;
};
Run run_of_parity(int x0, int x1, int parity) {
  const int first = x0 + ((x0 & 1) != parity ? 1 : 0);
  return {first, first < x1 ? (x1 - first + 1) / 2 : 0};
}

class WindowRefiner {
 public:
  WindowRefiner(const LevelView& parent, int level, Rect target, const StageNoise& stage, RefineScratch& scratch)
      : parent_(parent), target_(target), stage_(stage), scratch_(scratch), last_(1 << level) {
    // Columns the target's rows read: P' at even x and C at odd x in [low, high].
    const int low = std::max(target.x0 - 1, 0), high = std::min(target.x1, last_);
    i0_ = (low + 1) / 2;
    points_ = high / 2 - i0_ + 1;
    k0_ = low / 2;
    centres_ = (high - 1) / 2 - k0_ + 1;
    row_size_ = std::max(points_, centres_) + 1;
    scratch.rows.resize(4 * static_cast<std::size_t>(row_size_));
    const std::size_t width = static_cast<std::size_t>(target.width()) + 2;
    scratch.noise.resize(width + static_cast<std::size_t>(noise_slack));
    scratch.even.resize(width);
    scratch.odd.resize(width);
    assert(parent.level == level - 1 && parent.rect.contains(parent_rect(target, level)));
  }

  void run(GridView<float> out) {
    for (int y = target_.y0; y < target_.y1; ++y) {
      float* row = &out(0, y - target_.y0);
      if (y % 2 == 0)
        old_point_row(y, row);
      else
        centre_row(y, row);
    }
  }

 private:
  /// Parent row j from column `x` (parent indices) on.
  const float* parent_row(int j, int x) const { return &parent_.values(x - parent_.rect.x0, j - parent_.rect.y0); }

  /// P' (y even) or C (y odd) at row y, from the ring; computed on first use.
  const float* intermediate(int y) {
    const auto slot = static_cast<std::size_t>(y & 3);
    float* values = scratch_.rows.data() + slot * static_cast<std::size_t>(row_size_);
    if (ring_[slot] == y) return values;
    ring_[slot] = y;
    float* buffer = scratch_.noise.data();
    if (y % 2 == 0) {  // P'(2i, y) at values[i - i0]
      const float* p = parent_row(y / 2, i0_);
      if (stage_.additions) {
        const float* noise = fill_gaussians(stage_.square_add, 2 * i0_, 2, y, points_, stage_.square_scale, buffer);
        for (int t = 0; t < points_; ++t) values[t] = p[t] + noise[t];
      } else {
        std::copy_n(p, points_, values);
      }
    } else {  // C(2k + 1, y) at values[k - k0], from the corners (k, k + 1) of parent rows j, j + 1
      const float* north = parent_row((y - 1) / 2, k0_);
      const float* south = parent_row((y + 1) / 2, k0_);
      const float* noise = fill_gaussians(stage_.square_create, 2 * k0_ + 1, 2, y, centres_, stage_.square_scale, buffer);
      for (int t = 0; t < centres_; ++t) values[t] = mean4(north[t], north[t + 1], south[t], south[t + 1]) + noise[t];
    }
    return values;
  }

  /// Points that keep their value through the diamond half-step (old points on even rows,
  /// centres on odd ones): dst[t] = src[t], plus the half-step's additions at (first + 2t, y)
  /// when they are on.
  void carry_over(const float* src, int first, int count, int y, float* dst) {
    if (!stage_.additions) {
      std::copy_n(src, count, dst);
      return;
    }
    const float* noise = fill_gaussians(stage_.diamond_add, first, 2, y, count, stage_.diamond_scale, scratch_.noise.data());
    for (int t = 0; t < count; ++t) dst[t] = src[t] + noise[t];
  }

  /// Row y even: old points at even x, edge points at odd x between them.
  void old_point_row(int y, float* out) {
    const float* points = intermediate(y);                       // P'(x) at x / 2 - i0
    const float* north = y > 0 ? intermediate(y - 1) : nullptr;  // C(x) at (x - 1) / 2 - k0
    const float* south = y < last_ ? intermediate(y + 1) : nullptr;
    const Run olds = run_of_parity(target_.x0, target_.x1, 0), edges = run_of_parity(target_.x0, target_.x1, 1);
    float* even = scratch_.even.data();
    float* odd = scratch_.odd.data();
    float* buffer = scratch_.noise.data();

    carry_over(points + (olds.first / 2 - i0_), olds.first, olds.count, y, even);

    const float* noise = fill_gaussians(stage_.diamond_create, edges.first, 2, y, edges.count, stage_.diamond_scale, buffer);
    const float* west = points + ((edges.first - 1) / 2 - i0_);  // west[t + 1] is the east neighbour
    const int c = (edges.first - 1) / 2 - k0_;
    if (north != nullptr && south != nullptr) {
      const float* n = north + c;
      const float* s = south + c;
      for (int t = 0; t < edges.count; ++t) odd[t] = mean4(west[t], west[t + 1], n[t], s[t]) + noise[t];
    } else {  // the world's north or south edge: three neighbours
      const float* other = (north != nullptr ? north : south) + c;
      for (int t = 0; t < edges.count; ++t) odd[t] = mean3(west[t], west[t + 1], other[t]) + noise[t];
    }
    interleave(even, olds.count, odd, edges.count, olds.first - target_.x0, out);
  }

  /// Row y odd: centres at odd x, edge points at even x between them.
  void centre_row(int y, float* out) {
    const float* centres = intermediate(y);    // C(x) at (x - 1) / 2 - k0
    const float* north = intermediate(y - 1);  // P'(x) at x / 2 - i0
    const float* south = intermediate(y + 1);
    const Run mids = run_of_parity(target_.x0, target_.x1, 1), edges = run_of_parity(target_.x0, target_.x1, 0);
    float* even = scratch_.even.data();
    float* odd = scratch_.odd.data();
    float* buffer = scratch_.noise.data();

    carry_over(centres + ((mids.first - 1) / 2 - k0_), mids.first, mids.count, y, odd);

    const float* noise = fill_gaussians(stage_.diamond_create, edges.first, 2, y, edges.count, stage_.diamond_scale, buffer);
    // Edges on the world's west and east border have three neighbours; the others four.
    int begin = 0, end = edges.count;
    if (edges.count > 0 && edges.first == 0) {  // then i0 = k0 = 0
      even[0] = mean3(north[0], south[0], centres[0]) + noise[0];
      begin = 1;
    }
    if (edges.count > begin && edges.first + 2 * (edges.count - 1) == last_) {
      const int x = last_;
      even[edges.count - 1] = mean3(north[x / 2 - i0_], south[x / 2 - i0_], centres[(x - 2) / 2 - k0_]) + noise[edges.count - 1];
      end = edges.count - 1;
    }
    const int first_x = edges.first + 2 * begin;
    const float* west = centres + ((first_x - 2) / 2 - k0_);  // west[t + 1] is the east neighbour
    const float* n = north + (first_x / 2 - i0_);
    const float* s = south + (first_x / 2 - i0_);
    for (int t = begin; t < end; ++t) {
      const int u = t - begin;
      even[t] = mean4(west[u], west[u + 1], n[u], s[u]) + noise[t];
    }
    interleave(even, edges.count, odd, mids.count, edges.first - target_.x0, out);
  }

  const LevelView& parent_;
  Rect target_;
  const StageNoise& stage_;
  RefineScratch& scratch_;
  int last_;
  int i0_ = 0, points_ = 0;   // P' columns: x = 2 i, i0 <= i < i0 + points
  int k0_ = 0, centres_ = 0;  // C columns: x = 2 k + 1, k0 <= k < k0 + centres
  int row_size_ = 0;
  std::array<int, 4> ring_{-1, -1, -1, -1};  // the row each slot holds
};

}  // namespace

void refine_window(const LevelView& parent, int level, Rect target, const StageNoise& stage, RefineScratch& scratch, GridView<float> out) {
  assert(out.width == target.width() && out.height == target.height());
  WindowRefiner(parent, level, target, stage, scratch).run(out);
}

}  // namespace sansui::terrain::detail
