// Recipe graphs: checks, order, dot (see graph.hpp).
#include "scene/graph.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {
namespace {

std::string joined(const std::vector<std::string>& items) {
  return fmt::format("{}", fmt::join(items, ", "));
}

std::map<std::string, const GraphNode*> by_id(const std::vector<GraphNode>& nodes) {
  std::map<std::string, const GraphNode*> ids;
  for (const GraphNode& node : nodes) ids.emplace(node.id, &node);
  return ids;
}

/// A cycle through `start`, as ids "a -> b -> a", if there is one.
std::vector<std::string> cycle_from(const std::map<std::string, const GraphNode*>& ids, const GraphNode& start) {
  // Depth first along inputs, remembering the path (an explicit stack: no recursion depth that
  // a file can choose).
  std::vector<std::pair<const GraphNode*, std::size_t>> path{{&start, 0}};
  std::set<std::string> done;
  while (!path.empty()) {
    auto& [node, next] = path.back();
    if (next == node->inputs.size()) {
      done.insert(node->id);
      path.pop_back();
      continue;
    }
    const std::string& input = node->inputs[next++];
    const auto found = ids.find(input);
    if (found == ids.end() || done.count(input) != 0) continue;
    const auto on_path = std::find_if(path.begin(), path.end(), [&](const auto& step) { return step.first->id == input; });
    if (on_path != path.end()) {
      std::vector<std::string> cycle;
      for (auto step = on_path; step != path.end(); ++step) cycle.push_back(step->first->id);
      cycle.push_back(input);
      std::reverse(cycle.begin(), cycle.end());  // along the data: an input before what takes it
      return cycle;
    }
    path.emplace_back(found->second, 0);
  }
  return {};
}

}  // namespace

namespace {

/// Kahn's algorithm over node indices, ready nodes taken in file order (a heap of indices):
/// O((nodes + edges) log nodes). Nodes on or after a cycle are left out.
std::vector<std::size_t> kahn_order(const std::vector<GraphNode>& nodes) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < nodes.size(); ++i) index.emplace(nodes[i].id, i);
  std::vector<std::size_t> waiting(nodes.size(), 0);
  std::vector<std::vector<std::size_t>> takers(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (const std::string& input : nodes[i].inputs)
      if (const auto found = index.find(input); found != index.end()) ++waiting[i], takers[found->second].push_back(i);
  std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>> ready;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (waiting[i] == 0) ready.push(i);
  std::vector<std::size_t> order;
  while (!ready.empty()) {
    const std::size_t i = ready.top();
    ready.pop();
    order.push_back(i);
    for (std::size_t taker : takers[i])
      if (--waiting[taker] == 0) ready.push(taker);
  }
  return order;
}

}  // namespace

const NodeKind& GraphNode::node_kind() const {
  const NodeKind* found = find_node_kind(kind);
  if (found == nullptr) fail("{}: node `{}` has the unknown kind `{}`", where, id, kind);
  return *found;
}

