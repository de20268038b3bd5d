// Midpoint displacement with successive random additions, by windows (see midpoint.hpp).
//
// A window at level l (2^l + 1 samples per side) is refined from a window at level l-1 that is
// two coarse samples larger on each side (the "halo"), so any window can be computed from
// level 0 alone. Large windows are computed in blocks: a coarse level for the whole window,
// then independent cache-sized blocks refined through the last few levels, in parallel.
#include "terrain/midpoint.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <optional>
#include <vector>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/exact_math.hpp"
#include "terrain/midpoint_rules.hpp"

namespace sansui::terrain {
namespace rules {

std::vector<float> displacement_scales(double sigma_m, double hurst, int stages) {
  const double ratio = exact_exp2(-0.5 * hurst);  // 0.5^(0.5 H)
  std::vector<float> scales(static_cast<std::size_t>(2 * stages + 1));
  double delta = sigma_m;
  scales[0] = static_cast<float>(delta);
  for (std::size_t i = 1; i < scales.size(); ++i) {
    delta *= ratio;
    scales[i] = static_cast<float>(delta);
  }
  return scales;
}

}  // namespace rules

namespace {

using rules::HalfStep;
using rules::Operation;

constexpr int block_levels = 3;  // levels refined per block
constexpr int block_side = 256;  // finest samples per block side: fits in L2 with its parents

/// A rectangle of one level's samples with their values. rect is in that level's indices.
struct LevelWindow {
  int level = 0;
  Rect rect;
  Grid<float> values;  // values(x - rect.x0, y - rect.y0)
};

/// The window of level l-1 that refining needs to produce `target` at level l: the even samples
/// within two samples of the target, clipped to the world.
Rect parent_rect(Rect target, int level) {
  const int last = 1 << (level - 1);  // last index at level l-1
  auto floor_half = [](int v) { return v >= 0 ? v / 2 : -((1 - v) / 2); };
  auto ceil_half = [&](int v) { return -floor_half(-v); };
  return {std::max(0, ceil_half(target.x0 - 2)), std::max(0, ceil_half(target.y0 - 2)), std::min(last, floor_half(target.x1 + 1)) + 1,
          std::min(last, floor_half(target.y1 + 1)) + 1};
}

/// Writes scale * gaussian for the points (x_first + t * x_step, y), t < count, of one stream.
/// The counters are affine in t, so this loop vectorises.
void fill_gaussians(std::uint64_t key, int x_first, int x_step, int y, int count, float scale, float* out) {
  const std::uint64_t base = key + rng::pack(x_first, y) * rng::golden_gamma;
  const std::uint64_t step = static_cast<std::uint64_t>(x_step) * rng::golden_gamma;
  for (int t = 0; t < count; ++t) out[t] = scale * rng::to_gaussian(rng::mix64(base + static_cast<std::uint64_t>(t) * step));
}

class Generator {
 public:
  Generator(const MidpointParams& params, int world_levels, int output_level)
      : params_(params),
        world_levels_(world_levels),
        output_level_(output_level),
        scales_(rules::displacement_scales(params.sigma_m, params.hurst, world_levels)) {
    keys_.resize(static_cast<std::size_t>(4 * world_levels + 4));
    for (std::size_t s = 0; s < keys_.size(); ++s) keys_[s] = rng::stream_key(params.seed, s);
  }

  /// Values of `target` (level indices) at `level`, before the additions of later stages.
  LevelWindow compute(int level, Rect target, const Context& context) const {
    if (base_ && level == base_->level)
      return {level, target, copy_of(base_->values.view(target.translated(-base_->rect.x0, -base_->rect.y0)))};
    if (level == 0) return corners(target);
    const int lowest = base_ ? base_->level : 0;
    const long long area = static_cast<long long>(target.width()) * target.height();
    if (level <= block_levels || area <= static_cast<long long>(block_side) * block_side)
      return refine(compute(level - 1, parent_rect(target, level), context), level, target);

    // Blocked: one coarse window for the whole target, then independent blocks.
    const int coarse_level = std::max(level - block_levels, lowest);
    const int levels_down = level - coarse_level;
    std::vector<Rect> chain(static_cast<std::size_t>(levels_down + 1));  // wanted rect per level, finest last
    chain.back() = target;
    for (int i = levels_down; i > 0; --i)
      chain[static_cast<std::size_t>(i - 1)] = parent_rect(chain[static_cast<std::size_t>(i)], coarse_level + i);
    const LevelWindow coarse = compute(coarse_level, chain[0], context);

    LevelWindow result{level, target, Grid<float>::uninitialized(target.width(), target.height())};
    const int blocks_x = (target.width() + block_side - 1) / block_side;
    const int blocks_y = (target.height() + block_side - 1) / block_side;
    std::atomic<int> blocks_done{0};
    tbb::parallel_for(0, blocks_x * blocks_y, [&](int b) {
      context.check_cancelled();
      const int bx = target.x0 + (b % blocks_x) * block_side;
      const int by = target.y0 + (b / blocks_x) * block_side;
      const Rect block{bx, by, std::min(bx + block_side, target.x1), std::min(by + block_side, target.y1)};
      refine_block(coarse, level, block, result.values.view(block.translated(-target.x0, -target.y0)));
      if (level == output_level_) context.report("terrain", double(++blocks_done) / (blocks_x * blocks_y));
    });
    return result;
  }

