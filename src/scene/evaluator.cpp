// The evaluator of recipe graphs (see evaluator.hpp).
#include "scene/evaluator.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>

#include <unistd.h>

#include <fmt/format.h>

#include "contour/contour_tree.hpp"
#include "core/budget.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"
#include "scene/recipe.hpp"
#include "water/flow.hpp"

namespace sansui::scene {
namespace {

/// The context a node runs with: progress reports name the node ("worn: stream power"), and a
/// node reports its start and end; cancellation is the run's.
Context node_context(const Context& context, const std::string& id) {
  Context own;
  own.cancel = context.cancel;
  own.on_note = context.on_note;
  own.progress_lock = context.progress_lock;
  if (context.on_progress)
    // Called inside the node's own report(), which already serialises the calls.
    own.on_progress = [&context, id](std::string_view stage, double fraction) {
      context.on_progress(id + ": " + std::string(stage), fraction);
    };
  return own;
}

constexpr char cache_magic[] = "SANSUI-NODE-CACHE\n";
/// A node's report is a few figures and lines (a mesh's steps, a map's line count): an entry
/// holding more is not written, and one claiming more is not read.
constexpr std::size_t max_report_bytes = std::size_t{1} << 20;
constexpr std::uint32_t cache_format = 2;  // 2: the grid, then its report (JSON text)

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = 0xCBF29CE484222325ull) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001B3ull;
  return hash;
}

/// The contents of a file a node reads, as a hash. Read as the node would read it, so checked
/// first: a device, FIFO or link to one is refused with one line here (it would never end or
/// block forever), not hashed.
std::string file_hash(const std::filesystem::path& path, const std::string& where) {
  std::uint64_t hash = 0xCBF29CE484222325ull;
  try {
    // Eight bytes a step, mixed as xxHash64's round mixes them: six times less time than FNV-1a
    // byte by byte (perf, a 12 MB GeoTIFF). Blocks come whole but the last, so only it has a tail.
    io::read_file_blocks(path, [&](const char* data, std::size_t size) {
      std::size_t at = 0;
      for (; at + 8 <= size; at += 8) {
        std::uint64_t word = 0;
        std::memcpy(&word, data + at, 8);
        hash = std::rotl(hash + word * 0xC2B2AE3D27D4EB4Full, 31) * 0x9E3779B185EBCA87ull;
      }
      hash = fnv1a(data + at, size - at, hash);
    });
  } catch (const InputError& error) {
    fail("{}: {}", where, error.what());
  }
  return fmt::format("{:016x}", hash);
}

std::string file_name_of(const std::string& key) {
  return fmt::format("{:016x}.node", fnv1a(key.data(), key.size()));
}

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
bool take(const std::string& in, std::size_t& at, T& value) {
  if (at + sizeof value > in.size()) return false;
  std::memcpy(&value, in.data() + at, sizeof value);
  at += sizeof value;
  return true;
}

/// A report as a cache entry holds it: JSON text.
std::string report_text(const Report& report) {
  nlohmann::json json{{"statistics", report.statistics}, {"lines", report.lines}};
  if (report.base_level_m) json["base_level_m"] = *report.base_level_m;
  if (!report.settled.empty()) json["settled"] = report.settled;
  return json.dump();
}

/// A cache entry's report (its JSON text), or null where it is not one.
std::shared_ptr<const Report> report_of(std::string_view text) {
  const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
  if (!parsed.is_object() || !parsed.contains("statistics") || !parsed.contains("lines") || !parsed["lines"].is_array()) return nullptr;
  Report read;
  read.statistics = parsed["statistics"];
  for (const nlohmann::json& line : parsed["lines"]) {
    if (!line.is_string()) return nullptr;
    read.lines.push_back(line.get<std::string>());
  }
  if (const auto base = parsed.find("base_level_m"); base != parsed.end()) {
    if (!base->is_number()) return nullptr;
    read.base_level_m = base->get<double>();
  }
  if (const auto settled = parsed.find("settled"); settled != parsed.end()) {
    if (!settled->is_object()) return nullptr;
    for (const auto& [key, value] : settled->items()) {
      if (!value.is_number()) return nullptr;
      read.settled[key] = value.get<double>();
    }
  }
  return std::make_shared<const Report>(std::move(read));
}