std::vector<std::string> check_graph(const Recipe& recipe) {
  const std::vector<GraphNode>& nodes = recipe.nodes;
  std::vector<std::string> warnings;
  if (nodes.empty()) return warnings;
  if (recipe.source != SourceKind::none)
    fail("{}: a recipe with [[node]] tables has no source: its nodes make the heights (remove source = \"{}\")", nodes.front().where,
         source_name(recipe.source));
  if (!recipe.shape.empty()) fail("a recipe with [[node]] tables has no [[shape]] steps: shape the heights with nodes (stage, erode...)");
  std::map<std::string, const GraphNode*> ids;
  for (const GraphNode& node : nodes) {
    const auto [at, fresh] = ids.emplace(node.id, &node);
    if (!fresh) fail("{}: node id `{}` is used twice (also at {}): ids must differ", node.where, node.id, at->second->where);
  }
  std::vector<std::string> all_ids;
  all_ids.reserve(nodes.size());
  for (const GraphNode& node : nodes) all_ids.push_back(node.id);
  for (const GraphNode& node : nodes) {
    const NodeKind& kind = node.node_kind();
    if (node.inputs.size() < kind.required_inputs() || node.inputs.size() > kind.inputs.size()) {
      std::vector<std::string> slots;
      for (const InputSlot& slot : kind.inputs) slots.push_back(slot.optional ? slot.name + " (optional)" : slot.name);
      fail("{}: node `{}` ({}) takes {} input{}{}; it has {}", node.where, node.id, kind.name,
           kind.required_inputs() == kind.inputs.size() ? fmt::format("{}", kind.inputs.size())
                                                        : fmt::format("{} or {}", kind.required_inputs(), kind.inputs.size()),
           kind.inputs.size() == 1 ? "" : "s", slots.empty() ? "" : " (" + joined(slots) + ")", node.inputs.size());
    }
    for (std::size_t k = 0; k < node.inputs.size(); ++k) {
      const auto input = ids.find(node.inputs[k]);
      if (input == ids.end())
        fail("{}: node `{}` takes input `{}`, which no node has: the ids are {}", node.where, node.id, node.inputs[k], joined(all_ids));
      const ValueType given = input->second->node_kind().output, wanted = kind.inputs[k].type;
      if (given != wanted)
        fail("{}: node `{}` ({}) takes {} as input {} ({}); `{}` ({}, {}) gives {}", node.where, node.id, kind.name,
             value_type_name(wanted), k + 1, kind.inputs[k].name, input->second->id, input->second->kind, input->second->where,
             value_type_name(given));
    }
    try {
      kind.validate(node.params);
    } catch (const InputError& e) {
      fail("{}: node `{}` ({}): {}", node.where, node.id, kind.name, e.what());
    }
  }
  const std::vector<std::size_t> order = kahn_order(nodes);
  if (order.size() != nodes.size()) {
    // Some node is on a cycle or downstream of one: find a cycle from the first node left out.
    std::vector<bool> placed(nodes.size(), false);
    for (std::size_t i : order) placed[i] = true;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (placed[i]) continue;
      const std::vector<std::string> cycle = cycle_from(ids, nodes[i]);
      if (!cycle.empty())
        fail("{}: nodes {} form a cycle: a node cannot take its own result", ids.at(cycle.front())->where, fmt::join(cycle, " -> "));
    }
  }
  // Every output takes heights of one node; a node nothing takes is a warning.
  std::set<std::string> used;
  for (const GraphNode& node : nodes) used.insert(node.inputs.begin(), node.inputs.end());
  for (std::size_t k = 0; k < recipe.outputs.size(); ++k) {
    const GraphNode& node = output_node(recipe, k);
    used.insert(node.id);
    const Output& output = recipe.outputs[k];
    const auto kind = resolved_kind(output);
    if (node.node_kind().output == ValueType::mask && kind != OutputKind::heightmap)
      fail("output {} takes node `{}` ({}), a mask: a mask can only be written as a heightmap", output.file, node.id, node.where);
  }
  for (const GraphNode& node : nodes)
    if (used.count(node.id) == 0)
      warnings.push_back(fmt::format("{}: node `{}` ({}) is used by no other node and no output", node.where, node.id, node.kind));
  return warnings;
}

std::vector<std::string> topological_order(const std::vector<GraphNode>& nodes) {
  const std::vector<std::size_t> order = kahn_order(nodes);
  if (order.size() != nodes.size()) fail("the recipe graph has a cycle");  // check_graph names it
  std::vector<std::string> ids;
  ids.reserve(order.size());
  for (std::size_t i : order) ids.push_back(nodes[i].id);
  return ids;
}

const GraphNode& output_node(const Recipe& recipe, std::size_t output_index) {
  const Output& output = recipe.outputs.at(output_index);
  if (!output.node.empty()) {
    for (const GraphNode& node : recipe.nodes)
      if (node.id == output.node) return node;
    std::vector<std::string> ids;
    for (const GraphNode& node : recipe.nodes) ids.push_back(node.id);
    fail("output {} takes node `{}`, which no node has: the ids are {}", output.file, output.node, joined(ids));
  }
  try {
    return final_node(recipe.nodes);
  } catch (const InputError& e) {
    fail("output {} names no node, and {}", output.file, e.what());
  }
}

const GraphNode& final_node(const std::vector<GraphNode>& nodes) {
  std::set<std::string> taken;
  for (const GraphNode& node : nodes) taken.insert(node.inputs.begin(), node.inputs.end());
  std::vector<const GraphNode*> finals;
  for (const GraphNode& node : nodes)
    if (taken.count(node.id) == 0 && node.node_kind().output == ValueType::heights) finals.push_back(&node);
  if (finals.size() != 1) {
    std::vector<std::string> ids;
    ids.reserve(finals.size());
    for (const GraphNode* node : finals) ids.push_back(node->id);
    fail("the graph has {} final nodes of heights{}: say which with node = \"...\"", finals.size(),
         finals.empty() ? "" : " (" + joined(ids) + ")");
  }
  return *finals.front();
}