  /// Refines from `world` (every sample of the world at `level`, with final values) instead of
  /// from level 0: the later stages' additions at its points are taken off first, so that adding
  /// them back while refining gives `world`'s values there again (up to float rounding).
  /// The finer stages' displacements are scaled by `detail`.
  void start_from(const Heightfield& world, int level, double detail) {
    const int side = (1 << level) + 1;
    assert(world.width() == side && world.height() == side);
    for (std::size_t k = static_cast<std::size_t>(2 * level + 1); k < scales_.size(); ++k)
      scales_[k] = static_cast<float>(scales_[k] * detail);
    LevelWindow base{level, Rect{0, 0, side, side}, Grid<float>(side, side, 0.0f)};
    add_later_stages(base);
    for (std::size_t i = 0; i < base.values.size(); ++i) base.values.values()[i] = world.values()[i] - base.values.values()[i];
    base_ = std::move(base);
  }

  /// Adds to every sample of `window` (at `level`) the additions of all finer stages, so the
  /// values become those of the full-resolution world at these points.
  void add_later_stages(LevelWindow& window) const {
    if (!params_.additions) return;
    std::vector<float> noise(static_cast<std::size_t>(window.rect.width()));
    for (int stage = window.level + 1; stage <= world_levels_; ++stage) {
      const int shift = stage - window.level;
      for (HalfStep half : {HalfStep::square, HalfStep::diamond}) {
        const std::uint64_t key = key_of(stage, half, Operation::add);
        const float scale = rules::scale_of(scales_, stage, half);
        for (int y = window.rect.y0; y < window.rect.y1; ++y) {
          fill_gaussians(key, window.rect.x0 << shift, 1 << shift, y << shift, window.rect.width(), scale, noise.data());
          auto row = window.values.row(y - window.rect.y0);
          for (std::size_t i = 0; i < row.size(); ++i) row[i] += noise[i];
        }
      }
    }
  }

 private:
  std::uint64_t key_of(int stage, HalfStep half, Operation op) const {
    return keys_[static_cast<std::size_t>(rules::stream(stage, half, op))];
  }

  LevelWindow corners(Rect target) const {
    LevelWindow window{0, target, Grid<float>::uninitialized(target.width(), target.height())};
    const float sigma = scales_[0];
    for (int y = target.y0; y < target.y1; ++y)
      for (int x = target.x0; x < target.x1; ++x)
        window.values(x - target.x0, y - target.y0) = sigma * rng::to_gaussian(rng::bits(keys_[0], rng::pack(x, y)));
    return window;
  }

  /// Refines the part of `coarse` a block needs through the levels up to `level`, into `out`.
  void refine_block(const LevelWindow& coarse, int level, Rect block, GridView<float> out) const {
    std::vector<Rect> chain(static_cast<std::size_t>(level - coarse.level + 1));
    chain.back() = block;
    for (int l = level; l > coarse.level; --l) {
      const auto i = static_cast<std::size_t>(l - coarse.level);
      chain[i - 1] = parent_rect(chain[i], l);
    }
    const Rect start = chain[0];
    LevelWindow current{coarse.level, start, copy_of(coarse.values.view(start.translated(-coarse.rect.x0, -coarse.rect.y0)))};
    for (int l = coarse.level + 1; l < level; ++l) current = refine(current, l, chain[static_cast<std::size_t>(l - coarse.level)]);
    refine_into(current, level, block, out);
  }

