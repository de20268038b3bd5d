#include "water/flow.hpp"

#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "water/rivers.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

TEST(Flow, StackPutsEveryReceiverBeforeItsDonors) {
  const Heightfield ground = test::midpoint_terrain(65, 10.0);
  const FlowRouting flow = route_flow(ground, {});
  ASSERT_EQ(flow.stack.size(), ground.size());
  std::vector<int> position(ground.size(), -1);
  for (std::size_t k = 0; k < flow.stack.size(); ++k) {
    ASSERT_EQ(position[static_cast<std::size_t>(flow.stack[k])], -1) << "a cell twice";
    position[static_cast<std::size_t>(flow.stack[k])] = static_cast<int>(k);
  }
  for (std::size_t i = 0; i < ground.size(); ++i) EXPECT_LE(position[static_cast<std::size_t>(flow.receiver.data()[i])], position[i]);
}

TEST(Flow, DrainageAreaOfAValleyCountsItsCells) {
  // A V-shaped valley draining south: the valley floor at x = 3 gathers its whole row span.
  Heightfield ground(7, 6, 0.0f, 2.0);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 7; ++x) ground(x, y) = static_cast<float>(10 * std::abs(x - 3) + 10 - y);
  const FlowRouting flow = route_flow(ground, {});
  // The 5 x 4 interior cells drain sideways to the floor, which runs south to the edge.
  EXPECT_DOUBLE_EQ(flow.area_m2(3, 1), 5 * 4.0);   // its row
  EXPECT_DOUBLE_EQ(flow.area_m2(3, 4), 20 * 4.0);  // all four rows
  EXPECT_DOUBLE_EQ(flow.area_m2(3, 5), 21 * 4.0);  // and the outlet itself
  // Everything leaves through outlets: their areas add up to the map.
  double total = 0.0;
  for (std::size_t i = 0; i < ground.size(); ++i)
    if (flow.receiver.data()[i] == static_cast<CellIndex>(i)) total += flow.area_m2.data()[i];
  EXPECT_DOUBLE_EQ(total, static_cast<double>(ground.size()) * 4.0);
}

TEST(Flow, MultipleFlowDirectionsConserveArea) {
  const Heightfield ground = test::midpoint_terrain(65, 10.0, 4);
  const Heightfield surface = fill_depressions_epsilon(ground, {});
  const Grid<double> area = mfd_drainage_area(surface, {}, 1.1);
  const Grid<CellIndex> receiver = d8_receivers(surface, {});
  double total = 0.0;
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x)
      if (is_outlet(surface, {}, x, y)) total += area(x, y);
  EXPECT_NEAR(total, 65.0 * 65.0 * 100.0, 1e-6);
  // Spread flow: MFD gives fewer cells of large area than D8 on hillslopes, but each cell has at least its own area.
  for (double a : area.values()) EXPECT_GE(a, 100.0);
}

TEST(Flow, BasinsFollowReceivers) {
  const Heightfield ground = test::midpoint_terrain(65, 10.0, 5);
  const FlowRouting flow = route_flow(ground, {});
  const Grid<std::int32_t> basin = basin_labels(flow.receiver, flow.stack);
  for (std::size_t i = 0; i < ground.size(); ++i) {
    EXPECT_GT(basin.data()[i], 0);
    EXPECT_EQ(basin.data()[i], basin.data()[flow.receiver.data()[i]]);
  }
}

TEST(Flow, RiversRunDownstreamWithStrahlerOrderThatNeverDecreases) {
  const Heightfield ground = test::midpoint_terrain(129, 10.0, 6);
  const FlowRouting flow = route_flow(ground, {});
  FlowParams params;
  params.channel_area_m2 = 50 * 100.0;
  const RiverNetwork network = extract_rivers(flow, params);
  ASSERT_FALSE(network.rivers.empty());
  int highest = 0;
  for (const River& river : network.rivers) {
    ASSERT_GE(river.cells.size(), 1u);
    for (std::size_t k = 0; k + 1 < river.cells.size(); ++k) {
      EXPECT_EQ(flow.receiver.data()[river.cells[k]], river.cells[k + 1]);
      EXPECT_EQ(network.strahler.data()[river.cells[k]], river.strahler_order);
      EXPECT_LE(network.strahler.data()[river.cells[k]], network.strahler.data()[river.cells[k + 1]]);
    }
    EXPECT_GE(river.area_m2, params.channel_area_m2);
    EXPECT_NEAR(river.discharge_m3_per_s, river.area_m2 * 0.5 / (365.25 * 86400.0), 1e-12 * river.area_m2);
    highest = std::max(highest, river.strahler_order);
  }
  EXPECT_GE(highest, 3);
  for (std::size_t i = 0; i < ground.size(); ++i) EXPECT_EQ(network.channel.data()[i] != 0, network.strahler.data()[i] != 0);
}