/// The graph's one budget, before any node runs: its peak memory (the results alive at each
/// depth, those made at it and the scratch of its nodes, which run at once) and its time (every
/// node's, but those of nodes forced to run long), checked as one stage is (core/budget.hpp).
void check_graph_budget(const std::vector<std::vector<const GraphNode*>>& levels, const std::vector<std::string>& targets,
                        const GraphWorld& world) {
  const double grid_bytes = 4.0 * world.cells();
  std::map<std::string, std::size_t> last_use;
  for (std::size_t l = 0; l < levels.size(); ++l)
    for (const GraphNode* node : levels[l])
      for (const std::string& input : node->inputs) last_use[input] = l;
  // A result's grid and its own layers; a shaping node after one with layers also holds their
  // sums with its own (passed-on layers are shared, not copied).
  const auto result_bytes = [&](const NodeKind& kind) {
    return grid_bytes * (static_cast<double>(1 + (kind.passes_layers() ? 2 : 1) * kind.layers.size()) + kind.result_bytes_per_cell / 4.0);
  };
  std::map<std::string, double> bytes_of;
  budget::Cost cost;
  double alive = 0.0;
  std::size_t nodes = 0;
  const auto threads = static_cast<std::size_t>(std::max(1, parallel_detail::thread_slots()));
  for (std::size_t l = 0; l < levels.size(); ++l) {
    double made = 0.0;
    std::vector<double> scratches;
    for (const GraphNode* node : levels[l]) {
      const NodeKind& kind = node->node_kind();
      bytes_of[node->id] = result_bytes(kind);
      made += bytes_of[node->id];
      scratches.push_back(kind.scratch_bytes_per_cell / 4.0 * grid_bytes);
      const params::Value force = kind.row("force") != nullptr ? kind.get(node->params, "force") : params::Value{};
      const bool forced = std::holds_alternative<bool>(force) && std::get<bool>(force);
      if (!forced) cost.seconds += kind.seconds(node->params, world);
      ++nodes;
    }
    // The nodes of a depth run at once, as many as there are threads: the largest scratches.
    std::ranges::sort(scratches, std::greater<>());
    double scratch = 0.0;
    for (std::size_t k = 0; k < scratches.size() && k < threads; ++k) scratch += scratches[k];
    cost.bytes = std::max(cost.bytes, alive + made + scratch);
    alive += made;
    for (const auto& [id, last] : last_use)
      if (last == l && std::ranges::find(targets, id) == targets.end()) alive -= bytes_of[id];
  }
  cost.what = fmt::format("the graph ({} nodes on a {}x{} world)", nodes, world.width, world.height);
  cost.smaller = "use fewer nodes, a smaller world.size or lighter nodes";
  cost.force = "force = true on its long nodes";
  budget::check(cost);
}

/// `world` with the grid its sources made (`made`, the results of `sources`): their size, cell and
/// place, which every source of the graph must share.
GraphWorld world_of_sources(const GraphWorld& world, const std::vector<const GraphNode*>& sources, const std::vector<NodeProducts>& made) {
  GraphWorld settled = world;
  const Grid<float>& first = *made.front().grid;
  settled.width = first.width(), settled.height = first.height(), settled.cell_m = first.cell_size_m;
  settled.origin_x_m = first.origin_x_m, settled.origin_y_m = first.origin_y_m;
  // The highest base level a source brings (the plain round a contour mountain).
  for (const NodeProducts& result : made)
    if (result.report && result.report->base_level_m)
      settled.base_level_m = std::max(settled.base_level_m.value_or(-INFINITY), *result.report->base_level_m);
  for (std::size_t k = 1; k < made.size(); ++k)
    if (made[k].grid->width() != settled.width || made[k].grid->height() != settled.height)
      fail("{}: node `{}` made {}x{} samples where `{}` made {}x{}: the sources of a world without a size must agree", sources[k]->where,
           sources[k]->id, made[k].grid->width(), made[k].grid->height(), sources.front()->id, settled.width, settled.height);
  return settled;
}

}  // namespace

