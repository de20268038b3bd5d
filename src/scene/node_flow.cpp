// The flow node: routes its heights once (water/flow.hpp: D8 receivers across depressions, the
// receiver stack and the drainage area, with the world's sea level as outlets) and passes the
// heights on with their routing, which the nodes after it that route the same heights (erode,
// select_flow) take instead of routing them again, as fastscapelib's eroders take its flow graph.
// See node_kinds.hpp.
#include "core/params.hpp"
#include "scene/node_kinds.hpp"
#include "water/flow.hpp"

namespace sansui::scene {

/// The heights, routed. [[node]] kind = "flow" (no keys: the outlets are the world's sea level)
struct FlowNode {};
const params::Table<FlowNode>& parameter_table(const FlowNode*) {
  static const auto table = params::Table<FlowNode>("flow", "No parameters: the outlets are the map's edge and the world's sea");
  return table;
}

namespace {

NodeOutput run_flow(const FlowNode&, std::span<const Grid<float>* const> in, const GraphWorld& world, const Context& context) {
  NodeOutput out(*in[0]);
  out.flow = std::make_shared<const water::FlowRouting>(water::route_flow(*in[0], water::Outlets{world.sea_level_m}, context));
  return out;
}

}  // namespace

void add_flow_kinds(std::vector<NodeKind>& kinds) {
  kinds.push_back(kind_of<FlowNode>("flow", "routing",
                                    "The heights unchanged, routed: erode, select_flow and the water outputs (rivers, lakes, "
                                    "flow_map, wetness_map) of this node take the routing instead of routing the heights again",
                                    {{"heights", ValueType::heights, false}}, ValueType::heights, run_flow));
  // The routing beside the heights: receivers and stack (4 bytes a cell each), the filled
  // surface (4) and the drainage area (8); route_flow's scratch about as much again.
  kinds.back().result_bytes_per_cell = 20.0;
  kinds.back().scratch_bytes_per_cell = 48.0;
  kinds.back().seconds = [](const std::any&, const GraphWorld& world) { return 2.5e-7 * world.cells(); };
}

}  // namespace sansui::scene
