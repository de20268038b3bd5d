// Scratch memory of flow routing, kept between the routings of one erosion run: a step at 4097 x
// 4097 touches about a gigabyte of working arrays, and taking it afresh from the system every
// step cost a third of the step in page faults.
#pragma once

#include <cstdint>
#include <vector>

#include "water/neighbours.hpp"

namespace sansui::water {

/// Working arrays of route_flow. Their contents mean nothing between calls; they only keep their
/// memory, so that routing a grid of the size routed before allocates nothing.
struct RoutingScratch {
  std::vector<std::int32_t> basin;                  ///< basin label of every cell
  std::vector<CellIndex> pit;                       ///< root cell of every basin
  std::vector<std::int32_t> pits_per_block;         ///< pits counted per block of rows
  std::vector<std::vector<CellIndex>> stack_parts;  ///< per thread: the stack runs it built
  std::vector<std::uint8_t> donors;                 ///< per cell: which neighbours drain into it
};

}  // namespace sansui::water
