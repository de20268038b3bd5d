// What the serial build (SANSUI_PARALLEL_SERIAL: every parallel loop on one thread, in order) and
// this build both compute, by name, as hashes of their bytes: the loops with per-thread scratch
// and per-chunk work of terrain and water.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"
#include "water/erode.hpp"
#include "water/flow.hpp"

namespace sansui::test {

struct SerialBuildCase {
  std::string name;
  std::function<std::uint64_t()> hash;
};

/// A default midpoint terrain of 2^k + 1 samples, 30 m cells.
inline Heightfield serial_build_terrain(int size) {
  terrain::MidpointParams params;
  params.seed = 11;
  Heightfield h = terrain::generate_midpoint(params, size);
  h.cell_size_m = 30.0;
  return h;
}

template <class T>
std::uint64_t grid_hash(const Grid<T>& grid) {
  return fnv1a(grid.values());
}

inline std::vector<SerialBuildCase> serial_build_cases() {
  // 1025: large enough for midpoint's blocks, each refined in its thread's scratch.
  auto midpoint = [] { return grid_hash(serial_build_terrain(1025)); };
  auto routing = [] {
    const water::FlowRouting flow = water::route_flow(serial_build_terrain(257), water::Outlets{});
    std::uint64_t hash = grid_hash(flow.surface);
    hash ^= grid_hash(flow.receiver) * 3;
    hash ^= fnv1a(std::span<const water::CellIndex>(flow.stack)) * 5;
    return hash ^ grid_hash(flow.area_m2) * 7;
  };
  auto erosion = [] {
    const water::ErosionResult eroded = water::erode(serial_build_terrain(257), water::ErosionChainParams{});
    std::uint64_t hash = grid_hash(eroded.heights);
    hash ^= grid_hash(eroded.eroded_m) * 3;
    return hash ^ grid_hash(eroded.deposited_m) * 5;
  };
  return {{"midpoint_1025", midpoint}, {"flow_routing_257", routing}, {"default_erosion_257", erosion}};
}

}  // namespace sansui::test