Evaluator::Evaluator(std::filesystem::path cache_dir) : cache_dir_(std::move(cache_dir)) {
  if (cache_dir_.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(cache_dir_, error);
  if (error || !io::can_create_file_in(cache_dir_)) {
    warnings_.push_back(fmt::format("the cache directory {} cannot be written ({}): running without the cache", cache_dir_.string(),
                                    error ? error.message() : "permission denied"));
    cache_dir_.clear();
  }
}

std::string Evaluator::key_text(const GraphNode& node, const GraphWorld& world, const std::vector<std::string>& input_keys) {
  const NodeKind& kind = node.node_kind();
  std::string key =
      fmt::format("sansui node {} {}|{}|{}|{}", SANSUI_VERSION, recipe_version, kind.name, kind.to_json(node.params).dump(), world.key());
  for (const params::ParamInfo& row : kind.rows) {
    if (row.kind != params::Kind::path) continue;
    const params::Value value = kind.get(node.params, row.key);
    const auto* name = std::get_if<std::string>(&value);
    if (name == nullptr || name->empty()) continue;
    const std::filesystem::path path =
        std::filesystem::path(*name).is_absolute() ? std::filesystem::path(*name) : std::filesystem::path(world.base_dir) / *name;
    key += "|file " + row.key + " " + file_hash(path, fmt::format("{}: node `{}` {}", node.where, node.id, row.key));
  }
  for (const std::string& input : input_keys) key += fmt::format("|input {:016x}", fnv1a(input.data(), input.size()));
  return key;
}

std::shared_ptr<const Grid<float>> Evaluator::from_disk(const std::string& key, std::optional<std::pair<int, int>> size,
                                                        std::shared_ptr<const Report>* report) {
  if (cache_dir_.empty()) return nullptr;
  const std::filesystem::path path = cache_dir_ / file_name_of(key);
  const auto damaged = [&](const std::string& why) -> std::shared_ptr<const Grid<float>> {
    std::lock_guard lock(mutex_);
    warnings_.push_back(fmt::format("the cache entry {} {}: ignored and rebuilt", path.string(), why));
    return nullptr;
  };
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return nullptr;
  // Read as any input (a regular file: a FIFO or device there would block or never end), and
  // no larger than the grid it must hold (the world's size when known).
  const std::uint64_t largest =
      size ? static_cast<std::uint64_t>(size->first) * static_cast<std::uint64_t>(size->second) * 4 + key.size() + max_report_bytes + 256
           : memory_limit_bytes();
  std::string bytes;
  try {
    bytes = io::read_text_file(path, static_cast<std::size_t>(largest));
  } catch (const InputError& e) {
    return damaged(fmt::format("cannot be used ({})", e.what()));
  }
  const std::size_t magic = sizeof cache_magic - 1;
  if (bytes.size() < magic + 8 || bytes.compare(0, magic, cache_magic) != 0) return damaged("is not a Sansui cache entry");
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + bytes.size() - 8, 8);
  if (fnv1a(bytes.data(), bytes.size() - 8) != checksum) return damaged("is damaged (its checksum does not match)");
  std::size_t at = magic;
  std::uint32_t format = 0;
  std::uint64_t key_size = 0;
  if (!take(bytes, at, format) || format != cache_format) return damaged("was written by another version");
  if (!take(bytes, at, key_size) || key_size > bytes.size() - at) return damaged("is damaged");
  if (bytes.compare(at, key_size, key) != 0) return damaged("holds another node's result");
  at += key_size;
  std::int32_t width = 0, height = 0;
  double cell = 0, origin_x = 0, origin_y = 0;
  if (!take(bytes, at, width) || !take(bytes, at, height) || !take(bytes, at, cell) || !take(bytes, at, origin_x) ||
      !take(bytes, at, origin_y) || width <= 0 || height <= 0 ||
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * 4 > bytes.size() - 8 - at)
    return damaged("is damaged (its size does not match)");
  const std::size_t samples_at = at;
  at += static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  std::uint64_t report_size = 0;
  if (!take(bytes, at, report_size) || report_size != bytes.size() - 8 - at) return damaged("is damaged (its size does not match)");
  std::shared_ptr<const Report> kept_report;
  if (report_size > 0 && !(kept_report = report_of(std::string_view(bytes).substr(at, report_size))))
    return damaged("is damaged (its report is not JSON)");
  if (size && (width != size->first || height != size->second))
    return damaged(fmt::format("holds {}x{} samples where the world has {}x{}", width, height, size->first, size->second));
  auto grid = std::make_shared<Grid<float>>(Grid<float>::uninitialized(width, height, cell));
  grid->origin_x_m = origin_x, grid->origin_y_m = origin_y;
  std::memcpy(grid->data(), bytes.data() + samples_at, grid->size() * 4);
  if (report != nullptr) *report = std::move(kept_report);
  return grid;
}