  /// One stage: from `parent` at level-1 to `target` at `level` (parent must hold parent_rect).
  LevelWindow refine(const LevelWindow& parent, int level, Rect target) const {
    LevelWindow result{level, target, Grid<float>::uninitialized(target.width(), target.height())};
    refine_into(parent, level, target, result.values.view());
    return result;
  }

  /// refine(), writing the target's values into `out` (target's size).
  void refine_into(const LevelWindow& parent, int level, Rect target, GridView<float> out) const {
    const int stage = level;
    const int world_last = 1 << level;
    // The work area: every sample of this level spanned by the parent window.
    const int x0 = 2 * parent.rect.x0, y0 = 2 * parent.rect.y0;
    const int width = 2 * parent.rect.width() - 1, height = 2 * parent.rect.height() - 1;
    Grid<float> work = Grid<float>::uninitialized(width, height);
    std::vector<float> noise(static_cast<std::size_t>(width));

    for (int j = 0; j < parent.rect.height(); ++j) {  // old points at even positions
      const auto from = parent.values.row(j);
      auto to = work.row(2 * j);
      for (int i = 0; i < parent.rect.width(); ++i) to[static_cast<std::size_t>(2 * i)] = from[static_cast<std::size_t>(i)];
    }

    // Square half-step: centres from their four corners (before the additions).
    const float square_scale = rules::scale_of(scales_, stage, HalfStep::square);
    const int centres_per_row = (width - 1) / 2;
    for (int y = 1; y < height - 1; y += 2) {
      fill_gaussians(key_of(stage, HalfStep::square, Operation::create), x0 + 1, 2, y0 + y, centres_per_row, square_scale, noise.data());
      const float* north = &work(0, y - 1);
      const float* south = &work(0, y + 1);
      float* row = &work(0, y);
      for (int t = 0; t < centres_per_row; ++t) {
        const int x = 2 * t + 1;
        row[x] = rules::mean4(north[x - 1], north[x + 1], south[x - 1], south[x + 1]) + noise[static_cast<std::size_t>(t)];
      }
    }
    if (params_.additions) add_noise(work, x0, y0, 0, 0, stage, HalfStep::square, noise);

    // Diamond half-step: edge midpoints from their four neighbours (three on the world's border).
    const float diamond_scale = rules::scale_of(scales_, stage, HalfStep::diamond);
    const std::uint64_t diamond_key = key_of(stage, HalfStep::diamond, Operation::create);
    for (int y = 0; y < height; ++y) {
      const bool even_row = (y % 2) == 0;
      const int first = even_row ? 1 : 0;
      const int count = (width - first + 1) / 2;
      const bool has_north = y > 0, has_south = y < height - 1;
      if ((!has_north && y0 + y != 0) || (!has_south && y0 + y != world_last)) continue;  // window edge: not computable
      fill_gaussians(diamond_key, x0 + first, 2, y0 + y, count, diamond_scale, noise.data());
      float* row = &work(0, y);
      if (even_row) {  // points between two old points of this row; centres above and below
        const float* north = has_north ? &work(0, y - 1) : nullptr;
        const float* south = has_south ? &work(0, y + 1) : nullptr;
        for (int t = 0; t < count; ++t) {
          const int x = 2 * t + 1;
          const float mean = north == nullptr   ? rules::mean3(row[x - 1], row[x + 1], south[x])
                             : south == nullptr ? rules::mean3(row[x - 1], row[x + 1], north[x])
                                                : rules::mean4(row[x - 1], row[x + 1], north[x], south[x]);
          row[x] = mean + noise[static_cast<std::size_t>(t)];
        }
      } else {  // points between two centres of this row; old points above and below
        const float* north = &work(0, y - 1);
        const float* south = &work(0, y + 1);
        for (int t = 1; t < count - 1; ++t) {
          const int x = 2 * t;
          row[x] = rules::mean4(row[x - 1], row[x + 1], north[x], south[x]) + noise[static_cast<std::size_t>(t)];
        }
        // The ends: on the world's border they have three neighbours; on the window's, none known.
        if (x0 == 0) row[0] = rules::mean3(north[0], south[0], row[1]) + noise[0];
        const int last = width - 1;
        if (x0 + last == world_last)
          row[last] = rules::mean3(north[last], south[last], row[last - 1]) + noise[static_cast<std::size_t>(count - 1)];
      }
    }
    if (params_.additions) {
      add_noise(work, x0, y0, 0, 0, stage, HalfStep::diamond, noise);  // old points
      add_noise(work, x0, y0, 1, 1, stage, HalfStep::diamond, noise);  // centres
    }

    assert((Rect{x0, y0, x0 + width, y0 + height}.contains(target)));
    copy_into(work.view(target.translated(-x0, -y0)), out);
  }

