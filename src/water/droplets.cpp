// Droplet hydraulic erosion (see droplets.hpp).
#include "water/droplets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/parallel.hpp"
#include "core/random.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

constexpr std::uint64_t droplet_stream = 0x44524F504C455453ull;  // "DROPLETS"

struct Sample {
  float height, gradient_x, gradient_y;
};

[[gnu::always_inline]] inline Sample sample(const DropletGround& g, float x, float y) {
  const int cx = static_cast<int>(x), cy = static_cast<int>(y);
  const float u = x - static_cast<float>(cx), v = y - static_cast<float>(cy);
  const float* p = g.z + g.offset(cx, cy);
  const float nw = p[0], ne = p[1], sw = p[g.stride], se = p[g.stride + 1];
  return {nw * (1 - u) * (1 - v) + ne * u * (1 - v) + sw * (1 - u) * v + se * u * v, (ne - nw) * (1 - v) + (se - sw) * v,
          (sw - nw) * (1 - u) + (se - ne) * u};
}

}  // namespace

std::pair<float, float> droplet_start(int width, int height, const DropletParams& p, std::uint64_t index) {
  const std::uint64_t key = rng::stream_key(p.seed, droplet_stream);
  const auto lo = static_cast<std::int32_t>(index & 0xFFFFFFFFu), hi = static_cast<std::int32_t>(index >> 32);
  return {static_cast<float>(rng::to_uniform(rng::bits(key, rng::pack(lo, hi))) * (width - 1)),
          static_cast<float>(rng::to_uniform(rng::bits(key, rng::pack(lo, hi ^ 0x40000000))) * (height - 1))};
}

void run_droplet(const DropletGround& g, float cell_size, const DropletParams& p, float base_level, float x, float y) {
  const float per_cell = 1.0f / cell_size;
  const auto inertia = static_cast<float>(p.inertia), capacity_factor = static_cast<float>(p.capacity);
  const auto min_capacity = static_cast<float>(p.min_capacity), erosion_rate = static_cast<float>(p.erosion_rate);
  const auto deposition_rate = static_cast<float>(p.deposition_rate), keep_water = static_cast<float>(1.0 - p.evaporation);
  const auto gravity = static_cast<float>(p.gravity);
  float dir_x = 0, dir_y = 0, speed = 1, water = 1, sediment = 0;
  const float max_x = static_cast<float>(g.width - 1), max_y = static_cast<float>(g.height - 1);
  // The droplet changes the ground as it goes: a pit it deposits into fills up under it, a cell it
  // erodes gets lower, so the drop it sees next shrinks. Changes kept until the droplet dries
  // up would feed back instead: a droplet that rocks in a pit digs it deeper at every step.
  const auto change = [&](std::ptrdiff_t cell, float amount, float u, float v) {
    float* c = g.z + cell;
    c[0] += amount * (1 - u) * (1 - v);
    c[1] += amount * u * (1 - v);
    c[g.stride] += amount * (1 - u) * v;
    c[g.stride + 1] += amount * u * v;
  };
  for (int step = 0; step < p.lifetime; ++step) {
    const Sample here = sample(g, x, y);
    if (here.height <= base_level) return;  // the sea or the plain: the water leaves with its load
    const int cx = static_cast<int>(x), cy = static_cast<int>(y);
    const std::ptrdiff_t cell = g.offset(cx, cy);
    const float u = x - static_cast<float>(cx), v = y - static_cast<float>(cy);
    dir_x = dir_x * inertia - here.gradient_x * per_cell * (1 - inertia);
    dir_y = dir_y * inertia - here.gradient_y * per_cell * (1 - inertia);
    const float length = std::sqrt(dir_x * dir_x + dir_y * dir_y);
    if (length == 0.0f) break;  // a perfectly flat spot: the droplet stays and drops its load
    dir_x /= length, dir_y /= length;
    const float next_x = x + dir_x, next_y = y + dir_y;
    if (!(next_x >= 0 && next_y >= 0 && next_x < max_x && next_y < max_y)) return;  // off the map, load and all
    const Sample next = sample(g, next_x, next_y);
    const float drop = (here.height - next.height) * per_cell;
    const float capacity = std::max(drop * speed * water * capacity_factor, min_capacity);
    if (drop < 0 || sediment > capacity) {
      // Climbing: fill the step up (at most the load); slowing: drop part of the surplus.
      const float amount = drop < 0 ? std::min(-drop, sediment) : (sediment - capacity) * deposition_rate;
      sediment -= amount;
      change(cell, amount * cell_size, u, v);
    } else {
      // Never dig deeper than the drop ahead, so a droplet cannot cut a pit.
      const float amount = std::min((capacity - sediment) * erosion_rate, drop);
      sediment += amount;
      change(cell, -amount * cell_size, u, v);
    }
    speed = std::sqrt(std::max(0.0f, speed * speed + drop * gravity));
    water *= keep_water;
    x = next_x, y = next_y;
  }
  // What a droplet still carries when it dries up is not laid down in one heap at its last
  // spot (a heap as high as the whole descent, which later droplets pile onto without bound):
  // it stays as a thin veneer nobody draws, as in Lague's form of the model.
}

