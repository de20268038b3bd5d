// The 3-D random fractal field D of Okada, Taga, Yokoi and Toriwaki, "A study on solid texture
// generation by using 3-dimensional random fractal" (1990; seeds/002; SPEC 2): midpoint
// displacement over an octree on the lattice {0..2^R}^3. This header holds what every evaluator
// shares: the parameters, the per-level scales L(n), and the paper's memory formulas C1..C4.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/budget.hpp"
#include "core/params.hpp"

namespace sansui::solid {

/// The deepest lattice: rng::pack holds 21 bits per axis, so coordinates up to 2^20.
inline constexpr int max_levels = 20;

/// Table: solid_params.cpp (section [solid_field]).
struct FieldParams {
  /// Random seed: the same (seed, levels, beta, corners) gives the same field, bit for bit. [Default: 1]
  std::uint64_t seed = 1;
  /// Maximum recursion level R: the lattice is {0..2^R}^3. [Range: 1..20; Type I and II as memory allows] [Default: 8]
  int levels = 8;
  /// Decay constant beta: level n displaces by g * exp(-(n-1) * beta). Larger is smoother. [Range: > 0] [Default: 0.6]
  double beta = 0.6;
  /// Values at the 8 outer corners, index x + 2y + 4z (x, y, z in {0, 1}). [Range: finite] [Default: all 0]
  std::array<float, 8> corners{};

  /// Lattice points per side, 2^R + 1.
  int side() const { return (1 << levels) + 1; }
  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<FieldParams>& parameter_table(const FieldParams*);

/// L(n) = exp(-(n-1) * beta) for n = 0..levels, with L(0) = 1 (paper eq. 2), as floats that are
/// the same bytes on every platform (exact_exp2, not libm).
std::vector<float> displacement_scales(const FieldParams& params);

/// The four evaluators of the paper.
enum class EvaluatorType {
  type1,  ///< Type I: the whole lattice as one array, level by level.
  type2,  ///< Type II: on demand, every computed node memoised in a shared map.
  type3,  ///< Type III: one point from its ancestors only, O(R) memo.
  type4,  ///< Type IV: a Type I array up to level R2, Type III below it.
};

/// "I", "II", "III", "IV".
std::string type_name(EvaluatorType type);
/// The type named "I".."IV" (or 1..4); throws InputError for anything else.
EvaluatorType type_from_name(const std::string& name);

/// Bytes of a Type I array of (2^levels + 1)^3 floats.
std::size_t lattice_bytes(int levels);

/// The paper's memory formulas (Sec. 7-1), in words (one word holds one value or pointer).
/// C1 = N^3, N = 2^R + 1 (eq. 13); C2 = 13 words per node the queries touch (O(N^3), the paper
/// gives no closed form); C3 = 13 * 19 * R (eq. 15); C4 = N2^3 + 13 * 19 * (R - R2) (eq. 16).
double paper_words_c1(int levels);
double paper_words_c2(double nodes);
double paper_words_c3(int levels);
double paper_words_c4(int levels, int r2);

/// Checks that an evaluator of `type` fits in `budget_bytes` of memory (Type I: the whole
/// lattice; Type IV: the level-R2 array; Type II: `type2_nodes` nodes in its map; Type III:
/// always) and that levels and r2 suit the type. Throws InputError saying how much it would need.
void check_fits(EvaluatorType type, const FieldParams& params, int r2, double type2_nodes, std::size_t budget_bytes);

/// Bytes one Type II node takes in its hash map (key, value, list node and bucket), for estimates.
inline constexpr std::size_t type2_bytes_per_node = 40;

/// Nodes the Type II maps hold at the end of one picture of size_px x size_px pixels (a slice,
/// sphere or cube; each thread has its own map): a pixel's eight lattice corners and their
/// ancestors, about 27 nodes a pixel for each level past 7 (measured at R = 12..20, sizes
/// 64..256 px), and never more than the whole lattice.
double type2_picture_nodes(int levels, int size_px);

/// What a Type II map of `nodes` nodes needs: type2_bytes_per_node a node, and about a
/// microsecond a node to compute it (measured with slices at R = 12..20). For budget::check.
budget::Cost type2_cost(const FieldParams& params, double nodes, std::string_view outputs);

}  // namespace sansui::solid