/// Braun & Willett's stack as they build it, serially: donor lists in raster order, depth first
/// from each base level in raster order.
std::vector<CellIndex> serial_stack(const Grid<CellIndex>& receiver) {
  const std::size_t n = receiver.size();
  const CellIndex* rec = receiver.data();
  std::vector<std::vector<CellIndex>> donors(n);
  for (std::size_t i = 0; i < n; ++i)
    if (rec[i] != static_cast<CellIndex>(i)) donors[static_cast<std::size_t>(rec[i])].push_back(static_cast<CellIndex>(i));
  std::vector<CellIndex> stack, todo;
  for (std::size_t root = 0; root < n; ++root) {
    if (rec[root] != static_cast<CellIndex>(root)) continue;
    todo.push_back(static_cast<CellIndex>(root));
    while (!todo.empty()) {
      const CellIndex c = todo.back();
      todo.pop_back();
      stack.push_back(c);
      for (CellIndex d : donors[static_cast<std::size_t>(c)]) todo.push_back(d);
    }
  }
  return stack;
}

TEST(Flow, ParallelStackIsTheSerialDepthFirstStack) {
  // Sea cells and pits carved over their passes: many trees, receivers that are not D8's.
  for (int size : {33, 257}) {
    const Heightfield ground = test::midpoint_terrain(size, 10.0, 11);
    const FlowRouting flow = route_flow(ground, {50.0});
    EXPECT_EQ(flow.stack, serial_stack(flow.receiver)) << size;
  }
}

TEST(Flow, AStackOfReceiversThatLeaveTheEdgeIsTheSerialOne) {
  // Receivers made by hand may send an edge cell to its neighbour: its donors are then found
  // with bounds checks (no read outside the grid; the sanitizer build would see one).
  const Heightfield ground = test::midpoint_terrain(33, 10.0, 4);
  Grid<CellIndex> receiver = route_flow(ground, {}).receiver;
  receiver(0, 5) = 4 * 33;          // west edge, row 5, to row 4
  receiver(32, 32) = 32 * 33 + 31;  // the south-east corner to its west neighbour
  EXPECT_EQ(receiver_stack(receiver), serial_stack(receiver));
}

TEST(Flow, RoutingIntoKeptMemoryGivesTheSameBytes) {
  // An erosion run routes into the same memory every step, grids of other sizes in between.
  FlowRouting kept;
  RoutingScratch scratch;
  for (int size : {129, 65, 129}) {
    const Heightfield ground = test::midpoint_terrain(size, 10.0, size);
    const FlowRouting fresh = route_flow(ground, {0.0});
    route_flow(ground, {0.0}, kept, scratch);
    EXPECT_EQ(kept.stack, fresh.stack) << size;
    EXPECT_EQ(sansui::test::fnv1a(std::as_const(kept).receiver.values()), sansui::test::fnv1a(fresh.receiver.values())) << size;
    EXPECT_EQ(sansui::test::fnv1a(std::as_const(kept).surface.values()), sansui::test::fnv1a(fresh.surface.values())) << size;
    EXPECT_EQ(sansui::test::fnv1a(std::as_const(kept).area_m2.values()), sansui::test::fnv1a(fresh.area_m2.values())) << size;
  }
}

TEST(Flow, SameBytesWithOneAndTwoThreads) {
  const Heightfield ground = test::midpoint_terrain(257, 10.0, 7);
  const auto run = [&] {
    const FlowRouting flow = route_flow(ground, {100.0});
    const Grid<double> mfd = mfd_drainage_area(flow.surface, {100.0}, 1.1);
    return sansui::test::fnv1a(flow.surface.values()) ^ sansui::test::fnv1a(flow.receiver.values()) ^
           sansui::test::fnv1a(flow.area_m2.values()) ^ sansui::test::fnv1a(mfd.values()) ^
           sansui::test::fnv1a(std::span<const CellIndex>(flow.stack));
  };
  test::expect_same_bytes_with_one_and_two_threads(run);
}

}  // namespace
}  // namespace sansui::water
