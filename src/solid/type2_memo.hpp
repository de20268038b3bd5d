// Type II of Okada, Taga, Yokoi, Toriwaki (1990; seeds/002, Sec. 4; SPEC 2): nodes are computed
// on demand, from their parents (Sec. 4-1: the neighbours at distance 2^b along the active axes),
// and every computed node is memoised for all later queries.
//
// The paper keeps the nodes in a linear list (each entry: coordinates, value, levels and six
// pointers to the parents, 13 words) and searches it for every parent, so a look-up costs time
// proportional to the list's length and covering all N^3 points costs O(N^6); Sec. 5 names that
// search as Type II's problem. A hash map keyed by the packed coordinates finds a node in
// expected O(1), which keeps Type II usable; the pointers are not needed, since the parents'
// coordinates follow from the node's own (eqs. 9, 10).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "solid/evaluator.hpp"

namespace sansui::solid {

class MemoEvaluator final : public FieldEvaluator {
 public:
  explicit MemoEvaluator(const FieldParams& params);
  ~MemoEvaluator() override;

  float at(int x, int y, int z) override;
  /// A new evaluator with its own, empty map (the map is shared by the queries of one thread).
  std::unique_ptr<FieldEvaluator> clone() const override;
  std::size_t memory_bytes() const override;
  std::size_t peak_memory_bytes() const override;
  EvaluatorType type() const override { return EvaluatorType::type2; }

  /// Nodes in the map.
  std::size_t nodes() const;

 private:
  struct Map;
  float compute(int x, int y, int z, int level);

  std::unique_ptr<Map> map_;
  std::uint64_t key_;
  std::vector<float> scales_;
};

}  // namespace sansui::solid