void Evaluator::to_disk(const std::string& key, const Grid<float>& grid, const Report* report) {
  if (cache_dir_.empty()) return;
  std::string bytes(cache_magic, sizeof cache_magic - 1);
  put(bytes, cache_format);
  put(bytes, static_cast<std::uint64_t>(key.size()));
  bytes += key;
  put(bytes, static_cast<std::int32_t>(grid.width()));
  put(bytes, static_cast<std::int32_t>(grid.height()));
  put(bytes, grid.cell_size_m), put(bytes, grid.origin_x_m), put(bytes, grid.origin_y_m);
  bytes.append(reinterpret_cast<const char*>(grid.data()), grid.size() * 4);
  const std::string text = report != nullptr ? report_text(*report) : std::string();
  if (text.size() > max_report_bytes) return;  // not kept on disk: the node runs again next time
  put(bytes, static_cast<std::uint64_t>(text.size()));
  bytes += text;
  put(bytes, fnv1a(bytes.data(), bytes.size()));
  const std::filesystem::path path = cache_dir_ / file_name_of(key);
  try {
    // Through a temporary made anew (never a link planted under its name), renamed when whole
    // (io/atomic_file.hpp), with the run's other outputs.
    io::write_text_file(path, bytes, "cache");
  } catch (const InputError&) {
    std::lock_guard lock(mutex_);
    warnings_.push_back(fmt::format("the cache entry {} could not be written: the run goes on without it", path.string()));
    return;
  }
  std::lock_guard lock(mutex_);
  ++counters_.disk_writes;
}

namespace {

/// A grid alone as a result (a layer, a cached terrain).
NodeProducts grid_only(std::shared_ptr<const Grid<float>> grid) {
  NodeProducts products;
  products.grid = std::move(grid);
  return products;
}

std::string layer_key(const std::string& key, const std::string& name) {
  return key + "|layer " + name;
}

/// A shaping node's layers: its own, plus those of its heights input (summed where both have one:
/// the metres of two erosions add up).
void add_inherited_layers(NodeProducts& products, const NodeProducts& input) {
  // A source's report, mesh and contours, as a chain's sidecars and outputs give them after its steps.
  if (!products.report) products.report = input.report;
  if (!products.mesh) products.mesh = input.mesh;
  if (!products.tree) products.tree = input.tree;
  for (const auto& [name, inherited] : input.layers) {
    auto& own = products.layers[name];
    if (!own) {
      own = inherited;
      continue;
    }
    auto sum = std::make_shared<Grid<float>>(*own);
    for (std::size_t i = 0; i < sum->size() && i < inherited->size(); ++i) sum->values()[i] += inherited->values()[i];
    own = std::move(sum);
  }
}

}  // namespace

