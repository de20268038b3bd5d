// The one evaluator of recipe graphs (SPEC 3.8): it runs the nodes a result needs in dependency
// order, independent branches at once, and keeps each node's result under a key of everything
// the result depends on: the node's kind, its parameters, the contents of files it reads, the
// keys of its inputs, the world and the library's version. A node whose key is unchanged is not
// run again: in memory for the life of the evaluator (the viewer's rebuilds), and on disk
// between runs with a cache directory (`sansui run --cache DIR`).
//
// A cache entry holds its full key, its grid and a checksum; an entry that is corrupt, cut
// short or written under another key or version is ignored and rebuilt, never trusted. Results
// are the same bytes with or without the cache, and with any number of threads.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"
#include "scene/graph.hpp"

namespace sansui::scene {

/// What a node reports beside its grid, for the outputs (NodeOutput::statistics and lines).
struct Report {
  nlohmann::json statistics;
  std::vector<std::string> lines;
  std::optional<double> base_level_m;     ///< NodeOutput::base_level_m
  std::map<std::string, double> settled;  ///< NodeOutput::settled

  bool empty() const { return (!statistics.is_object() || statistics.empty()) && lines.empty() && !base_level_m && settled.empty(); }
};

/// What a node's result holds: its grid, and the layers it carries beside it (NodeOutput): its
/// own and, for a shaping node, those of its heights input (summed where both have one).
struct NodeProducts {
  std::shared_ptr<const Grid<float>> grid;
  std::map<std::string, std::shared_ptr<const Grid<float>>> layers;
  /// A flow node's routing of `grid` (NodeOutput::flow), while it is in memory: a result read
  /// from disk has none, and the nodes after it route the heights themselves (the same bytes).
  std::shared_ptr<const water::FlowRouting> flow;
  /// What a source reports (NodeOutput::statistics and lines) and a mesh node's fine mesh, passed
  /// on by the shaping nodes after it. Null: none.
  std::shared_ptr<const Report> report;
  std::shared_ptr<const TriangleMesh> mesh;
  /// A contour node's contour lines (NodeOutput::tree), passed on as the mesh is.
  std::shared_ptr<const contour::ContourTree> tree;
};

class Evaluator {
 public:
  /// `cache_dir`: where results are kept between runs; empty for memory only. A directory that
  /// cannot be made or written is left out with a warning (warnings()), and the run goes on.
  explicit Evaluator(std::filesystem::path cache_dir = {});

  /// The results of the nodes `targets` (ids) of `nodes` on `world`, computing what the caches
  /// do not hold. Throws InputError (bad input), Cancelled.
  std::map<std::string, NodeProducts> evaluate(const std::vector<GraphNode>& nodes, const GraphWorld& world,
                                               const std::vector<std::string>& targets, const Context& context = quiet_context());

  /// The grid `compute` makes, kept under `key` (the whole text of everything it depends on) in
  /// the same caches as the nodes' results; `label` counts its runs. For results that are not a
  /// graph's nodes: the terrain of a recipe with a source, the coarse eroded world its tiles share.
  std::shared_ptr<const Grid<float>> cached(const std::string& label, const std::string& key, const std::function<Grid<float>()>& compute);

  /// A product that is not a grid (a scene's rock texture, sky, water or plants: scene_parts.hpp),
  /// kept in memory under `label` and `key` (the text of everything it is made from) with the
  /// results and in their budget, `bytes` its size; `label` counts its runs.
  template <class T, class Make>
  std::shared_ptr<const T> product(const std::string& label, const std::string& key, Make make, std::size_t (*bytes)(const T&)) {
    const std::string entry = "product " + label + "|" + key;
    if (std::shared_ptr<const void> found = kept_product(entry)) return std::static_pointer_cast<const T>(found);
    auto made = std::make_shared<const T>(make());
    keep_product(label, entry, made, bytes(*made));
    return made;
  }

  /// Keeps at most about `bytes` of results in memory, dropping the least recently used first
  /// (a result in use stays alive with its user). Unlimited by default; the viewer, whose edits
  /// make a new terrain each time, bounds it.
  void keep_in_memory(std::size_t bytes);

  /// Forgets every result held in memory (not those on disk).
  void forget_memory();

  /// Forgets the result of node `id` (the next evaluate runs it, and so everything after it).
  void invalidate(const std::string& id);

  /// How many times each node id ran, and how many results came from each cache.
  struct Counters {
    std::map<std::string, int> runs;
    int memory_hits = 0, disk_hits = 0, disk_writes = 0;
  };
  const Counters& counters() const { return counters_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// The key of a node's result (hex), as the caches file it.
  static std::string key_text(const GraphNode& node, const GraphWorld& world, const std::vector<std::string>& input_keys);

 private:
  /// The entry of `key`, if it is whole and of `size` (width, height) when that is known.
  std::shared_ptr<const Grid<float>> from_disk(const std::string& key, std::optional<std::pair<int, int>> size = std::nullopt,
                                               std::shared_ptr<const Report>* report = nullptr);
  void to_disk(const std::string& key, const Grid<float>& grid, const Report* report = nullptr);
  /// One node at `key`: from the caches when its grid and every layer of `layer_names` are
  /// there, else run (its own layers, before the inherited ones are added).
  NodeProducts node_result(const GraphNode& node, const std::string& key, const std::vector<std::string>& layer_names,
                           const std::map<std::string, NodeProducts>& results, const GraphWorld& world, const Context& context);

  std::filesystem::path cache_dir_;
  struct Kept {
    NodeProducts result;  ///< without layers: each is kept under its own key
    std::uint64_t last_use = 0;
    std::shared_ptr<const void> product;  ///< or a product (product()), of product_bytes
    std::size_t product_bytes = 0;
    std::size_t bytes() const;
  };
  std::shared_ptr<const void> kept_product(const std::string& entry);
  void keep_product(const std::string& label, const std::string& entry, std::shared_ptr<const void> product, std::size_t bytes);
  NodeProducts from_memory(const std::string& key);             // with mutex_ held; no grid: not kept
  void to_memory(const std::string& key, NodeProducts result);  // with mutex_ held; its layers are not kept
  void keep(const std::string& key, Kept kept);                 // with mutex_ held; drops the least recently used over budget

  std::map<std::string, Kept> memory_;  // key -> result
  std::size_t memory_bytes_ = 0, memory_budget_ = static_cast<std::size_t>(-1);
  std::uint64_t uses_ = 0;
  std::map<std::string, std::string> key_of_id_;                  // node id -> the key of its last result
  std::map<std::string, std::vector<std::string>> layers_of_id_;  // node id -> the names of its own layers
  Counters counters_;
  std::vector<std::string> warnings_;
  std::mutex mutex_;
};

}  // namespace sansui::scene
