// Type II: on demand with a shared memo (see type2_memo.hpp).
#include "solid/type2_memo.hpp"

#include <algorithm>
#include <cassert>

#include "solid/node_rules.hpp"

namespace sansui::solid {
// Named, not anonymous: MemoEvaluator::Map (external linkage) holds these types, which GCC
// flags when the file is compiled inside a unity batch.
namespace memo_detail {

/// Counts the bytes the map allocates (nodes and bucket array), for the memory experiment.
struct ByteCount {
  std::size_t now = 0;
  std::size_t peak = 0;
};

template <class T>
struct CountingAllocator {
  using value_type = T;
  ByteCount* count;

  explicit CountingAllocator(ByteCount* c) : count(c) {}
  template <class U>
  CountingAllocator(const CountingAllocator<U>& other) : count(other.count) {}

  T* allocate(std::size_t n) {
    count->now += n * sizeof(T);  // NOLINT(bugprone-sizeof-expression): T may be a pointer (map buckets)
    count->peak = std::max(count->peak, count->now);
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) {
    count->now -= n * sizeof(T);  // NOLINT(bugprone-sizeof-expression)
    std::allocator<T>().deallocate(p, n);
  }
  template <class U>
  friend bool operator==(const CountingAllocator& a, const CountingAllocator<U>& b) {
    return a.count == b.count;
  }
};

struct MixHash {
  std::size_t operator()(std::uint64_t key) const { return static_cast<std::size_t>(rng::mix64(key)); }
};

}  // namespace memo_detail

using memo_detail::ByteCount;
using memo_detail::CountingAllocator;
using memo_detail::MixHash;

struct MemoEvaluator::Map {
  ByteCount bytes;
  std::unordered_map<std::uint64_t, float, MixHash, std::equal_to<>, CountingAllocator<std::pair<const std::uint64_t, float>>> nodes{
      16, MixHash{}, std::equal_to<>{}, CountingAllocator<std::pair<const std::uint64_t, float>>(&bytes)};
};

MemoEvaluator::MemoEvaluator(const FieldParams& params)
    : FieldEvaluator(params),
      map_(std::make_unique<Map>()),
      key_(rng::stream_key(params.seed, rules::stream)),
      scales_(displacement_scales(params)) {}

MemoEvaluator::~MemoEvaluator() = default;

std::unique_ptr<FieldEvaluator> MemoEvaluator::clone() const {
  return std::make_unique<MemoEvaluator>(params());
}

std::size_t MemoEvaluator::memory_bytes() const {
  return map_->bytes.now;
}
std::size_t MemoEvaluator::peak_memory_bytes() const {
  return map_->bytes.peak;
}
std::size_t MemoEvaluator::nodes() const {
  return map_->nodes.size();
}

float MemoEvaluator::at(int x, int y, int z) {
  assert(x >= 0 && y >= 0 && z >= 0 && x <= last() && y <= last() && z <= last());
  const int levels = params().levels;
  const int level = std::max({rules::axis_level(x, levels), rules::axis_level(y, levels), rules::axis_level(z, levels)});
  if (level == 0) {
    const int corner = (x >> levels) + 2 * (y >> levels) + 4 * (z >> levels);
    return params().corners[static_cast<std::size_t>(corner)];
  }
  const std::uint64_t key = rng::pack(x, y, z);
  if (const auto found = map_->nodes.find(key); found != map_->nodes.end()) return found->second;
  const float value = compute(x, y, z, level);
  map_->nodes.emplace(key, value);
  return value;
}

/// A node from its parents: the neighbours at distance 2^b along each active axis (the axes whose
/// level is the node's level), in pairs (minus, plus), axes in the order x, y, z.
float MemoEvaluator::compute(int x, int y, int z, int level) {
  const int levels = params().levels;
  const int half = 1 << (levels - level);
  float parents[6];
  int count = 0;
  if (rules::axis_level(x, levels) == level) {
    parents[count++] = at(x - half, y, z);
    parents[count++] = at(x + half, y, z);
  }
  if (rules::axis_level(y, levels) == level) {
    parents[count++] = at(x, y - half, z);
    parents[count++] = at(x, y + half, z);
  }
  if (rules::axis_level(z, levels) == level) {
    parents[count++] = at(x, y, z - half);
    parents[count++] = at(x, y, z + half);
  }
  const float mean = count == 2   ? rules::mean2(parents[0], parents[1])
                     : count == 4 ? rules::mean4(parents[0], parents[1], parents[2], parents[3])
                                  : rules::mean6(parents[0], parents[1], parents[2], parents[3], parents[4], parents[5]);
  const float g = rules::gaussian(key_, rules::counter(x, y, z, levels));
  return rules::displace(mean, g, scales_[static_cast<std::size_t>(level)]);
}

}  // namespace sansui::solid
