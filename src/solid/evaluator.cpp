// The evaluator interface: Type I's array evaluator, the factory, and trilinear sampling, which
// all types share so that continuous queries are bit-identical too.
#include "solid/evaluator.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "solid/type1_array.hpp"
#include "solid/type2_memo.hpp"
#include "solid/type3_ancestors.hpp"

namespace sansui::solid {
namespace {

/// Type I: look-ups in the whole lattice, computed once and shared by clones.
class ArrayEvaluator final : public FieldEvaluator {
 public:
  ArrayEvaluator(const FieldParams& params, std::shared_ptr<const Volume> volume) : FieldEvaluator(params), volume_(std::move(volume)) {}
  float at(int x, int y, int z) override { return (*volume_)(x, y, z); }
  std::unique_ptr<FieldEvaluator> clone() const override { return std::make_unique<ArrayEvaluator>(params(), volume_); }
  std::size_t memory_bytes() const override { return volume_->bytes(); }
  std::size_t peak_memory_bytes() const override { return volume_->bytes(); }
  EvaluatorType type() const override { return EvaluatorType::type1; }

 private:
  std::shared_ptr<const Volume> volume_;
};

float lerp(float a, float b, float t) {
  return a + (b - a) * t;
}

}  // namespace

float FieldEvaluator::sample(double x, double y, double z) {
  const double end = last();
  if (!(x >= 0.0 && x <= end && y >= 0.0 && y <= end && z >= 0.0 && z <= end))
    fail("point ({}, {}, {}) is outside the block: coordinates must be in [0, {}]", x, y, z, last());
  return sample_inside(x, y, z);
}

float FieldEvaluator::sample_inside(double x, double y, double z) {
  const double end = last();
  x = std::clamp(x, 0.0, end);
  y = std::clamp(y, 0.0, end);
  z = std::clamp(z, 0.0, end);
  const int i = std::min(static_cast<int>(x), last() - 1);
  const int j = std::min(static_cast<int>(y), last() - 1);
  const int k = std::min(static_cast<int>(z), last() - 1);
  const auto tx = static_cast<float>(x - i), ty = static_cast<float>(y - j), tz = static_cast<float>(z - k);
  // Always the same eight look-ups and the same order of lerps: x, then y, then z.
  const float c00 = lerp(at(i, j, k), at(i + 1, j, k), tx);
  const float c10 = lerp(at(i, j + 1, k), at(i + 1, j + 1, k), tx);
  const float c01 = lerp(at(i, j, k + 1), at(i + 1, j, k + 1), tx);
  const float c11 = lerp(at(i, j + 1, k + 1), at(i + 1, j + 1, k + 1), tx);
  return lerp(lerp(c00, c10, ty), lerp(c01, c11, ty), tz);
}

std::unique_ptr<FieldEvaluator> make_evaluator(EvaluatorType type, const FieldParams& params, const EvaluatorOptions& options,
                                               const Context& context) {
  params.validate();
  switch (type) {
    case EvaluatorType::type1:
      return std::make_unique<ArrayEvaluator>(params, std::make_shared<const Volume>(generate_type1(params, context)));
    case EvaluatorType::type2:
      return std::make_unique<MemoEvaluator>(params);
    case EvaluatorType::type3:
      return std::make_unique<AncestorEvaluator>(params, corner_volume(params), options.reuse);
    case EvaluatorType::type4: {
      if (options.r2 < 0 || options.r2 > params.levels) fail("R2 = {} is not allowed: it must be 0..R (R = {})", options.r2, params.levels);
      FieldParams upper = params;
      upper.levels = options.r2;
      // Levels 0..R2 of this field are the field of R2 levels (node_rules.hpp hashes world
      // coordinates), so the upper array is simply Type I with R2 levels.
      std::shared_ptr<const Volume> array =
          options.r2 == 0 ? corner_volume(params) : std::make_shared<const Volume>(generate_type1(upper, context));
      return std::make_unique<AncestorEvaluator>(params, std::move(array), options.reuse);
    }
  }
  fail("unknown evaluator type");
}

void evaluate_plane(FieldEvaluator& field, int z, float* out) {
  const int side = field.last() + 1;
  if (field.type() == EvaluatorType::type2) {
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        out[static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x)] = field.at(x, y, z);
    return;
  }
  ThreadLocal<std::unique_ptr<FieldEvaluator>> evaluators([&] { return field.clone(); });
  parallel_for(0, side, [&](int y) {
    FieldEvaluator& evaluator = *evaluators.local();
    float* row = out + static_cast<std::size_t>(y) * static_cast<std::size_t>(side);
    for (int x = 0; x < side; ++x) row[x] = evaluator.at(x, y, z);
  });
}

}  // namespace sansui::solid
