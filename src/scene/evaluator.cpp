// The evaluator of recipe graphs (see evaluator.hpp).
#include "scene/evaluator.hpp"

#include <atomic>
#include <cstring>
#include <fstream>
#include <set>

#include <unistd.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {
namespace {

/// The context a node runs with: progress reports name the node ("worn: stream power"), and a
/// node reports its start and end; cancellation is the run's.
Context node_context(const Context& context, const std::string& id) {
  Context own;
  own.cancel = context.cancel;
  own.on_note = context.on_note;
  if (context.on_progress)
    // Called inside the node's own report(), which already serialises the calls.
    own.on_progress = [&context, id](std::string_view stage, double fraction) {
      context.on_progress(id + ": " + std::string(stage), fraction);
    };
  return own;
}

constexpr char cache_magic[] = "SANSUI-NODE-CACHE\n";
constexpr std::uint32_t cache_format = 1;

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = 0xCBF29CE484222325ull) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001B3ull;
  return hash;
}

/// The contents of a file a node reads, as a hash ("missing" when it cannot be read).
std::string file_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "missing";
  std::uint64_t hash = 0xCBF29CE484222325ull;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    hash = fnv1a(buffer, static_cast<std::size_t>(in.gcount()), hash);
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

}  // namespace

Evaluator::Evaluator(std::filesystem::path cache_dir) : cache_dir_(std::move(cache_dir)) {
  if (cache_dir_.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(cache_dir_, error);
  const std::filesystem::path probe = cache_dir_ / fmt::format(".probe-{}", ::getpid());
  std::ofstream(probe) << "sansui";
  if (error || !std::filesystem::exists(probe)) {
    warnings_.push_back(fmt::format("the cache directory {} cannot be written ({}): running without the cache", cache_dir_.string(),
                                    error ? error.message() : "permission denied"));
    cache_dir_.clear();
    return;
  }
  std::filesystem::remove(probe, error);
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
    key += "|file " + row.key + " " + file_hash(path);
  }
  for (const std::string& input : input_keys) key += fmt::format("|input {:016x}", fnv1a(input.data(), input.size()));
  return key;
}

std::shared_ptr<const Grid<float>> Evaluator::from_disk(const std::string& key) {
  if (cache_dir_.empty()) return nullptr;
  const std::filesystem::path path = cache_dir_ / file_name_of(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return nullptr;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto damaged = [&](const char* why) -> std::shared_ptr<const Grid<float>> {
    std::lock_guard lock(mutex_);
    warnings_.push_back(fmt::format("the cache entry {} {}: ignored and rebuilt", path.string(), why));
    return nullptr;
  };
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
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * 4 != bytes.size() - 8 - at)
    return damaged("is damaged (its size does not match)");
  auto grid = std::make_shared<Grid<float>>(Grid<float>::uninitialized(width, height, cell));
  grid->origin_x_m = origin_x, grid->origin_y_m = origin_y;
  std::memcpy(grid->data(), bytes.data() + at, grid->size() * 4);
  return grid;
}

void Evaluator::to_disk(const std::string& key, const Grid<float>& grid) {
  if (cache_dir_.empty()) return;
  std::string bytes(cache_magic, sizeof cache_magic - 1);
  put(bytes, cache_format);
  put(bytes, static_cast<std::uint64_t>(key.size()));
  bytes += key;
  put(bytes, static_cast<std::int32_t>(grid.width()));
  put(bytes, static_cast<std::int32_t>(grid.height()));
  put(bytes, grid.cell_size_m), put(bytes, grid.origin_x_m), put(bytes, grid.origin_y_m);
  bytes.append(reinterpret_cast<const char*>(grid.data()), grid.size() * 4);
  put(bytes, fnv1a(bytes.data(), bytes.size()));
  static std::atomic<int> counter{0};
  const std::filesystem::path path = cache_dir_ / file_name_of(key);
  std::filesystem::path temporary = path;
  temporary += fmt::format(".tmp-{}-{}", ::getpid(), counter++);
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      std::lock_guard lock(mutex_);
      warnings_.push_back(fmt::format("the cache entry {} could not be written: the run goes on without it", path.string()));
      return;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) std::filesystem::remove(temporary, error);
  std::lock_guard lock(mutex_);
  ++counters_.disk_writes;
}

