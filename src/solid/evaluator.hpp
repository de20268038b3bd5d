// One interface over the four evaluators of Okada, Taga, Yokoi, Toriwaki (1990; seeds/002;
// SPEC 2). All four give the same value, bit for bit, at every lattice point for the same
// (seed, R, beta, corners): they differ only in time and memory.
//
// An evaluator is used by one thread at a time (Types II-IV keep memos); clone() gives another
// thread its own evaluator that shares the immutable parts (the Type I array, the Type IV upper
// levels).
#pragma once

#include <cstddef>
#include <memory>

#include "core/context.hpp"
#include "solid/field.hpp"

namespace sansui::solid {

class FieldEvaluator {
 public:
  virtual ~FieldEvaluator() = default;

  /// D at the lattice point (x, y, z). [Range: 0 <= x, y, z <= 2^R] (asserted: check user points with sample())
  virtual float at(int x, int y, int z) = 0;

  /// Another evaluator of the same field for another thread.
  virtual std::unique_ptr<FieldEvaluator> clone() const = 0;

  /// Bytes of the evaluator's data (array, map, memo) now and at its largest so far.
  virtual std::size_t memory_bytes() const = 0;
  virtual std::size_t peak_memory_bytes() const = 0;

  virtual EvaluatorType type() const = 0;
  const FieldParams& params() const { return params_; }
  /// 2^R: the block is [0, 2^R]^3 in lattice units.
  int last() const { return 1 << params_.levels; }

  /// D at a real point (lattice units) by trilinear interpolation of the 8 lattice points around
  /// it. Throws InputError if the point is outside the block [0, 2^R]^3 or not finite.
  float sample(double x, double y, double z);
  /// The same for points known to be inside the block (clamped, not checked).
  float sample_inside(double x, double y, double z);

 protected:
  explicit FieldEvaluator(const FieldParams& params) : params_(params) {}
  FieldEvaluator(const FieldEvaluator&) = default;

 private:
  FieldParams params_;
};

struct EvaluatorOptions {
  /// Type IV: levels computed as a Type I array; below them, Type III. [Range: 0..R] [Default: 6]
  int r2 = 6;
  /// Type III/IV: keep the previous query's ancestors and reuse what still applies (false: a
  /// fresh memo per query, as the paper's Type III clears its list). [Default: true]
  bool reuse = true;
};

/// An evaluator of the given type. Type I computes its whole array here (progress and
/// cancellation through `context`), Type IV its upper levels. Throws InputError for bad
/// parameters (R out of range, R2 > R, beta <= 0, NaN corners).
std::unique_ptr<FieldEvaluator> make_evaluator(EvaluatorType type, const FieldParams& params, const EvaluatorOptions& options = {},
                                               const Context& context = quiet_context());

/// One z-plane of the lattice, (2^R+1)^2 values, x fastest: rows in parallel on clones of
/// `field` (Type II: the field itself, one thread, so that its one map serves every query).
void evaluate_plane(FieldEvaluator& field, int z, float* out);

}  // namespace sansui::solid
