// Droplet hydraulic erosion (see droplets.hpp).
#include "water/droplets.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/random.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

constexpr std::uint64_t droplet_stream = 0x44524F504C455453ull;  // "DROPLETS"

/// One change a droplet makes: `amount` (m; > 0 deposits, < 0 erodes) spread
/// bilinearly over the cell at `cell` and its east, south and south-east neighbours.
struct Change {
  std::int32_t cell;
  float amount, u, v;
};

struct Sample {
  float height, gradient_x, gradient_y;
};

[[gnu::always_inline]] inline Sample sample(const float* z, int width, float x, float y) {
  const int cx = static_cast<int>(x), cy = static_cast<int>(y);
  const float u = x - static_cast<float>(cx), v = y - static_cast<float>(cy);
  const float* p = z + static_cast<std::ptrdiff_t>(cy) * width + cx;
  const float nw = p[0], ne = p[1], sw = p[width], se = p[width + 1];
  return {nw * (1 - u) * (1 - v) + ne * u * (1 - v) + sw * (1 - u) * v + se * u * v, (ne - nw) * (1 - v) + (se - sw) * v,
          (sw - nw) * (1 - u) + (se - ne) * u};
}

/// Runs one droplet on the frozen heights `z` (in cell sizes); writes its changes, returns how many.
int run_droplet(const float* z, int width, int height, float cell_size, const DropletParams& p, std::uint64_t index, Change* changes) {
  const float per_cell = 1.0f / cell_size;
  const std::uint64_t key = rng::stream_key(p.seed, droplet_stream);
  const auto lo = static_cast<std::int32_t>(index & 0xFFFFFFFFu), hi = static_cast<std::int32_t>(index >> 32);
  float x = static_cast<float>(rng::to_uniform(rng::bits(key, rng::pack(lo, hi))) * (width - 1));
  float y = static_cast<float>(rng::to_uniform(rng::bits(key, rng::pack(lo, hi ^ 0x40000000))) * (height - 1));
  const auto inertia = static_cast<float>(p.inertia), capacity_factor = static_cast<float>(p.capacity);
  const auto min_capacity = static_cast<float>(p.min_capacity), erosion_rate = static_cast<float>(p.erosion_rate);
  const auto deposition_rate = static_cast<float>(p.deposition_rate), keep_water = static_cast<float>(1.0 - p.evaporation);
  const auto gravity = static_cast<float>(p.gravity);
  float dir_x = 0, dir_y = 0, speed = 1, water = 1, sediment = 0;
  int count = 0;
  const float max_x = static_cast<float>(width - 1), max_y = static_cast<float>(height - 1);
  // The heights are frozen for the batch, so the sample at the next position is the next
  // step's own: one bilinear sample per step.
  Sample here = sample(z, width, x, y);
  for (int step = 0; step < p.lifetime; ++step) {
    const int cx = static_cast<int>(x), cy = static_cast<int>(y);
    const std::int32_t cell = cy * width + cx;
    const float u = x - static_cast<float>(cx), v = y - static_cast<float>(cy);
    dir_x = dir_x * inertia - here.gradient_x * per_cell * (1 - inertia);
    dir_y = dir_y * inertia - here.gradient_y * per_cell * (1 - inertia);
    const float length = std::sqrt(dir_x * dir_x + dir_y * dir_y);
    if (length == 0.0f) break;  // a perfectly flat spot: the droplet stays and drops its load
    dir_x /= length, dir_y /= length;
    const float next_x = x + dir_x, next_y = y + dir_y;
    if (!(next_x >= 0 && next_y >= 0 && next_x < max_x && next_y < max_y)) return count;  // off the map, load and all
    const Sample next = sample(z, width, next_x, next_y);
    const float drop = (here.height - next.height) * per_cell;
    const float capacity = std::max(drop * speed * water * capacity_factor, min_capacity);
    if (drop < 0 || sediment > capacity) {
      // Climbing: fill the step up (at most the load); slowing: drop part of the surplus.
      const float amount = drop < 0 ? std::min(-drop, sediment) : (sediment - capacity) * deposition_rate;
      sediment -= amount;
      changes[count++] = {cell, amount * cell_size, u, v};
    } else {
      // Never dig deeper than the drop ahead, so a droplet cannot cut a pit.
      const float amount = std::min((capacity - sediment) * erosion_rate, drop);
      sediment += amount;
      changes[count++] = {cell, -amount * cell_size, u, v};
    }
    speed = std::sqrt(std::max(0.0f, speed * speed + drop * gravity));
    water *= keep_water;
    x = next_x, y = next_y;
    here = next;
  }
  if (sediment > 0) {
    const int cx = static_cast<int>(x), cy = static_cast<int>(y);
    changes[count++] = {cy * width + cx, sediment * cell_size, x - static_cast<float>(cx), y - static_cast<float>(cy)};
  }
  return count;
}

}  // namespace

Heightfield erode_droplets(const Heightfield& heights, const DropletParams& params, const Context& context) {
  params.validate();
  require_finite_heights(heights, "droplet erosion");
  const int width = heights.width(), height = heights.height();
  if (width < 2 || height < 2 || params.droplets == 0) return heights;
  // Droplets work in cell sizes, so slopes are plain ratios; changes are recorded in metres.
  const auto cell_size = static_cast<float>(heights.cell_size_m);
  Heightfield z(heights);
  const auto slots = static_cast<std::size_t>(params.lifetime) + 1;
  std::vector<Change> changes(static_cast<std::size_t>(droplet_batch) * slots);
  std::vector<int> counts(static_cast<std::size_t>(droplet_batch));
  float* data = z.data();
  for (std::int64_t first = 0; first < params.droplets; first += droplet_batch) {
    const int batch = static_cast<int>(std::min<std::int64_t>(droplet_batch, params.droplets - first));
    tbb::parallel_for(tbb::blocked_range<int>(0, batch, 64), [&](const tbb::blocked_range<int>& range) {
      for (int d = range.begin(); d < range.end(); ++d) {
        const auto slot = static_cast<std::size_t>(d);
        counts[slot] =
            run_droplet(data, width, height, cell_size, params, static_cast<std::uint64_t>(first + d), changes.data() + slot * slots);
      }
    });
    // Applied in droplet order: the same sums in the same order with any number of threads.
    for (int d = 0; d < batch; ++d) {
      const Change* c = changes.data() + static_cast<std::size_t>(d) * slots;
      for (int k = 0; k < counts[static_cast<std::size_t>(d)]; ++k) {
        float* p = data + c[k].cell;
        const float a = c[k].amount, u = c[k].u, v = c[k].v;
        p[0] += a * (1 - u) * (1 - v);
        p[1] += a * u * (1 - v);
        p[width] += a * (1 - u) * v;
        p[width + 1] += a * u * v;
      }
    }
    if ((first / droplet_batch) % 64 == 0) {
      context.check_cancelled();
      context.report("droplet erosion", static_cast<double>(first + batch) / static_cast<double>(params.droplets));
    }
  }
  return z;
}

}  // namespace sansui::water