NodeProducts Evaluator::node_result(const GraphNode& node, const std::string& key, const std::vector<std::string>& layer_names,
                                    const std::map<std::string, NodeProducts>& results, const GraphWorld& world, const Context& context) {
  // A world without a grid takes its source's: nothing to check the source's result against.
  const auto world_size = world.has_grid() ? std::optional(std::pair{world.width, world.height}) : std::nullopt;
  const auto of_world = [&](const Grid<float>& grid) {
    return !world_size || (grid.width() == world.width && grid.height() == world.height);
  };
  NodeProducts products;
  {
    std::lock_guard lock(mutex_);
    products = from_memory(key);
    for (const std::string& name : layer_names)
      if (products.grid) products.layers[name] = from_memory(layer_key(key, name)).grid;
  }
  const auto whole = [&] {
    return products.grid && std::ranges::all_of(products.layers, [](const auto& layer) { return layer.second != nullptr; });
  };
  if (whole()) {
    std::lock_guard lock(mutex_);
    ++counters_.memory_hits;
    return products;
  }
  products = {};
  products.grid = from_disk(key, world_size, &products.report);
  for (const std::string& name : layer_names)
    if (products.grid) products.layers[name] = from_disk(layer_key(key, name), world_size);
  if (whole()) {
    std::lock_guard lock(mutex_);
    ++counters_.disk_hits;
  } else {
    const NodeKind& kind = node.node_kind();
    std::vector<const Grid<float>*> inputs(kind.inputs.size(), nullptr);
    for (std::size_t k = 0; k < node.inputs.size(); ++k) inputs[k] = results.at(node.inputs[k]).grid.get();
    // Heights that carry their routing (a flow node's) are not routed again by a kind that can take it.
    const water::FlowRouting* routed = node.inputs.empty() ? nullptr : results.at(node.inputs[0]).flow.get();
    context.check_cancelled();
    context.report(node.id, 0.0);
    const Context own = node_context(context, node.id);
    NodeOutput made = routed != nullptr && kind.run_routed ? kind.run_routed(node.params, inputs, *routed, world, own)
                                                           : kind.run(node.params, inputs, world, own);
    context.report(node.id, 1.0);
    products = {};
    products.grid = std::make_shared<Grid<float>>(std::move(made.grid));
    products.flow = std::move(made.flow);
    if (Report report{std::move(made.statistics), std::move(made.lines), made.base_level_m, std::move(made.settled)}; !report.empty())
      products.report = std::make_shared<const Report>(std::move(report));
    products.mesh = std::move(made.mesh);
    products.tree = std::move(made.tree);
    for (auto& [name, layer] : made.layers) products.layers[name] = std::make_shared<Grid<float>>(std::move(layer));
    for (const auto& [name, grid] : products.layers)
      if (std::ranges::find(layer_names, name) == layer_names.end() || !of_world(*grid))
        fail("{}: node `{}` ({}) made a layer {} it does not declare or of another size", node.where, node.id, node.kind, name);
    if (!of_world(*products.grid))
      fail("{}: node `{}` ({}) made {}x{} samples; the world is {}x{}", node.where, node.id, node.kind, products.grid->width(),
           products.grid->height(), world.width, world.height);
    // A result with a mesh or contours is kept in memory only (the disk holds grids): from disk,
    // it runs again.
    if (!products.mesh && !products.tree) {
      to_disk(key, *products.grid, products.report.get());
      for (const auto& [name, layer] : products.layers) to_disk(layer_key(key, name), *layer);
    }
    std::lock_guard lock(mutex_);
    ++counters_.runs[node.id];
  }
  std::lock_guard lock(mutex_);
  to_memory(key, products);
  for (const auto& [name, layer] : products.layers) to_memory(layer_key(key, name), grid_only(layer));
  return products;
}

