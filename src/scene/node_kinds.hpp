// The kinds of node a recipe graph is made of (scene/graph.hpp), registered once each: a name,
// the types of its inputs and output, its parameter table (the keys of its [[node]] table, with
// unit, range, default and help, as every params struct has) and what it computes. Checks,
// docs, `sansui params` and `--graph` come from this list; adding a kind is one file's worth of
// code and one line in all_node_kinds().
//
//   sources    midpoint, constant, file, contour, contour_map, mesh -> heights
//   shaping    stage, erode, terrace, smooth, scale, clamp  heights (+ an optional mask) -> heights
//   routing    flow                                        heights -> the same heights, routed
//   masks      select_height, select_slope, select_curvature, select_flow, mask_polygon -> mask
//   combining  blend (a, b, mask), max, min, add
//
// Heights are metres on the world's grid; masks are grids of 0..1 of their own type, so a mask
// wired where heights are expected (or the other way round) is refused before any work. A flow
// node's heights carry their flow routing (FlowRouting, in memory): the kinds that route their
// heights input (erode, select_flow) take it there instead of routing the same heights again.
#pragma once

#include <any>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "core/triangle_mesh.hpp"
#include "core/world.hpp"

namespace sansui::water {
struct FlowRouting;
}
namespace sansui::contour {
struct ContourTree;
}

namespace sansui::scene {

/// What flows along an edge of the graph.
enum class ValueType { heights, mask };
std::string_view value_type_name(ValueType type);

/// The world every node of a graph receives: the core World (grid and sea level, from the
/// recipe's [world], or the grid its source reads where it has none) and what a recipe adds.
struct GraphWorld : World {
  /// Relative file names of nodes start here (the recipe's directory).
  std::string base_dir;
  /// The level a midpoint node puts its land_fraction above: the sea level (unset), or 0 m in a
  /// chain recipe before version 3, whose terrain was generated so whatever its steps' sea level.
  /// [Units: m]
  std::optional<double> midpoint_datum_m;
  /// The recipe version whose erosion model the erode nodes take (water/erode.hpp): a chain's
  /// own (model 1 for version 1), a graph's of [[node]] tables at least 2 (they never took model
  /// 1); 0: this sansui's.
  int version = 0;
  /// The level erosion takes as its base where it is above the sea: the flat plain round a
  /// contour mountain, in a world that takes its grid from that source (NodeOutput::base_level_m).
  /// [Units: m]
  std::optional<double> base_level_m;

  /// The world's facts as text, for cache keys (base_dir is not a fact of the result).
  std::string key() const;
  /// A node's file name, relative to base_dir unless absolute.
  std::filesystem::path resolve(const std::string& name) const;
};

/// What one run of a node makes: its grid (heights or a mask) and, for some kinds, layers beside
/// it that outputs write (an erode node's metres eroded and deposited: erosion_map and
/// deposition_map). A kind of group "shaping" passes on the layers of its heights input, and adds
/// its own to them (two erode nodes in a row: their metres summed, as two [[shape]] steps).
struct NodeOutput {
  NodeOutput(Grid<float> made) : grid(std::move(made)) {}  // NOLINT(google-explicit-constructor): most kinds make one grid
  Grid<float> grid;
  std::map<std::string, Grid<float>> layers;
  /// A flow node's: the routing of `grid` with the world's sea level as outlets (water/flow.hpp).
  std::shared_ptr<const water::FlowRouting> flow;
  /// Figures of the run that the outputs' sidecars carry (a source's: a contour map's lines and
  /// spot heights, as its chain source reports them); a JSON object, or null for none.
  nlohmann::json statistics;
  /// Lines of the run's report (a mesh's steps), as its chain source reports them.
  std::vector<std::string> lines;
  /// A mesh node's fine mesh, in a world without a grid (a chain's mesh source): the mesh output
  /// writes it. Kept in memory only.
  std::shared_ptr<const TriangleMesh> mesh;
  /// A contour node's contour lines, in a world without a grid (a chain's contour source): the
  /// contours and map outputs write them. Kept in memory only.
  std::shared_ptr<const contour::ContourTree> tree;
  /// A source's own base level for erosion, above the sea (the flat plain round a contour
  /// mountain): a world without a grid takes it from its sources. [Units: m]
  std::optional<double> base_level_m;
  /// Keys the node left unset whose values its run chose (a contour node's offset and z0), for
  /// the sidecars of the chain recipe it stands for.
  std::map<std::string, double> settled;
};

/// The layers of an erode node: metres carved and laid down (erosion_map, deposition_map).
inline constexpr std::string_view eroded_layer = "eroded_m", deposited_layer = "deposited_m";

/// One input of a node kind: its type, and whether it may be left out.
struct InputSlot {
  std::string name;  ///< "heights", "mask", "a", ...
  ValueType type = ValueType::heights;
  bool optional = false;
};

/// A node kind. Its parameters are held type-erased (std::any of the kind's params struct);
/// the functions below know the struct.
struct NodeKind {
  std::string name;
  std::string group;  ///< "source", "shaping", "mask", "combining"
  std::string help;   ///< one line
  std::vector<InputSlot> inputs;
  ValueType output = ValueType::heights;
  /// The names of the layers its runs make beside the grid (NodeOutput::layers).
  std::vector<std::string> layers;
  /// The rows of its parameter table, for docs and messages.
  std::vector<params::ParamInfo> rows;

