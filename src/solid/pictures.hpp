// Pictures of a solid texture: a slice through the block, a shaded sphere carved out of the
// block (the object of the paper's Experiment 2, Okada et al. 1990; seeds/002, Sec. 7-3), and a
// cube showing three faces of the block. Orthographic views, computed on the CPU from the field
// at each visible surface point, so any evaluator type can draw them (Types III/IV without the
// whole lattice in memory).
#pragma once

#include "core/color.hpp"
#include "core/context.hpp"
#include "solid/evaluator.hpp"
#include "solid/texture.hpp"

namespace sansui::solid {

/// A slice of the block perpendicular to `axis` (0 x, 1 y, 2 z) at `position` (lattice units,
/// 0..2^R), `size_px` pixels square; pixel i stands at i * 2^R / (size_px - 1), so size_px =
/// 2^R + 1 shows every lattice point once. The other axes run right and up (x right, y up for a
/// z-slice; x or y right, z up otherwise). Throws InputError for a bad axis, position or size.
Image render_slice(const FieldEvaluator& field, const SolidTexture& texture, int axis, double position, int size_px,
                   const Context& context = quiet_context());

/// The sphere inscribed in the block, lit from the upper left, on a dark grey ground.
Image render_sphere(const FieldEvaluator& field, const SolidTexture& texture, int size_px, const Context& context = quiet_context());

/// The whole block seen from above, front and right: its top, front and right faces.
Image render_cube(const FieldEvaluator& field, const SolidTexture& texture, int size_px, const Context& context = quiet_context());

/// Largest picture side. [Units: px]
inline constexpr int max_picture_px = 8192;

}  // namespace sansui::solid