std::map<std::string, NodeProducts> Evaluator::evaluate(const std::vector<GraphNode>& nodes, const GraphWorld& world,
                                                        const std::vector<std::string>& targets, const Context& context) {
  // The nodes the targets need, in topological order, grouped by depth: the nodes of one depth
  // depend only on earlier depths, so they run at once.
  std::set<std::string> needed;
  for (const std::string& target : targets)
    for (const std::string& id : ancestors(nodes, target)) needed.insert(id);
  std::map<std::string, const GraphNode*> by_id;
  for (const GraphNode& node : nodes) by_id.emplace(node.id, &node);
  std::map<std::string, int> depth;
  std::vector<std::vector<const GraphNode*>> levels;
  for (const std::string& id : topological_order(nodes)) {
    if (needed.count(id) == 0) continue;
    const GraphNode& node = *by_id.at(id);
    int d = 0;
    for (const std::string& input : node.inputs) d = std::max(d, depth.at(input) + 1);
    depth[id] = d;
    if (static_cast<int>(levels.size()) <= d) levels.resize(static_cast<std::size_t>(d) + 1);
    levels[static_cast<std::size_t>(d)].push_back(&node);
  }
  // A world without a grid takes its sources' (they have no inputs: the first level), and the
  // budget is checked once that is known.
  GraphWorld settled = world;
  if (world.has_grid()) check_graph_budget(levels, targets, world);
  // The level after which no node needs a result: it is dropped then (but a target's).
  std::map<std::string, std::size_t> last_use;
  for (std::size_t l = 0; l < levels.size(); ++l)
    for (const GraphNode* node : levels[l])
      for (const std::string& input : node->inputs) last_use[input] = l;
  std::map<std::string, NodeProducts> results;
  std::map<std::string, std::string> keys;
  for (std::size_t level_index = 0; level_index < levels.size(); ++level_index) {
    const auto& level = levels[level_index];
    context.check_cancelled();
    std::vector<std::string> level_keys(level.size());
    std::vector<NodeProducts> level_results(level.size());
    for (std::size_t i = 0; i < level.size(); ++i) {
      std::vector<std::string> input_keys;
      for (const std::string& input : level[i]->inputs) input_keys.push_back(keys.at(input));
      level_keys[i] = key_text(*level[i], settled, input_keys);
    }
    parallel_for(std::size_t{0}, level.size(), [&](std::size_t i) {
      const GraphNode& node = *level[i];
      level_results[i] = node_result(node, level_keys[i], node.node_kind().layers, results, settled, context);
      if (node.node_kind().passes_layers() && !node.inputs.empty()) add_inherited_layers(level_results[i], results.at(node.inputs[0]));
    });
    for (std::size_t i = 0; i < level.size(); ++i) {
      results[level[i]->id] = level_results[i];
      keys[level[i]->id] = level_keys[i];
      key_of_id_[level[i]->id] = level_keys[i];
      layers_of_id_[level[i]->id] = level[i]->node_kind().layers;
    }
    if (!settled.has_grid()) {
      settled = world_of_sources(world, level, level_results);
      check_graph_budget(levels, targets, settled);
    }
    for (auto& [id, result] : results)
      if (const auto last = last_use.find(id);
          last != last_use.end() && last->second <= level_index && std::ranges::find(targets, id) == targets.end())
        result = {};
  }
  std::map<std::string, NodeProducts> out;
  for (const std::string& target : targets) out[target] = results.at(target);
  return out;
}

std::shared_ptr<const Grid<float>> Evaluator::cached(const std::string& label, const std::string& key,
                                                     const std::function<Grid<float>()>& compute) {
  {
    std::lock_guard lock(mutex_);
    if (auto kept = from_memory(key).grid) {
      ++counters_.memory_hits;
      return kept;
    }
  }
  std::shared_ptr<const Grid<float>> result = from_disk(key);
  if (result) {
    std::lock_guard lock(mutex_);
    ++counters_.disk_hits;
  } else {
    auto grid = std::make_shared<Grid<float>>(compute());
    to_disk(key, *grid);
    result = std::move(grid);
    std::lock_guard lock(mutex_);
    ++counters_.runs[label];
  }
  std::lock_guard lock(mutex_);
  to_memory(key, grid_only(result));
  return result;
}

