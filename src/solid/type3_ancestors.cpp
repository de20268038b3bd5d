// Types III and IV: a lattice point from its ancestors (see type3_ancestors.hpp).
#include "solid/type3_ancestors.hpp"

#include <algorithm>
#include <cassert>
#include <climits>
#include <utility>
#include <vector>

#include "solid/node_rules.hpp"

namespace sansui::solid {
namespace {

constexpr int nowhere = INT_MIN / 4;  // origin of a level that holds no cube yet

/// A new node of a cube: its slot and its parents' slots, in pairs along the active axes x, y, z.
struct NewNode {
  int slot = 0;
  int count = 0;
  std::array<int, 6> parents{};
};

/// The 19 new nodes of a cube in an order where parents come first: 12 edge midpoints, 6 face
/// centres, the centre (the paper's steps (1), (2), (3)).
constexpr std::array<NewNode, 19> make_new_nodes() {
  std::array<NewNode, 19> nodes{};
  int n = 0;
  for (int active = 1; active <= 3; ++active)
    for (int slot = 0; slot < 27; ++slot) {
      const int index[3] = {slot % 3, (slot / 3) % 3, slot / 9};
      const int stride[3] = {1, 3, 9};
      int count = 0;
      for (int a = 0; a < 3; ++a) count += index[a] == 1 ? 1 : 0;
      if (count != active) continue;
      NewNode node;
      node.slot = slot;
      for (int a = 0; a < 3; ++a)
        if (index[a] == 1) {
          node.parents[static_cast<std::size_t>(node.count++)] = slot - stride[a];
          node.parents[static_cast<std::size_t>(node.count++)] = slot + stride[a];
        }
      nodes[static_cast<std::size_t>(n++)] = node;
    }
  return nodes;
}
constexpr std::array<NewNode, 19> new_nodes = make_new_nodes();

/// Lanes of the Gaussian batch: 19 nodes padded to two 16-float vectors.
constexpr int lanes = 32;

/// Per lane, the packed (i, j, k) of the node in half-steps: pack(i*h, j*h, k*h) = this << log2 h,
/// since packing is linear when no field overflows.
constexpr std::array<std::uint64_t, lanes> make_lane_offsets() {
  std::array<std::uint64_t, lanes> offsets{};
  for (std::size_t n = 0; n < new_nodes.size(); ++n) {
    const int slot = new_nodes[n].slot;
    offsets[n] = rng::pack(slot % 3, (slot / 3) % 3, slot / 9);
  }
  return offsets;
}
constexpr std::array<std::uint64_t, lanes> lane_offsets = make_lane_offsets();

/// g for every lane: rules::gaussian of the counters base + offset << shift, in one loop that
/// vectorises. `base_bits` is key + base * golden_gamma.
void gaussian_batch(std::uint64_t base_bits, int shift, float* __restrict g) {
  for (int lane = 0; lane < lanes; ++lane)
    g[lane] = rng::to_gaussian(rng::mix64(base_bits + (lane_offsets[static_cast<std::size_t>(lane)] << shift) * rng::golden_gamma));
}

/// One new node from its parents, with the node's slot and parents known at compile time.
template <std::size_t N>
inline void combine_one(float* v, const float* g, float scale) {
  constexpr NewNode node = new_nodes[N];
  constexpr auto q = node.parents;
  float mean;
  if constexpr (node.count == 2)
    mean = rules::mean2(v[q[0]], v[q[1]]);
  else if constexpr (node.count == 4)
    mean = rules::mean4(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  else
    mean = rules::mean6(v[q[0]], v[q[1]], v[q[2]], v[q[3]], v[q[4]], v[q[5]]);
  v[node.slot] = rules::displace(mean, g[N], scale);
}

/// All 19 new nodes in order, unrolled.
template <std::size_t... N>
inline void combine(float* v, const float* g, float scale, std::index_sequence<N...>) {
  (combine_one<N>(v, g, scale), ...);
}

}  // namespace

std::shared_ptr<const Volume> corner_volume(const FieldParams& params) {
  auto corners = std::make_shared<Volume>(0);
  for (int i = 0; i < 8; ++i) (*corners)(i & 1, (i >> 1) & 1, (i >> 2) & 1) = params.corners[static_cast<std::size_t>(i)];
  return corners;
}

AncestorEvaluator::AncestorEvaluator(const FieldParams& params, std::shared_ptr<const Volume> upper, bool reuse)
    : FieldEvaluator(params),
      upper_(std::move(upper)),
      levels_(params.levels),
      r2_(upper_->levels()),
      reuse_(reuse),
      deepest_(r2_),
      key_(rng::stream_key(params.seed, rules::stream)) {
  assert(r2_ >= 0 && r2_ <= levels_ && levels_ <= max_levels);
  const std::vector<float> scales = displacement_scales(params);
  std::copy(scales.begin(), scales.end(), scales_.begin());
  for (LevelMemo& memo : memo_) memo.origin = {nowhere, nowhere, nowhere};
}

std::unique_ptr<FieldEvaluator> AncestorEvaluator::clone() const {
  return std::make_unique<AncestorEvaluator>(params(), upper_, reuse_);
}

std::size_t AncestorEvaluator::memo_bytes() const {
  return static_cast<std::size_t>(levels_ - r2_) * sizeof(LevelMemo);
}

std::size_t AncestorEvaluator::memory_bytes() const {
  return memo_bytes() + upper_->bytes();
}

int AncestorEvaluator::memo_nodes() const {
  return nodes_per_level * (deepest_ - r2_);
}

/// Makes memo_[l], for l = R2+1..level, hold a cube of level l that contains (x, y, z) and lies
/// inside the cube of level l-1: kept from the previous query when it still qualifies, else
/// computed.
void AncestorEvaluator::walk_to(int x, int y, int z, int level) {
  const std::array<int, 3> p{x, y, z};
  const int last = 1 << levels_;
  bool parent_kept = true;
  for (int l = r2_ + 1; l <= level; ++l) {
    LevelMemo& memo = memo_[static_cast<std::size_t>(l)];
    const int side = 1 << (levels_ - l + 1);
    const LevelMemo* parent = l > r2_ + 1 ? &memo_[static_cast<std::size_t>(l - 1)] : nullptr;
    bool keep = reuse_ && l <= deepest_;
    for (std::size_t a = 0; a < 3 && keep; ++a) {
      const int o = memo.origin[a];
      keep = p[a] >= o && p[a] <= o + side;
      if (keep && !parent_kept) keep = o >= parent->origin[a] && o <= parent->origin[a] + side;
    }
    if (keep) continue;
    for (std::size_t a = 0; a < 3; ++a) {
      if (parent == nullptr) {
        memo.origin[a] = std::min(p[a] & ~(side - 1), last - side);
      } else {  // the octant of the parent's cube that holds the point
        const int po = parent->origin[a];
        memo.origin[a] = po + (p[a] - po >= side ? side : 0);
      }
    }
    compute_cube(l);
    parent_kept = false;
  }
  if (!parent_kept || level > deepest_) deepest_ = level;  // deeper levels may no longer nest
}

/// The 27 nodes of level l's cube: corners from the level above, then the 19 new nodes.
void AncestorEvaluator::compute_cube(int level) {
  LevelMemo& memo = memo_[static_cast<std::size_t>(level)];
  auto& v = memo.values;
  const int half_shift = levels_ - level;
  if (level == r2_ + 1) {
    const int shift = levels_ - r2_;
    for (int k = 0; k <= 2; k += 2)
      for (int j = 0; j <= 2; j += 2)
        for (int i = 0; i <= 2; i += 2)
          v[static_cast<std::size_t>(i + 3 * j + 9 * k)] =
              (*upper_)((memo.origin[0] + (i << half_shift)) >> shift, (memo.origin[1] + (j << half_shift)) >> shift,
                        (memo.origin[2] + (k << half_shift)) >> shift);
  } else {
    const LevelMemo& parent = memo_[static_cast<std::size_t>(level - 1)];
    const int up = half_shift + 1;
    const int ox = (memo.origin[0] - parent.origin[0]) >> up, oy = (memo.origin[1] - parent.origin[1]) >> up,
              oz = (memo.origin[2] - parent.origin[2]) >> up;  // octant, 0 or 1 per axis
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i)
          v[static_cast<std::size_t>(2 * i + 6 * j + 18 * k)] =
              parent.values[static_cast<std::size_t>((ox + i) + 3 * (oy + j) + 9 * (oz + k))];
  }

