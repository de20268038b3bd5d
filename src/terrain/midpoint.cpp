// Midpoint displacement with successive random additions, by windows (see midpoint.hpp).
//
// A window at level l (2^l + 1 samples per side) is refined from a window at level l-1 that is
// two coarse samples larger on each side (the "halo"), so any window can be computed from
// level 0 alone. Large windows are computed in blocks: a coarse level for the whole window,
// then independent cache-sized blocks refined through the last few levels, in parallel.
#include "terrain/midpoint.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "core/exact_math.hpp"
#include "core/parallel.hpp"
#include "terrain/midpoint_refine.hpp"
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

using detail::fill_gaussians;
using detail::LevelView;
using detail::parent_rect;
using rules::HalfStep;
using rules::Operation;

constexpr int block_levels = 3;  // levels refined per block
constexpr int block_side = 512;  // finest samples per block side: fits in L2 with its parents

/// A rectangle of one level's samples with their values. rect is in that level's indices.
struct LevelWindow {
  int level = 0;
  Rect rect;
  Grid<float> values;  // values(x - rect.x0, y - rect.y0)

  LevelView view() const { return {level, rect, values.view()}; }
};

/// What one thread reuses from block to block: the rows of the fused stage and two levels of a
/// block's chain, so that refining a block allocates nothing once warm.
struct BlockScratch {
  detail::RefineScratch rows;
  std::array<std::vector<float>, 2> levels;

  GridView<float> level_buffer(int level, Rect rect) {
    std::vector<float>& buffer = levels[static_cast<std::size_t>(level & 1)];
    buffer.resize(static_cast<std::size_t>(rect.width()) * static_cast<std::size_t>(rect.height()));
    return {buffer.data(), rect.width(), rect.height(), rect.width()};
  }
};

class Generator {
 public:
  Generator(const MidpointParams& params, int world_levels, int output_level)
      : params_(params),
        world_levels_(world_levels),
        output_level_(output_level),
        scales_(rules::displacement_scales(params.sigma(), params.hurst, world_levels)) {
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
    LevelWindow result{level, target, Grid<float>::uninitialized(target.width(), target.height())};
    if (level <= block_levels || area <= static_cast<long long>(block_side) * block_side) {
      const LevelWindow parent = compute(level - 1, parent_rect(target, level), context);
      detail::RefineScratch rows;
      detail::refine_window(parent.view(), level, target, stage(level), rows, result.values.view());
      return result;
    }

    // Blocked: one coarse window for the whole target, then independent blocks, each refined
    // through the last levels in its thread's scratch and written once into the result.
    const int coarse_level = std::max(level - block_levels, lowest);
    const int levels_down = level - coarse_level;
    std::vector<Rect> chain(static_cast<std::size_t>(levels_down + 1));  // wanted rect per level, finest last
    chain.back() = target;
    for (int i = levels_down; i > 0; --i)
      chain[static_cast<std::size_t>(i - 1)] = parent_rect(chain[static_cast<std::size_t>(i)], coarse_level + i);
    const LevelWindow coarse = compute(coarse_level, chain[0], context);

    const int blocks_x = (target.width() + block_side - 1) / block_side;
    const int blocks_y = (target.height() + block_side - 1) / block_side;
    std::atomic<int> blocks_done{0};
    ThreadLocal<BlockScratch> scratch;
    parallel_for(0, blocks_x * blocks_y, [&](int b) {
      context.check_cancelled();
      const int bx = target.x0 + (b % blocks_x) * block_side;
      const int by = target.y0 + (b / blocks_x) * block_side;
      const Rect block{bx, by, std::min(bx + block_side, target.x1), std::min(by + block_side, target.y1)};
      refine_block(coarse.view(), level, block, scratch.local(), result.values.view(block.translated(-target.x0, -target.y0)));
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
    std::vector<float> buffer(static_cast<std::size_t>(window.rect.width()) + detail::noise_slack);
    for (int stage = window.level + 1; stage <= world_levels_; ++stage) {
      const int shift = stage - window.level;
      for (HalfStep half : {HalfStep::square, HalfStep::diamond}) {
        const std::uint64_t key = key_of(stage, half, Operation::add);
        const float scale = rules::scale_of(scales_, stage, half);
        for (int y = window.rect.y0; y < window.rect.y1; ++y) {
          const float* noise =
              fill_gaussians(key, window.rect.x0 << shift, 1 << shift, y << shift, window.rect.width(), scale, buffer.data());
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

  detail::StageNoise stage(int level) const {
    return {key_of(level, HalfStep::square, Operation::create),
            key_of(level, HalfStep::square, Operation::add),
            key_of(level, HalfStep::diamond, Operation::create),
            key_of(level, HalfStep::diamond, Operation::add),
            rules::scale_of(scales_, level, HalfStep::square),
            rules::scale_of(scales_, level, HalfStep::diamond),
            params_.additions};
  }

  LevelWindow corners(Rect target) const {
    LevelWindow window{0, target, Grid<float>::uninitialized(target.width(), target.height())};
    const float sigma = scales_[0];
    for (int y = target.y0; y < target.y1; ++y)
      for (int x = target.x0; x < target.x1; ++x)
        window.values(x - target.x0, y - target.y0) = sigma * rules::corner_gaussian(keys_[0], x, y);
    return window;
  }

  /// Refines the part of `coarse` a block needs through the levels up to `level`, into `out`:
  /// the levels in between live in the thread's two scratch buffers.
  void refine_block(const LevelView& coarse, int level, Rect block, BlockScratch& scratch, GridView<float> out) const {
    std::vector<Rect> chain(static_cast<std::size_t>(level - coarse.level + 1));
    chain.back() = block;
    for (int l = level; l > coarse.level; --l) {
      const auto i = static_cast<std::size_t>(l - coarse.level);
      chain[i - 1] = parent_rect(chain[i], l);
    }
    LevelView current = coarse;
    for (int l = coarse.level + 1; l < level; ++l) {
      const Rect rect = chain[static_cast<std::size_t>(l - coarse.level)];
      const GridView<float> values = scratch.level_buffer(l, rect);
      detail::refine_window(current, l, rect, stage(l), scratch.rows, values);
      current = {l, rect, values};
    }
    detail::refine_window(current, level, block, stage(level), scratch.rows, out);
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

float sea_level_offset(const MidpointParams& params, int world_levels, const Context& context) {
  if (params.paper_sea_level) return 0.0f;
  // 257 x 257 samples tell the quantile to well under a percent of the land, in about a millisecond.
  const int levels = std::min(world_levels, 8), side = (1 << levels) + 1;
  const Heightfield preview = generate_midpoint(params, WorldWindow{world_levels, world_levels - levels, Rect{0, 0, side, side}}, context);
  std::vector<float> heights(preview.values().begin(), preview.values().end());
  const auto rank = static_cast<std::ptrdiff_t>((1.0 - params.land_fraction) * static_cast<double>(heights.size() - 1));
  std::nth_element(heights.begin(), heights.begin() + rank, heights.end());
  return heights[static_cast<std::size_t>(rank)];
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