std::size_t Evaluator::Kept::bytes() const {
  if (!result.grid) return product_bytes;
  std::size_t total = result.grid->size() * sizeof(float);
  if (const auto& flow = result.flow)
    total += flow->surface.size() * sizeof(float) + flow->receiver.size() * sizeof(water::CellIndex) +
             flow->stack.size() * sizeof(water::CellIndex) + flow->area_m2.size() * sizeof(double);
  if (const auto& mesh = result.mesh)
    total += (mesh->positions.size() + mesh->normals.size() + mesh->colors.size()) * sizeof(glm::vec3) +
             mesh->indices.size() * sizeof(std::uint32_t) + mesh->uvs.size() * sizeof(glm::vec2);
  if (const auto& tree = result.tree)
    for (const contour::ContourNode& node : tree->nodes) total += sizeof node + node.ring.size() * sizeof(contour::Point);
  return total;
}

NodeProducts Evaluator::from_memory(const std::string& key) {
  const auto found = memory_.find(key);
  if (found == memory_.end()) return {};
  found->second.last_use = ++uses_;
  return found->second.result;
}

void Evaluator::to_memory(const std::string& key, NodeProducts result) {
  result.layers.clear();
  Kept kept;
  kept.result = std::move(result);
  keep(key, std::move(kept));
}

void Evaluator::keep(const std::string& key, Kept kept) {
  if (const auto old = memory_.find(key); old != memory_.end()) memory_bytes_ -= old->second.bytes();
  kept.last_use = ++uses_;
  memory_bytes_ += kept.bytes();
  memory_[key] = std::move(kept);
  // The least recently used go first; the newest result stays even when it alone is over budget.
  while (memory_bytes_ > memory_budget_ && memory_.size() > 1) {
    auto oldest = memory_.begin();
    for (auto it = memory_.begin(); it != memory_.end(); ++it)
      if (it->second.last_use < oldest->second.last_use) oldest = it;
    memory_bytes_ -= oldest->second.bytes();
    memory_.erase(oldest);
  }
}

std::shared_ptr<const void> Evaluator::kept_product(const std::string& entry) {
  std::lock_guard lock(mutex_);
  const auto found = memory_.find(entry);
  if (found == memory_.end() || !found->second.product) return nullptr;
  found->second.last_use = ++uses_;
  ++counters_.memory_hits;
  return found->second.product;
}

void Evaluator::keep_product(const std::string& label, const std::string& entry, std::shared_ptr<const void> product, std::size_t bytes) {
  std::lock_guard lock(mutex_);
  ++counters_.runs[label];
  Kept kept;
  kept.product = std::move(product);
  kept.product_bytes = bytes;
  keep(entry, std::move(kept));
}

void Evaluator::keep_in_memory(std::size_t bytes) {
  std::lock_guard lock(mutex_);
  memory_budget_ = bytes;
}

void Evaluator::forget_memory() {
  std::lock_guard lock(mutex_);
  memory_.clear();
  memory_bytes_ = 0;
  key_of_id_.clear();
  layers_of_id_.clear();
}

void Evaluator::invalidate(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto found = key_of_id_.find(id);
  if (found == key_of_id_.end()) return;
  const std::string& key = found->second;
  for (auto kept = memory_.begin(); kept != memory_.end();)
    if (kept->first == key || kept->first.starts_with(layer_key(key, ""))) {
      memory_bytes_ -= kept->second.bytes();
      kept = memory_.erase(kept);
    } else {
      ++kept;
    }
  if (!cache_dir_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(cache_dir_ / file_name_of(key), ignored);
    for (const std::string& name : layers_of_id_[found->first])
      std::filesystem::remove(cache_dir_ / file_name_of(layer_key(key, name)), ignored);
  }
  key_of_id_.erase(found);
}

}  // namespace sansui::scene