  alignas(64) float g[lanes];
  const int shift = rules::world_shift(levels_);
  const std::uint64_t base = rules::counter(memo.origin[0], memo.origin[1], memo.origin[2], levels_);
  gaussian_batch(key_ + base * rng::golden_gamma, half_shift + shift, g);
  combine(v.data(), g, scales_[static_cast<std::size_t>(level)], std::make_index_sequence<new_nodes.size()>{});
  ++cubes_computed_;
}

float AncestorEvaluator::at(int x, int y, int z) {
  assert(x >= 0 && y >= 0 && z >= 0 && x <= last() && y <= last() && z <= last());
  const int level = std::max({rules::axis_level(x, levels_), rules::axis_level(y, levels_), rules::axis_level(z, levels_)});
  if (level <= r2_) {
    const int shift = levels_ - r2_;
    return (*upper_)(x >> shift, y >> shift, z >> shift);
  }
  walk_to(x, y, z, level);
  const LevelMemo& memo = memo_[static_cast<std::size_t>(level)];
  const int half = levels_ - level;
  const int i = (x - memo.origin[0]) >> half, j = (y - memo.origin[1]) >> half, k = (z - memo.origin[2]) >> half;
  return memo.values[static_cast<std::size_t>(i + 3 * j + 9 * k)];
}

}  // namespace sansui::solid