std::vector<std::string> ancestors(const std::vector<GraphNode>& nodes, const std::string& target) {
  const auto ids = by_id(nodes);
  std::set<std::string> needed{target};
  std::vector<std::string> todo{target};
  while (!todo.empty()) {
    const std::string id = todo.back();
    todo.pop_back();
    const auto found = ids.find(id);
    if (found == ids.end()) continue;
    for (const std::string& input : found->second->inputs)
      if (needed.insert(input).second) todo.push_back(input);
  }
  std::vector<std::string> ordered;
  for (const std::string& id : topological_order(nodes))
    if (needed.count(id) != 0) ordered.push_back(id);
  return ordered;
}

std::vector<std::string> layers_of(const std::vector<GraphNode>& nodes, const std::string& id) {
  const auto ids = by_id(nodes);
  std::set<std::string> layers;
  // Down the chain of heights inputs while the nodes pass layers on (at most once per node: a
  // cycle, refused by check_graph, cannot loop here).
  std::string at = id;
  for (std::size_t walked = 0; walked <= nodes.size(); ++walked) {
    const auto found = ids.find(at);
    if (found == ids.end()) break;
    const NodeKind& kind = found->second->node_kind();
    layers.insert(kind.layers.begin(), kind.layers.end());
    if (!kind.passes_layers() || found->second->inputs.empty()) break;
    at = found->second->inputs.front();
  }
  return {layers.begin(), layers.end()};
}

std::string graph_dot(const Recipe& recipe) {
  std::string dot = "digraph recipe {\n  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n";
  // A dot string: quotes and backslashes escaped, line breaks as dot's \n.
  const auto quoted = [](const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '\n' ? std::string("\\n") : (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return out + "\"";
  };
  const auto output_box = [&](std::size_t k) {
    const Output& output = recipe.outputs[k];
    const auto kind = resolved_kind(output);
    return fmt::format("  {} [shape=note, label={}];\n", quoted("output:" + output.file),
                       quoted(output.file + "\n" + (kind ? std::string(output_kind_name(*kind)) : std::string("?"))));
  };
  if (recipe.nodes.empty()) {
    // A chain drawn as the graph the evaluator runs it as, where it has one.
    if (std::vector<GraphNode> nodes = chain_as_graph(recipe); !nodes.empty()) {
      Recipe as_graph = recipe;
      as_graph.source = SourceKind::none;
      as_graph.shape.clear();
      as_graph.nodes = std::move(nodes);
      return graph_dot(as_graph);
    }
    // Any other source and its chain of steps.
    std::string previous = "source";
    if (recipe.source != SourceKind::none)
      dot += fmt::format("  source [label={}];\n", quoted(std::string(source_name(recipe.source)) + "\nsource"));
    for (std::size_t k = 0; k < recipe.shape.size(); ++k) {
      const std::string id = fmt::format("shape{}", k + 1);
      const ShapeStep& step = recipe.shape[k];
      dot += fmt::format("  {} [label={}];\n", id,
                         quoted(fmt::format("{} {}\n[[shape]] {}", step.step == StepKind::erode ? "erode" : "stage",
                                            terrain::stage_name(step.stage.stage), k + 1)));
      dot += fmt::format("  {} -> {};\n", previous, id);
      previous = id;
    }
    for (std::size_t k = 0; k < recipe.outputs.size(); ++k) {
      dot += output_box(k);
      if (recipe.source != SourceKind::none) dot += fmt::format("  {} -> {};\n", previous, quoted("output:" + recipe.outputs[k].file));
    }
    return dot + "}\n";
  }
  for (const GraphNode& node : recipe.nodes) {
    const bool mask = node.node_kind().output == ValueType::mask;
    dot +=
        fmt::format("  {} [label={}{}];\n", quoted(node.id), quoted(node.id + "\n" + node.kind), mask ? ", style=\"rounded,dashed\"" : "");
  }
  for (const GraphNode& node : recipe.nodes) {
    const NodeKind& kind = node.node_kind();
    for (std::size_t k = 0; k < node.inputs.size(); ++k)
      dot += fmt::format("  {} -> {} [label={}];\n", quoted(node.inputs[k]), quoted(node.id),
                         quoted(k < kind.inputs.size() ? kind.inputs[k].name : ""));
  }
  for (std::size_t k = 0; k < recipe.outputs.size(); ++k) {
    dot += output_box(k);
    dot += fmt::format("  {} -> {};\n", quoted(output_node(recipe, k).id), quoted("output:" + recipe.outputs[k].file));
  }
  return dot + "}\n";
}

}  // namespace sansui::scene
