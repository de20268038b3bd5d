// Recipes as graphs (SPEC 3.8): [[node]] tables, each with an id, a kind (scene/node_kinds.hpp),
// the ids of its inputs and the kind's parameters, on one [world]; outputs name the node whose
// heights they write. Checked as a whole before any work: every id once, every input an id of
// the recipe, the right number and types of inputs (a mask is never taken for heights), no
// cycle; a node that nothing uses is a warning.
//
//   [world]                [[node]]                  [[node]]                 [[output]]
//   size = 1025            id = "hills"              id = "eroded"            file = "t.png"
//   cell = 10.0            kind = "midpoint"         kind = "erode"           node = "eroded"
//                          seed = 3                  inputs = ["hills"]
#pragma once

#include <any>
#include <string>
#include <vector>

#include "scene/node_kinds.hpp"

namespace sansui::scene {

struct Recipe;

/// One node of a recipe graph.
struct GraphNode {
  std::string id;
  std::string kind;                 ///< a name of all_node_kinds()
  std::vector<std::string> inputs;  ///< ids, in the kind's slot order
  std::any params;                  ///< the kind's params struct
  std::string where;                ///< "scene.toml:12": where the node was read, for messages

  const NodeKind& node_kind() const;
};

/// Checks the graph of `recipe` (see above): throws InputError naming file:line, the node ids
/// and what is allowed; returns the warnings (unused nodes).
std::vector<std::string> check_graph(const Recipe& recipe);

/// The node ids in an order where every node comes after its inputs (file order among equals).
std::vector<std::string> topological_order(const std::vector<GraphNode>& nodes);

/// The graph's one final node of heights: the one no other node takes as input. Throws
/// InputError when there is not exactly one.
const GraphNode& final_node(const std::vector<GraphNode>& nodes);

/// The node an output takes: its `node`, or the graph's final node.
const GraphNode& output_node(const Recipe& recipe, std::size_t output_index);

/// The names of the layers node `id`'s result carries (NodeOutput): its kind's own and, for a
/// shaping node, those of its heights input.
std::vector<std::string> layers_of(const std::vector<GraphNode>& nodes, const std::string& id);
/// The ids of `target` and every node it depends on, in topological order.
std::vector<std::string> ancestors(const std::vector<GraphNode>& nodes, const std::string& target);

/// The graph a chain recipe (a source and [[shape]] steps, its data-dependent defaults filled in)
/// is read as: the source as a node named after it, then a node per step ("erode-1", "stage-2"),
/// each taking the one before. Empty where a chain has no node form yet: sources other than
/// midpoint, file, contour_map and mesh, tiles, levels of detail, windows of a larger world, and recipes before
/// version 3 whose steps give different sea levels; those still run as chains. Run it on
/// chain_world.
std::vector<GraphNode> chain_as_graph(const Recipe& resolved);

/// The world a recipe's [[node]] graph runs on: its [world] size, cell and sea level, and its
/// directory for the nodes' files.
GraphWorld graph_world(const Recipe& recipe);

/// The world a chain's graph runs on: the recipe's, with its steps' one sea level, and for a
/// recipe before version 3 its midpoint terrain generated around 0 m and version 1's erosion
/// model; a file, contour_map or mesh source's world has no grid of its own and takes its source's. For a chain
/// chain_as_graph reads as a graph.
GraphWorld chain_world(const Recipe& resolved);

/// The recipe as a Graphviz dot graph: its nodes (masks dashed), their edges and its outputs.
/// A recipe without [[node]] tables is drawn as the graph it is read as: its source, its shaping
/// steps in a chain, its outputs.
std::string graph_dot(const Recipe& recipe);

}  // namespace sansui::scene