std::map<std::string, std::shared_ptr<const Grid<float>>> Evaluator::evaluate(const std::vector<GraphNode>& nodes, const GraphWorld& world,
                                                                              const std::vector<std::string>& targets,
                                                                              const Context& context) {
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
  std::map<std::string, std::shared_ptr<const Grid<float>>> results;
  std::map<std::string, std::string> keys;
  for (const auto& level : levels) {
    context.check_cancelled();
    std::vector<std::string> level_keys(level.size());
    std::vector<std::shared_ptr<const Grid<float>>> level_results(level.size());
    for (std::size_t i = 0; i < level.size(); ++i) {
      std::vector<std::string> input_keys;
      for (const std::string& input : level[i]->inputs) input_keys.push_back(keys.at(input));
      level_keys[i] = key_text(*level[i], world, input_keys);
    }
    parallel_for(std::size_t{0}, level.size(), [&](std::size_t i) {
      const GraphNode& node = *level[i];
      const std::string& key = level_keys[i];
      {
        std::lock_guard lock(mutex_);
        if (auto kept = from_memory(key)) {
          ++counters_.memory_hits;
          level_results[i] = std::move(kept);
          return;
        }
      }
      std::shared_ptr<const Grid<float>> result = from_disk(key);
      if (result) {
        std::lock_guard lock(mutex_);
        ++counters_.disk_hits;
      } else {
        const NodeKind& kind = node.node_kind();
        std::vector<const Grid<float>*> inputs(kind.inputs.size(), nullptr);
        for (std::size_t k = 0; k < node.inputs.size(); ++k) inputs[k] = results.at(node.inputs[k]).get();
        context.check_cancelled();
        context.report(node.id, 0.0);
        auto grid = std::make_shared<Grid<float>>(kind.run(node.params, inputs, world, node_context(context, node.id)));
        context.report(node.id, 1.0);
        if (grid->width() != world.size || grid->height() != world.size)
          fail("{}: node `{}` ({}) made {}x{} samples; the world is {}x{}", node.where, node.id, node.kind, grid->width(), grid->height(),
               world.size, world.size);
        to_disk(key, *grid);
        result = std::move(grid);
        std::lock_guard lock(mutex_);
        ++counters_.runs[node.id];
      }
      std::lock_guard lock(mutex_);
      to_memory(key, result);
      level_results[i] = result;
    });
    for (std::size_t i = 0; i < level.size(); ++i) {
      results[level[i]->id] = level_results[i];
      keys[level[i]->id] = level_keys[i];
      key_of_id_[level[i]->id] = level_keys[i];
    }
  }
  std::map<std::string, std::shared_ptr<const Grid<float>>> out;
  for (const std::string& target : targets) out[target] = results.at(target);
  return out;
}

std::shared_ptr<const Grid<float>> Evaluator::cached(const std::string& label, const std::string& key,
                                                     const std::function<Grid<float>()>& compute) {
  {
    std::lock_guard lock(mutex_);
    if (auto kept = from_memory(key)) {
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
  to_memory(key, result);
  return result;
}

std::shared_ptr<const Grid<float>> Evaluator::from_memory(const std::string& key) {
  const auto found = memory_.find(key);
  if (found == memory_.end()) return nullptr;
  found->second.last_use = ++uses_;
  return found->second.result;
}

void Evaluator::to_memory(const std::string& key, std::shared_ptr<const Grid<float>> result) {
  const auto bytes = [](const Kept& kept) { return kept.result->size() * sizeof(float); };
  if (const auto old = memory_.find(key); old != memory_.end()) memory_bytes_ -= bytes(old->second);
  Kept& kept = memory_[key];
  kept = {std::move(result), ++uses_};
  memory_bytes_ += bytes(kept);
  // The least recently used go first; the newest result stays even when it alone is over budget.
  while (memory_bytes_ > memory_budget_ && memory_.size() > 1) {
    auto oldest = memory_.begin();
    for (auto it = memory_.begin(); it != memory_.end(); ++it)
      if (it->second.last_use < oldest->second.last_use) oldest = it;
    memory_bytes_ -= bytes(oldest->second);
    memory_.erase(oldest);
  }
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
}

void Evaluator::invalidate(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto found = key_of_id_.find(id);
  if (found == key_of_id_.end()) return;
  if (const auto kept = memory_.find(found->second); kept != memory_.end()) {
    memory_bytes_ -= kept->second.result->size() * sizeof(float);
    memory_.erase(kept);
  }
  if (!cache_dir_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(cache_dir_ / file_name_of(found->second), ignored);
  }
  key_of_id_.erase(found);
}

}  // namespace sansui::scene
