// One stage of midpoint displacement with additions over a window of the world, computed row by
// row straight into its destination (the output grid, or a block's scratch level).
//
// A stage turns level l-1 into level l in four steps over the whole window: square step (the
// centres), square additions (the old points), diamond step (the edge midpoints), diamond
// additions (old points and centres). Each sample of level l depends on parent samples at most
// one parent cell away, so the four steps fuse into one pass over the output rows that keeps
// only four short rows of intermediate values (old points after the square additions, centres
// before the diamond additions) and writes every output sample once, with the operations of
// midpoint_rules.hpp in their order: the bytes equal the plain algorithm's.
#pragma once

#include <cstdint>
#include <vector>

#include "core/gaussian_row.hpp"
#include "core/grid.hpp"
#include "core/random.hpp"
#include "core/rect.hpp"

namespace sansui::terrain::detail {

/// scale * rules::gaussian for the points (x_first + t * x_step, y), t < count, of one stream:
/// written into `buffer` (room for count + noise_slack values) from the start of the first
/// point's pair, in whole groups of pairs, and returned from the first point on.
inline constexpr int noise_slack = 2 + 2 * rng::gaussian_pair_group;
const float* fill_gaussians(std::uint64_t key, int x_first, int x_step, int y, int count, float scale, float* buffer);

/// The random streams (keys) and displacement scales of one stage.
struct StageNoise {
  std::uint64_t square_create = 0, square_add = 0, diamond_create = 0, diamond_add = 0;
  float square_scale = 0.0f, diamond_scale = 0.0f;
  bool additions = true;
};

/// Samples of one level in a rectangle of that level's indices: sample (x, y) is
/// values(x - rect.x0, y - rect.y0).
struct LevelView {
  int level = 0;
  Rect rect;
  ConstGridView<float> values;
};

/// Row buffers of refine_window, kept by a thread between calls so that refining allocates
/// nothing once warm.
struct RefineScratch {
  std::vector<float> rows;  ///< four rows of intermediate values
  std::vector<float> noise, even, odd;
};

/// The window of level l-1 that refining needs to produce `target` at level l: the even samples
/// within two samples of the target, clipped to the world.
Rect parent_rect(Rect target, int level);

/// Level `level`'s samples of `target` into `out` (target's size) from `parent` (level - 1),
/// which must hold parent_rect(target, level).
void refine_window(const LevelView& parent, int level, Rect target, const StageNoise& stage, RefineScratch& scratch, GridView<float> out);

}  // namespace sansui::terrain::detail
