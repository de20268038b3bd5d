// Big heightfields (up to 16385^2) are averaged down before they go to the GPU: the mesh, the
// height texture and the shading maps each have a cap on samples per side.
#pragma once

#include "core/grid.hpp"

namespace sansui::look {

/// The smallest whole step f such that every f-th sample fits in `max_samples` per side, but
/// never so large that the shorter side keeps fewer than 2 samples: a long, thin heightfield
/// (130 x 2) keeps both its rows and goes over the cap along its length.
int downsample_step(int width, int height, int max_samples);

/// Every `step`-th sample of `heights` (x and y), each the mean of the samples within
/// step/2 of it (a box filter, so peaks and ridges thinner than the step are not aliased).
/// The output has (width - 1) / step + 1 samples per side (for 2^k+1 sizes and a power-of-two
/// step, the same corners; otherwise up to step - 1 edge samples are dropped) and cell size
/// step times the input's; origin is kept. step 1 returns a copy.
/// [Range: step >= 1]
Heightfield downsample(const Heightfield& heights, int step);

}  // namespace sansui::look
