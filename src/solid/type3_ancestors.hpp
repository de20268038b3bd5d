// Types III and IV of Okada, Taga, Yokoi, Toriwaki (1990; seeds/002, Sec. 5 and 6; SPEC 2).
//
// Type III computes one lattice point from its ancestors only. Because a node's Gaussian is a
// pure function of its coordinates (the paper's eq. 12), nothing but the ancestors of the wanted
// point needs to be known. At each level l the point lies in one cube of the level-(l-1)
// lattice; that cube's 19 new nodes (12 edge midpoints, 6 face centres, 1 centre) are all the
// ancestors level l can contribute, and its 8 corners are nodes of the cube one level up. So the
// memo is one 3x3x3 block of values per level: O(R) memory (the paper's C3 = 13*19*R words; here
// 27 floats and an origin per level), inside the evaluator, never allocated per query.
//
// A cube is computed whole when the walk enters it: its 19 Gaussians in one vectorised batch,
// then edges, faces and centre in the order of node_rules.hpp. That costs about as much as two
// or three Gaussians computed one at a time, and leaves every node of the cube ready for the
// next queries.
//
// Reuse: the memo keeps the previous query's cubes. A new query keeps every level whose cube
// still contains it (and lies inside the kept cube above) and recomputes only the levels below.
// For queries in a coherent order (raster order, along a surface) most levels are kept. With
// reuse off, every query recomputes its whole chain, as the paper's Type III clears its list.
//
// Type IV is the same walk starting below level R2, whose nodes come from a Type I array.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "solid/evaluator.hpp"
#include "solid/volume.hpp"

namespace sansui::solid {

class AncestorEvaluator final : public FieldEvaluator {
 public:
  /// Type III when `upper` is the 2x2x2 lattice of the corners (levels 0), Type IV when it is a
  /// Type I array of levels R2 of the same field. [Range: upper->levels() <= params.levels]
  AncestorEvaluator(const FieldParams& params, std::shared_ptr<const Volume> upper, bool reuse);

  float at(int x, int y, int z) override;
  std::unique_ptr<FieldEvaluator> clone() const override;
  std::size_t memory_bytes() const override;
  std::size_t peak_memory_bytes() const override { return memory_bytes(); }
  EvaluatorType type() const override { return r2_ == 0 ? EvaluatorType::type3 : EvaluatorType::type4; }

  /// Values per level of the memo: the 19 new nodes of the level's cube and its 8 corners.
  static constexpr int nodes_per_level = 27;
  /// Nodes held in the memo now; never more than nodes_per_level * (R - R2).
  int memo_nodes() const;
  /// Bytes of the memo (fixed at construction).
  std::size_t memo_bytes() const;
  /// Cubes computed so far (each: 19 nodes): the work the memo did not save.
  std::uint64_t cubes_computed() const { return cubes_computed_; }

 private:
  /// One level's cube: its origin (lattice units) and its 3x3x3 nodes, slot = i + 3j + 9k.
  struct LevelMemo {
    std::array<int, 3> origin{};
    std::array<float, 27> values{};
  };

  void walk_to(int x, int y, int z, int level);
  void compute_cube(int level);

  std::shared_ptr<const Volume> upper_;
  int levels_;
  int r2_;
  bool reuse_;
  int deepest_ = 0;  // levels r2_+1 .. deepest_ hold cubes
  std::uint64_t key_;
  std::uint64_t cubes_computed_ = 0;
  std::array<float, max_levels + 1> scales_{};
  std::array<LevelMemo, max_levels + 1> memo_{};
};

/// The lattice of the 8 corners (levels 0): what Type III starts from.
std::shared_ptr<const Volume> corner_volume(const FieldParams& params);

}  // namespace sansui::solid
