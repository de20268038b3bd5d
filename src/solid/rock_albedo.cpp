#include "solid/rock_albedo.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "solid/evaluator.hpp"
#include "solid/texture.hpp"

namespace sansui::solid {

void RockParams::validate() const {
  params::validate(*this);
  if (r2 > levels) fail("rock.r2 {} is not allowed: it must be 0..levels = {}", r2, levels);
}

Image rock_albedo(const Heightfield& heights, const RockParams& params, const Context& context) {
  params.validate();
  if (params.texture == "none") return Image();  // no rock: the renderer keeps its cliff colour
  SolidTexture texture = texture_preset(params.texture);
  texture.strata.seed = params.seed;
  const TextureSampler sampler(texture);
  if (heights.empty()) return Image();

  float low = heights.values()[0], high = low;
  for (float h : heights.values()) {
    if (!std::isfinite(h)) fail("the heightfield has a height {}: rock needs finite heights", h);
    low = std::min(low, h);
    high = std::max(high, h);
  }
  FieldParams field_params;
  field_params.seed = params.seed;
  field_params.levels = params.levels;
  field_params.beta = params.beta;
  const auto field = make_evaluator(EvaluatorType::type4, field_params, {params.r2, true}, context);

  // Where a point (metres) falls in the field's block (lattice units).
  const double last = std::ldexp(1.0, params.levels);
  const double extent = std::max(
      {(heights.width() - 1) * heights.cell_size_m, (heights.height() - 1) * heights.cell_size_m, static_cast<double>(high - low), 1e-6});
  const bool anchored = params.field_cell_m > 0.0;
  const double cell = anchored ? params.field_cell_m : extent / last;
  const double base_x = anchored ? 0.0 : heights.origin_x_m, base_y = anchored ? 0.0 : heights.origin_y_m;
  const double base_z = anchored ? -0.5 * last * cell : low;

  Image albedo = Image::uninitialized(heights.width(), heights.height());
  albedo.cell_size_m = heights.cell_size_m;
  albedo.origin_x_m = heights.origin_x_m;
  albedo.origin_y_m = heights.origin_y_m;
  ThreadLocal<std::unique_ptr<FieldEvaluator>> evaluators([&] { return field->clone(); });
  std::atomic<int> rows_done{0};
  parallel_for(0, heights.height(), [&](int y) {
    context.check_cancelled();
    FieldEvaluator& evaluator = *evaluators.local();
    const double south = heights.origin_y_m + y * heights.cell_size_m;
    for (int x = 0; x < heights.width(); ++x) {
      const double east = heights.origin_x_m + x * heights.cell_size_m;
      const double up = heights(x, y);
      const float d = evaluator.sample_inside(std::clamp((east - base_x) / cell, 0.0, last), std::clamp((south - base_y) / cell, 0.0, last),
                                              std::clamp((up - base_z) / cell, 0.0, last));
      const Rgb c = sampler.color(east / params.texture_size_m, south / params.texture_size_m, up / params.texture_size_m, d);
      albedo(x, y) = {static_cast<std::uint8_t>(std::clamp(c.r, 0.0f, 1.0f) * 255.0f + 0.5f),
                      static_cast<std::uint8_t>(std::clamp(c.g, 0.0f, 1.0f) * 255.0f + 0.5f),
                      static_cast<std::uint8_t>(std::clamp(c.b, 0.0f, 1.0f) * 255.0f + 0.5f), 255};
    }
    context.report("rock", static_cast<double>(++rows_done) / heights.height());
  });
  return albedo;
}

}  // namespace sansui::solid