double droplet_height_scale(const Heightfield& heights) {
  // The mean height step between east neighbours, over every 7th row, in cell sizes. An exact sum
  // (core/exact_sum.hpp): a tiled world sums the same terms in another order.
  ExactSum sum;
  std::int64_t count = 0;
  for (int y = 0; y < heights.height(); y += 7)
    for (int x = 0; x + 1 < heights.width(); ++x) {
      sum.add(height_step(heights(x + 1, y), heights(x, y)));
      ++count;
    }
  return droplet_height_scale(sum, count, heights.cell_size_m);
}

double droplet_height_scale(const ExactSum& steps, std::int64_t count, double cell_size_m) {
  const double typical_step = count > 0 ? steps.value() / static_cast<double>(count) / cell_size_m : 0.0;
  return std::max(typical_step / 0.01, 1.0);
}

std::int64_t droplet_count(const DropletParams& params, std::size_t cells) {
  if (params.droplets) return *params.droplets;
  return std::llround(params.droplets_per_cell * static_cast<double>(cells));
}

Heightfield erode_droplets(const Heightfield& heights, const DropletParams& params, const Context& context,
                           std::optional<double> base_level_m) {
  params.validate();
  require_finite_heights(heights, "droplet erosion");
  const int width = heights.width(), height = heights.height();
  const std::int64_t droplets = droplet_count(params, heights.size());
  if (width < 2 || height < 2 || droplets == 0) return heights;
  const float base_level = base_level_m ? static_cast<float>(*base_level_m) : -std::numeric_limits<float>::infinity();
  // Droplets work in units of `scale` metres of height per cell of distance: Beyer's constants
  // (capacity, rates, gravity) are tuned for terrain whose height changes by about a hundredth
  // of that unit per cell. Real relief in metres on metre-sized cells drops by whole cells per
  // step, and droplets then carry (and leave in one heap) hundreds of metres of rock, which
  // grows without bound. The scale is set from the terrain's typical step, so the same params
  // give the same look on any relief and spacing; changes are recorded back in metres.
  const auto cell_size = static_cast<float>(heights.cell_size_m * droplet_height_scale(heights));
  Heightfield z(heights);
  float* data = z.data();
  // Every droplet sees the changes of the droplets before it (droplets that all read the same
  // frozen heights dig the same channel cell over and over, and the terrain blows up). For that
  // in parallel, and the same bytes with any number of threads: the map is cut into square tiles
  // wider than twice a droplet's reach; tiles of one colour of a 2x2 checkerboard are two tiles
  // apart, so their droplets never touch the same cell and run at once, each tile's droplets one
  // after another in droplet order, the four colours in turn.
  const DropletTiles layout(params, width, height);
  const int tile = layout.tile, tiles_x = layout.tiles_x, tiles_y = layout.tiles_y;
  const DropletGround ground{data, width, 0, 0, width, height};
  struct Start {
    std::uint64_t index;
    float x, y;
  };
  std::vector<std::vector<Start>> by_tile(static_cast<std::size_t>(tiles_x) * static_cast<std::size_t>(tiles_y));
  for (std::int64_t first = 0; first < droplets; first += droplet_round) {
    const std::int64_t count = std::min<std::int64_t>(droplet_round, droplets - first);
    for (auto& bucket : by_tile) bucket.clear();
    for (std::int64_t d = first; d < first + count; ++d) {
      const auto [x, y] = droplet_start(width, height, params, static_cast<std::uint64_t>(d));
      const int tx = std::min(static_cast<int>(x) / tile, tiles_x - 1), ty = std::min(static_cast<int>(y) / tile, tiles_y - 1);
      by_tile[static_cast<std::size_t>(ty) * tiles_x + tx].push_back({static_cast<std::uint64_t>(d), x, y});
    }
    for (int colour = 0; colour < 4; ++colour) {
      const int cx = colour % 2, cy = colour / 2;
      const int across = (tiles_x - cx + 1) / 2, down = (tiles_y - cy + 1) / 2;
      parallel_for_ranges<int>(0, across * down, 1, [&](int range_begin, int range_end) {
        for (int t = range_begin; t < range_end; ++t) {
          const int tx = cx + 2 * (t % across), ty = cy + 2 * (t / across);
          for (const Start& start : by_tile[static_cast<std::size_t>(ty) * tiles_x + tx])
            run_droplet(ground, cell_size, params, base_level, start.x, start.y);
        }
      });
    }
    context.check_cancelled();
    context.report("droplet erosion", static_cast<double>(first + count) / static_cast<double>(droplets));
  }
  return z;
}

}  // namespace sansui::water