  std::function<std::any()> make;  ///< the params with their defaults
  /// Sets one key from a checked value (params::check passed); false when the kind has no such key.
  std::function<bool(std::any& params, std::string_view key, const params::Value& value)> set;
  std::function<params::Value(const std::any& params, std::string_view key)> get;
  /// Throws InputError naming the first bad value (values that depend on each other).
  std::function<void(const std::any& params)> validate;
  /// Computes the node: `inputs` in slot order, null for a missing optional one.
  std::function<NodeOutput(const std::any& params, std::span<const Grid<float>* const> inputs, const GraphWorld& world,
                           const Context& context)>
      run;
  /// For a kind that routes its heights input (the first): run, taking `flow`, the routing those
  /// heights carry (a flow node's), instead of routing them again. Unset: run.
  std::function<NodeOutput(const std::any& params, std::span<const Grid<float>* const> inputs, const water::FlowRouting& flow,
                           const GraphWorld& world, const Context& context)>
      run_routed;

  /// What one run costs beyond its result grid, for the graph's one budget (Evaluator checks the
  /// whole graph's memory and time before any node runs): scratch bytes per cell, and seconds on
  /// the reference machine (2 cores, Release). The defaults fit a pointwise node; heavier kinds
  /// set their own where they are registered.
  double scratch_bytes_per_cell = 8.0;
  /// What its result holds beyond its grid and layers (a flow node's routing), per cell.
  double result_bytes_per_cell = 0.0;
  std::function<double(const std::any& params, const GraphWorld& world)> seconds = [](const std::any&, const GraphWorld& world) {
    return 2e-8 * world.cells();
  };

  const params::ParamInfo* row(std::string_view key) const;
  /// Every key set to its value, unset ones left out: the node's canonical form (sidecars, cache keys).
  nlohmann::json to_json(const std::any& params) const;
  std::size_t required_inputs() const;
  /// Whether it passes on the layers of its heights input (the shaping kinds, and flow, whose
  /// heights are its input's).
  bool passes_layers() const { return group == "shaping" || group == "routing"; }
};

/// Every node kind, in the order docs list them.
const std::vector<NodeKind>& all_node_kinds();

/// The kind of this name, or null.
const NodeKind* find_node_kind(std::string_view name);

/// The registered kinds, one function per file that defines them (node_terrain.cpp,
/// node_mesh.cpp, node_masks.cpp).
void add_terrain_kinds(std::vector<NodeKind>& kinds);
void add_mesh_kinds(std::vector<NodeKind>& kinds);
void add_mask_kinds(std::vector<NodeKind>& kinds);
void add_flow_kinds(std::vector<NodeKind>& kinds);

/// A NodeKind whose params are the struct P with its parameter table (params::table_of<P>()).
template <class P>
NodeKind kind_of(std::string name, std::string group, std::string help, std::vector<InputSlot> inputs, ValueType output,
                 std::function<NodeOutput(const P&, std::span<const Grid<float>* const>, const GraphWorld&, const Context&)> run) {
  NodeKind kind;
  kind.name = std::move(name), kind.group = std::move(group), kind.help = std::move(help);
  kind.inputs = std::move(inputs), kind.output = output;
  const params::Table<P>& table = params::table_of<P>();
  for (const auto& row : table.rows)
    if (row.exposed) kind.rows.push_back(row);
  kind.make = [] { return std::any(P{}); };
  kind.set = [&table](std::any& params, std::string_view key, const params::Value& value) {
    const auto* row = table.find(key);
    if (row == nullptr || !row->exposed) return false;
    row->set(std::any_cast<P&>(params), value);
    return true;
  };
  kind.get = [&table](const std::any& params, std::string_view key) {
    const auto* row = table.find(key);
    return row == nullptr ? params::Value{} : row->get(std::any_cast<const P&>(params));
  };
  kind.validate = [](const std::any& params) { params::validate(std::any_cast<const P&>(params)); };
  kind.run = [run = std::move(run)](const std::any& params, std::span<const Grid<float>* const> in, const GraphWorld& world,
                                    const Context& context) { return run(std::any_cast<const P&>(params), in, world, context); };
  return kind;
}

/// Sets kind.run_routed (see there) from a function of the kind's params struct P.
template <class P>
void set_run_routed(
    NodeKind& kind,
    std::function<NodeOutput(const P&, std::span<const Grid<float>* const>, const water::FlowRouting&, const GraphWorld&, const Context&)>
        run) {
  kind.run_routed = [run = std::move(run)](const std::any& params, std::span<const Grid<float>* const> in, const water::FlowRouting& flow,
                                           const GraphWorld& world, const Context& context) {
    return run(std::any_cast<const P&>(params), in, flow, world, context);
  };
}

}  // namespace sansui::scene