  /// Successive random addition to the points of `work` at (odd_x + 2i, odd_y + 2j).
  void add_noise(Grid<float>& work, int x0, int y0, int first_x, int first_y, int stage, HalfStep half, std::vector<float>& noise) const {
    const std::uint64_t key = key_of(stage, half, Operation::add);
    const float scale = rules::scale_of(scales_, stage, half);
    const int count = (work.width() - first_x + 1) / 2;
    for (int y = first_y; y < work.height(); y += 2) {
      fill_gaussians(key, x0 + first_x, 2, y0 + y, count, scale, noise.data());
      float* row = &work(0, y);
      for (int t = 0; t < count; ++t) row[first_x + 2 * t] += noise[static_cast<std::size_t>(t)];
    }
  }

  MidpointParams params_;
  int world_levels_;
  int output_level_;                 // progress is reported for this level's blocks
  std::optional<LevelWindow> base_;  // a given level to refine from (start_from)
  std::vector<float> scales_;
  std::vector<std::uint64_t> keys_;
};

}  // namespace

int levels_for_size(long long size) {
  for (int k = 0; k <= 40; ++k)
    if ((1ll << k) + 1 == size) return k;
  return -1;
}

Heightfield generate_midpoint(const MidpointParams& params, const WorldWindow& where, const Context& context) {
  params.validate();
  if (where.world_levels < 0 || where.world_levels > max_world_levels)
    fail("world of 2^{}+1 samples is not allowed: at most 2^{}+1", where.world_levels, max_world_levels);
  if (where.lod < 0 || where.lod > where.world_levels) fail("level of detail {} is outside 0..{}", where.lod, where.world_levels);
  const int last = 1 << (where.world_levels - where.lod);
  const Rect whole{0, 0, last + 1, last + 1};
  if (where.window.empty() || !whole.contains(where.window))
    fail("window [{},{})x[{},{}) is outside the world's {} samples per side", where.window.x0, where.window.x1, where.window.y0,
         where.window.y1, last + 1);

  const int output_level = where.world_levels - where.lod;
  const Generator generator(params, where.world_levels, output_level);
  LevelWindow window = generator.compute(output_level, where.window, context);
  generator.add_later_stages(window);
  return std::move(window.values);
}

Heightfield refine_midpoint(const MidpointParams& params, const WorldWindow& where, const Heightfield& coarse, double detail,
                            const Context& context) {
  params.validate();
  if (!(detail >= 0.0 && detail <= 1.0)) fail("detail {} is not allowed: it must be between 0 and 1", detail);
  const int coarse_level = levels_for_size(coarse.width());
  if (coarse_level < 0 || coarse.height() != coarse.width() || coarse_level > where.world_levels)
    fail("the coarse world is {}x{}; it must be square with 2^k+1 samples per side, k at most {}", coarse.width(), coarse.height(),
         where.world_levels);
  const int output_level = where.world_levels - where.lod;
  if (output_level < coarse_level) fail("level of detail {} is coarser than the given coarse world's", where.lod);
  const int last = 1 << output_level;
  if (where.window.empty() || !Rect{0, 0, last + 1, last + 1}.contains(where.window))
    fail("window [{},{})x[{},{}) is outside the world's {} samples per side", where.window.x0, where.window.x1, where.window.y0,
         where.window.y1, last + 1);
  Generator generator(params, where.world_levels, output_level);
  generator.start_from(coarse, coarse_level, detail);
  LevelWindow window = generator.compute(output_level, where.window, context);
  generator.add_later_stages(window);
  return std::move(window.values);
}

Heightfield generate_midpoint(const MidpointParams& params, int size, const Context& context) {
  const int levels = levels_for_size(size);
  if (levels < 1 || levels > 14) fail("size {} is not allowed: it must be 2^k+1 between 3 and 16385", size);
  return generate_midpoint(params, WorldWindow{levels, 0, Rect{0, 0, size, size}}, context);
}

}  // namespace sansui::terrain
