// `sansui bench solid`: the solid-texture paper's experiments (Okada, Taga, Yokoi, Toriwaki 1990;
// seeds/002, SPEC 2), printed as tables shaped like the paper's, with its memory formulas beside
// the measured peak memory of child processes, and the issue's speed targets.
#include "bench/harness/solid_experiments.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "core/context.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/params.hpp"
#include "core/random.hpp"
#include "solid/evaluator.hpp"
#include "solid/sphere_surface.hpp"
#include "solid/type1_array.hpp"
#include "solid/type2_memo.hpp"
#include "solid/type3_ancestors.hpp"

extern char** environ;

namespace sansui::bench {
namespace {

// ---- shared by every subsystem's bench -----------------------------------------------------

/// Wall and CPU seconds of one call (CPU: the whole process, so worker threads count).
struct Seconds {
  double wall = 0.0;
  double cpu = 0.0;
};

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Seconds measure(const std::function<void()>& work) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_seconds();
  work();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(), process_cpu_seconds() - cpu0};
}

double load_average() {
  double load[1] = {0.0};
  return ::getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

/// A plain-text table: columns right-aligned except the first, widths from the contents.
class Table {
 public:
  explicit Table(std::vector<std::string> header) { rows_.push_back(std::move(header)); }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print() const {
    std::vector<std::size_t> width;
    for (const auto& row : rows_)
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (width.size() <= c) width.push_back(0);
        width[c] = std::max(width[c], row[c].size());
      }
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      std::string line;
      for (std::size_t c = 0; c < rows_[r].size(); ++c)
        line += c == 0 ? fmt::format("  {:<{}}", rows_[r][c], width[c]) : fmt::format("  {:>{}}", rows_[r][c], width[c]);
      fmt::print("{}\n", line);
      if (r == 0) fmt::print("  {}\n", std::string(line.size() - 2, '-'));
    }
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};

std::string with_commas(double value) {
  const std::string digits = fmt::format("{:.0f}", value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string bytes_text(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.2f} GB", bytes / 1e9);
  if (bytes >= 1e6) return fmt::format("{:.1f} MB", bytes / 1e6);
  if (bytes >= 1e3) return fmt::format("{:.1f} kB", bytes / 1e3);
  return fmt::format("{:.0f} B", bytes);
}

std::string seconds_text(double s) {
  if (s < 0.0) return "-";
  if (s < 0.001) return fmt::format("{:.1e}", s);
  if (s < 0.01) return fmt::format("{:.4f}", s);
  if (s < 10.0) return fmt::format("{:.3f}", s);
  return fmt::format("{:.1f}", s);
}

/// This process's peak resident memory (VmHWM) in bytes. Per address space, so a child started
/// with exec reports only its own (its rusage maxrss would include the parent's).
double own_peak_rss() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kilobytes = 0.0;
      status >> kilobytes;
      return kilobytes * 1024.0;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0.0;
}

/// Runs this program again with `args`; the child prints its own_peak_rss() as its last line.
std::optional<double> child_peak_rss(const std::vector<std::string>& args) {
  int pipe_ends[2];
  if (::pipe(pipe_ends) != 0) return std::nullopt;
  posix_spawn_file_actions_t actions;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  ::posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  std::vector<std::string> copies = args;
  copies.insert(copies.begin(), "/proc/self/exe");
  std::vector<char*> argv;
  argv.reserve(copies.size() + 1);
  for (auto& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_ends[1]);
  std::string output;
  char buffer[256];
  for (ssize_t n; spawned == 0 && (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    output.append(buffer, static_cast<std::size_t>(n));
  ::close(pipe_ends[0]);
  int status = 0;
  if (spawned != 0 || ::waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  try {
    return std::stod(output);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// ---- solid: Okada, Taga, Yokoi, Toriwaki (1990; seeds/002), SPEC 2 -------------------------

using solid::EvaluatorType;
using solid::FieldEvaluator;
using solid::FieldParams;

FieldParams field_of(int levels, std::uint64_t seed) {
  FieldParams params;
  params.levels = levels;
  params.seed = seed;
  return params;
}

volatile float sink = 0.0f;  // keeps the queries from being optimised away

/// Every lattice point, raster order (x fastest).
void query_all(FieldEvaluator& field) {
  const int last = field.last();
  float sum = 0.0f;
  for (int z = 0; z <= last; ++z)
    for (int y = 0; y <= last; ++y)
      for (int x = 0; x <= last; ++x) sum += field.at(x, y, z);
  sink = sink + sum;
}

void query_voxels(FieldEvaluator& field, const std::vector<solid::SurfaceVoxel>& voxels) {
  float sum = 0.0f;
  for (const auto& v : voxels) sum += field.at(v.x, v.y, v.z);
  sink = sink + sum;
}

/// An evaluator of `type` with its set-up, then `work` on it, on one thread: CPU seconds of both.
double one_thread_seconds(EvaluatorType type, const FieldParams& params, int r2, bool reuse,
                          const std::function<void(FieldEvaluator&)>& work) {
  double seconds = 0.0;
  tbb::task_arena(1).execute([&] {
    seconds = measure([&] {
                auto field = solid::make_evaluator(type, params, {r2, reuse});
                work(*field);
              }).cpu;
  });
  return seconds;
}

/// A table cell that is skipped when the estimate from the previous R says it would take too long.
struct Column {
  std::string name;
  std::function<double(int levels)> run;  // seconds
  std::function<bool(int levels)> allowed = [](int) { return true; };
  double growth = 8.0;  // time ratio from R to R + 1
  double previous = -1.0;

  std::string cell(int levels, double max_seconds) {
    if (!allowed(levels)) return "(skipped)";
    if (previous > 0.0 && previous * growth > max_seconds) {
      previous *= growth;
      return fmt::format("~{:.0f} est.", previous);
    }
    previous = run(levels);
    return seconds_text(previous);
  }
};

/// Progress of one table on the context: each unit of work adds its weight.
class TableProgress {
 public:
  TableProgress(const Context& context, std::string name, double total) : context_(context), name_(std::move(name)), total_(total) {}
  void advance(double weight = 1.0) {
    done_ += weight;
    context_.report(name_, done_ / total_);
  }

 private:
  const Context& context_;
  std::string name_;
  double total_;
  double done_ = 0.0;
};

/// The weights of rows from..to whose work grows by `growth` per row (the last rows dominate).
double growing_total(int from, int to, double growth) {
  double total = 0.0;
  for (int R = from; R <= to; ++R) total += std::pow(growth, R - from);
  return total;
}

void experiment_1(const SolidBenchOptions& o, const Context& context) {
  fmt::print("\nExperiment 1: every lattice point of {{0..2^R}}^3 (paper Sec. 7-2, Fig. 9)\n");
  fmt::print(
      "CPU seconds on one thread, raster order (x fastest). III (paper) clears its memo for every point as\n"
      "the paper's Type III does; III and IV keep the previous point's ancestors. The paper plots its 1990 times\n"
      "in Fig. 9 without printing them (the text gives no values) and omits Type IV there.\n\n");
  std::vector<Column> columns;
  columns.push_back({"I", [&](int R) { return one_thread_seconds(EvaluatorType::type1, field_of(R, o.seed), 0, true, query_all); }});
  columns.back().allowed = [&](int R) { return o.full || R <= 9; };
  columns.push_back({"II", [&](int R) { return one_thread_seconds(EvaluatorType::type2, field_of(R, o.seed), 0, true, query_all); }});
  columns.back().allowed = [&](int R) { return o.full || R <= 8; };
  columns.push_back(
      {"III (paper)", [&](int R) { return one_thread_seconds(EvaluatorType::type3, field_of(R, o.seed), 0, false, query_all); }});
  columns.back().growth = 9.0;
  columns.push_back({"III", [&](int R) { return one_thread_seconds(EvaluatorType::type3, field_of(R, o.seed), 0, true, query_all); }});
  columns.push_back({"IV (R2=R-2)", [&](int R) {
                       return one_thread_seconds(EvaluatorType::type4, field_of(R, o.seed), std::max(R - 2, 0), true, query_all);
                     }});
  std::vector<std::string> header{"R", "points"};
  for (const auto& c : columns) header.push_back(c.name);
  Table table(header);
  TableProgress progress(context, "experiment 1", growing_total(o.exp1_from, o.exp1_to, 8.0) * static_cast<double>(columns.size()));
  for (int R = o.exp1_from; R <= o.exp1_to; ++R) {
    const double side = std::ldexp(1.0, R) + 1.0;
    std::vector<std::string> row{std::to_string(R), with_commas(side * side * side)};
    for (auto& c : columns) {
      row.push_back(c.cell(R, o.max_seconds));
      progress.advance(std::pow(8.0, R - o.exp1_from));
    }
    table.add(row);
  }
  table.print();
}

void experiment_2(const SolidBenchOptions& o, const Context& context) {
  fmt::print("\nExperiment 2: the voxels on the surface of the digital sphere inscribed in the lattice (paper Sec. 7-3, Fig. 10)\n");
  fmt::print(
      "CPU seconds on one thread; the voxels in octree (Morton) order, i.e. along the surface; Type I computes its\n"
      "whole array first, as in the paper; Type IV with R2 = {}. The paper plots its times in Fig. 10 without printing them.\n\n",
      o.r2);
  std::vector<solid::SurfaceVoxel> voxels;
  auto on_voxels = [&](FieldEvaluator& field) { query_voxels(field, voxels); };
  std::vector<Column> columns;
  columns.push_back({"I", [&](int R) { return one_thread_seconds(EvaluatorType::type1, field_of(R, o.seed), 0, true, on_voxels); }});
  columns.back().allowed = [&](int R) { return o.full || R <= 9; };
  columns.push_back({"II", [&](int R) { return one_thread_seconds(EvaluatorType::type2, field_of(R, o.seed), 0, true, on_voxels); }});
  columns.back().growth = 4.0;
  columns.push_back(
      {"III (paper)", [&](int R) { return one_thread_seconds(EvaluatorType::type3, field_of(R, o.seed), 0, false, on_voxels); }});
  columns.back().growth = 4.5;
  columns.push_back({"III", [&](int R) { return one_thread_seconds(EvaluatorType::type3, field_of(R, o.seed), 0, true, on_voxels); }});
  columns.back().growth = 4.0;
  columns.push_back({fmt::format("IV (R2={})", o.r2), [&](int R) {
                       return one_thread_seconds(EvaluatorType::type4, field_of(R, o.seed), std::min(o.r2, R), true, on_voxels);
                     }});
  columns.back().growth = 4.0;
  std::vector<std::string> header{"R", "surface voxels"};
  for (const auto& c : columns) header.push_back(c.name);
  Table table(header);
  TableProgress progress(context, "experiment 2", growing_total(o.exp2_from, o.exp2_to, 4.0) * static_cast<double>(columns.size()));
  for (int R = o.exp2_from; R <= o.exp2_to; ++R) {
    voxels = solid::digital_sphere_surface(R);
    solid::sort_along_octree(voxels);
    std::vector<std::string> row{std::to_string(R), with_commas(static_cast<double>(voxels.size()))};
    for (auto& c : columns) {
      row.push_back(c.cell(R, o.max_seconds));
      progress.advance(std::pow(4.0, R - o.exp2_from));
    }
    table.add(row);
  }
  table.print();
}

/// The hidden child of the memory table, "TYPE,R,R2,WORKLOAD,RUN": builds the workload's voxel
/// list, then evaluates it if RUN is 1; with RUN 0 it is the baseline (same list, same thread
/// pool and code, one point of a Type III field). Prints its peak resident memory.
void run_memory_child(const std::string& spec) {
  int type = 0, levels = 0, r2 = 0, run = 0;
  char workload[16] = {};
  if (std::sscanf(spec.c_str(), "%d,%d,%d,%15[a-z],%d", &type, &levels, &r2, workload, &run) != 5) fail("bad --child '{}'", spec);
  const FieldParams params = field_of(levels, 1);
  const std::string what = workload;
  std::vector<solid::SurfaceVoxel> voxels = what == "sphere" ? solid::digital_sphere_surface(levels) : std::vector<solid::SurfaceVoxel>{};
  solid::sort_along_octree(voxels);
  tbb::task_arena(1).execute([&] {
    auto field = solid::make_evaluator(run == 0 ? EvaluatorType::type3 : static_cast<EvaluatorType>(type), params, {r2, true});
    if (run == 0)
      sink = sink + field->at(1, 1, 1);
    else if (what == "sphere")
      query_voxels(*field, voxels);
    else
      query_all(*field);
  });
  fmt::print("{:.0f}\n", own_peak_rss());
}

void memory_table(const SolidBenchOptions& o, const Context& context) {
  const int R = o.memory_levels, r2 = std::min(o.r2, R);
  const double N = std::ldexp(1.0, R) + 1.0;
  fmt::print("\nMemory at R = {} (N = {}), Type IV with R2 = {} (paper Sec. 7-1, eqs. 13-16; a word taken as 4 bytes)\n", R,
             static_cast<int>(N), r2);
  fmt::print(
      "'ours' is what the evaluator's data structures hold at their peak; 'peak RSS' is the measured peak resident\n"
      "memory of a child process running the workload, minus the same process with the workload built but not run.\n\n");
  TableProgress progress(context, "memory", o.skip_memory ? 5.0 : 15.0);  // five evaluators, two children each
  // Our data structures, measured in this process.
  auto accounted = [&](EvaluatorType type, bool sphere) {
    const FieldParams params = field_of(R, o.seed);
    auto voxels = sphere ? solid::digital_sphere_surface(R) : std::vector<solid::SurfaceVoxel>{};
    solid::sort_along_octree(voxels);
    auto field = solid::make_evaluator(type, params, {r2, true});
    if (sphere)
      query_voxels(*field, voxels);
    else if (type == EvaluatorType::type2)
      query_all(*field);
    std::size_t nodes = 0;
    if (auto* memo = dynamic_cast<solid::MemoEvaluator*>(field.get())) nodes = memo->nodes();
    progress.advance();
    return std::make_pair(static_cast<double>(field->peak_memory_bytes()), static_cast<double>(nodes));
  };
  auto measured = [&](EvaluatorType type, const std::string& workload) -> std::string {
    if (o.skip_memory) return "-";
    const std::string base = fmt::format("{},{},{},{},", static_cast<int>(type), R, r2, workload);
    const auto none = child_peak_rss({"bench", "solid", "--child", base + "0"});
    progress.advance();
    const auto with = child_peak_rss({"bench", "solid", "--child", base + "1"});
    progress.advance();
    if (!none || !with) return "(failed)";
    return bytes_text(std::max(0.0, *with - *none));
  };
  Table table({"type", "paper formula", "paper words", "paper bytes", "ours", "peak RSS"});
  const auto [type1_bytes, unused1] = accounted(EvaluatorType::type1, false);
  table.add({"I", "C1 = N^3", with_commas(solid::paper_words_c1(R)), bytes_text(4.0 * solid::paper_words_c1(R)), bytes_text(type1_bytes),
             measured(EvaluatorType::type1, "all")});
  const auto [type2_sphere, sphere_nodes] = accounted(EvaluatorType::type2, true);
  table.add({"II (sphere)", "C2 = 13 x nodes", with_commas(solid::paper_words_c2(sphere_nodes)),
             bytes_text(4.0 * solid::paper_words_c2(sphere_nodes)), bytes_text(type2_sphere), measured(EvaluatorType::type2, "sphere")});
  const auto [type2_all, all_nodes] = accounted(EvaluatorType::type2, false);
  table.add({"II (all points)", "C2 = 13 x nodes", with_commas(solid::paper_words_c2(all_nodes)),
             bytes_text(4.0 * solid::paper_words_c2(all_nodes)), bytes_text(type2_all), measured(EvaluatorType::type2, "all")});
  const auto [type3_bytes, unused3] = accounted(EvaluatorType::type3, true);
  table.add({"III", "C3 = 13 x 19 x R", with_commas(solid::paper_words_c3(R)), bytes_text(4.0 * solid::paper_words_c3(R)),
             bytes_text(type3_bytes), measured(EvaluatorType::type3, "sphere")});
  const auto [type4_bytes, unused4] = accounted(EvaluatorType::type4, true);
  table.add({"IV", "C4 = N2^3 + 13 x 19 x (R-R2)", with_commas(solid::paper_words_c4(R, r2)),
             bytes_text(4.0 * solid::paper_words_c4(R, r2)), bytes_text(type4_bytes), measured(EvaluatorType::type4, "sphere")});
  table.print();
  fmt::print("  Type II nodes: {} for the sphere's {} surface voxels, {} for all points.\n", with_commas(sphere_nodes),
             with_commas(static_cast<double>(solid::digital_sphere_surface(R).size())), with_commas(all_nodes));
}

void reach_table(const SolidBenchOptions& o) {
  const auto available = static_cast<double>(available_memory_bytes());
  fmt::print("\nHow far each type goes on this machine ({} of memory available now)\n\n", bytes_text(available));
  int type1_max = 0;
  while (type1_max < 20 && 4.0 * solid::paper_words_c1(type1_max + 1) <= available) ++type1_max;
  int type2_max = 0;  // all points: one map node per lattice point
  while (type2_max < 20 && static_cast<double>(solid::type2_bytes_per_node) * solid::paper_words_c1(type2_max + 1) <= available)
    ++type2_max;
  Table table({"type", "largest R", "limit", "memory at that R"});
  table.add({"I", std::to_string(type1_max),
             fmt::format("R = {} needs {}", type1_max + 1, bytes_text(4.0 * solid::paper_words_c1(type1_max + 1))),
             bytes_text(4.0 * solid::paper_words_c1(type1_max))});
  table.add({"II (all points)", std::to_string(type2_max),
             fmt::format("R = {} needs about {}", type2_max + 1, bytes_text(40.0 * solid::paper_words_c1(type2_max + 1))),
             bytes_text(40.0 * solid::paper_words_c1(type2_max))});
  table.add({"III", std::to_string(solid::max_levels), "coordinates hashed in 21 bits per axis", bytes_text(120.0 * solid::max_levels)});
  table.add({fmt::format("IV (R2={})", o.r2), std::to_string(solid::max_levels), "as III",
             bytes_text(4.0 * solid::paper_words_c1(o.r2) + 120.0 * (solid::max_levels - o.r2))});
  table.print();
  fmt::print("  Types III and IV are limited by time, not memory: a surface at R = 20 has ~10^13 voxels.\n");
}

void targets(const SolidBenchOptions& o, const Context& context) {
  fmt::print("\nIssue targets (load average now {:.1f} on {} threads: wall times are shared with other work)\n\n", load_average(),
             tbb::info::default_concurrency());
  const FieldParams p9 = field_of(9, o.seed);
  const double points9 = std::pow(p9.side(), 3.0);
  TableProgress progress(context, "targets", 10.0);  // the ten measurements below
  // Type I at 513^3 on all threads; the first fill pays the operating system's first touch of
  // the memory, so the best of three is reported.
  Seconds best{1e30, 1e30};
  for (int i = 0; i < 3; ++i) {
    const Seconds s = measure([&] {
      solid::Volume v = solid::generate_type1(p9);
      sink = sink + v(1, 2, 3);
    });
    if (s.wall < best.wall) best = s;
    progress.advance();
  }
  double type1_one_thread = 1e30;
  tbb::task_arena(1).execute([&] {
    for (int i = 0; i < 2; ++i)
      type1_one_thread = std::min(type1_one_thread, measure([&] {
                                                      solid::Volume v = solid::generate_type1(p9);
                                                      sink = sink + v(1, 2, 3);
                                                    }).cpu);
  });
  progress.advance(2.0);
  const double type1_ns = type1_one_thread / points9 * 1e9;
  Table table({"measure", "ours", "target"});
  table.add({"Type I fill 513^3, all threads: points/s (wall)", fmt::format("{:.0f} M", points9 / best.wall / 1e6), ">= 100 M"});
  table.add({"Type I fill 513^3, points per CPU second (x cores = rate on an idle machine)",
             fmt::format("{:.0f} M (x{} = {:.0f} M)", points9 / best.cpu / 1e6, tbb::info::default_concurrency(),
                         points9 / best.cpu / 1e6 * tbb::info::default_concurrency()),
             ">= 100 M"});
  table.add({"Type I per point, one thread (reference)", fmt::format("{:.1f} ns", type1_ns), ""});

  // Type III per point in three orders, one thread, R = 9.
  auto per_point = [&](const std::function<void(FieldEvaluator&)>& work, double count, EvaluatorType type, int r2) {
    auto field = solid::make_evaluator(type, p9, {r2, true});
    double seconds = 0.0;
    tbb::task_arena(1).execute([&] { seconds = measure([&] { work(*field); }).cpu; });
    progress.advance();
    return seconds / count * 1e9;
  };
  const int side = p9.side(), planes = 16;
  const double raster_ns = per_point(
      [&](FieldEvaluator& f) {
        float sum = 0.0f;
        for (int z = 200; z < 200 + planes; ++z)
          for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) sum += f.at(x, y, z);
        sink = sink + sum;
      },
      static_cast<double>(planes) * side * side, EvaluatorType::type3, 0);
  const auto sphere_raster = solid::digital_sphere_surface(9);
  auto sphere_octree = sphere_raster;
  solid::sort_along_octree(sphere_octree);
  const double surface_ns = per_point([&](FieldEvaluator& f) { query_voxels(f, sphere_octree); }, static_cast<double>(sphere_octree.size()),
                                      EvaluatorType::type3, 0);
  const double surface_raster_ns = per_point([&](FieldEvaluator& f) { query_voxels(f, sphere_raster); },
                                             static_cast<double>(sphere_raster.size()), EvaluatorType::type3, 0);
  std::vector<solid::SurfaceVoxel> random(200000);
  for (std::size_t i = 0; i < random.size(); ++i)
    random[i] = {static_cast<int>(rng::uniform(7, 3, static_cast<int>(i), 0) * side),
                 static_cast<int>(rng::uniform(7, 3, static_cast<int>(i), 1) * side),
                 static_cast<int>(rng::uniform(7, 3, static_cast<int>(i), 2) * side)};
  const double random_ns =
      per_point([&](FieldEvaluator& f) { query_voxels(f, random); }, static_cast<double>(random.size()), EvaluatorType::type3, 0);
  auto ratio = [&](double ns) { return fmt::format("{:.0f} ns = {:.1f}x Type I", ns, ns / type1_ns); };
  table.add({"Type III per point, raster order (R = 9)", ratio(raster_ns), "<= 50x"});
  table.add({"Type III per point, along the sphere's surface (octree order, R = 9)", ratio(surface_ns), "<= 50x"});
  table.add({"Type III per point, sphere's surface in raster order (R = 9)", ratio(surface_raster_ns), "(reported)"});
  table.add({"Type III per point, random order (R = 9)", ratio(random_ns), "(reported)"});

  // Type IV on the Experiment 2 sphere at R = 10, set-up included, one thread.
  auto sphere10 = solid::digital_sphere_surface(10);
  solid::sort_along_octree(sphere10);
  const double type4_seconds = one_thread_seconds(EvaluatorType::type4, field_of(10, o.seed), std::min(o.r2, 10), true,
                                                  [&](FieldEvaluator& f) { query_voxels(f, sphere10); });
  progress.advance();
  table.add(
      {fmt::format("Type IV, Experiment 2 sphere at R = 10 ({} voxels), one thread", with_commas(static_cast<double>(sphere10.size()))),
       fmt::format("{:.2f} s", type4_seconds), "< 3 s"});
  table.print();
}

}  // namespace

const params::Table<SolidBenchOptions>& parameter_table(const SolidBenchOptions*) {
  using P = SolidBenchOptions;
  static const auto table =
      params::Table<P>("bench_solid", "The solid-texture paper's experiments as a benchmark")
          .add(params::field("exp1_from", &P::exp1_from).in(1, 12).doc("Experiment 1: first R"))
          .add(params::field("exp1_to", &P::exp1_to).in(1, 12).doc("Experiment 1: last R"))
          .add(params::field("exp2_from", &P::exp2_from).in(1, 12).doc("Experiment 2: first R"))
          .add(params::field("exp2_to", &P::exp2_to).in(1, 12).doc("Experiment 2: last R"))
          .add(params::field("memory_levels", &P::memory_levels).in(1, 12).doc("R of the memory table"))
          .add(params::field("r2", &P::r2).in(0, 10).doc("Type IV's array levels"))
          .add(params::field("max_seconds", &P::max_seconds)
                   .above(0)
                   .units("s")
                   .doc("Skip a cell whose estimate exceeds this (printed as an estimate)"))
          .add(params::field("full", &P::full).doc("Also run Types I and II where they need gigabytes (Type I at R = 10: 4.3 GB)"))
          .add(params::field("skip_memory", &P::skip_memory).doc("Skip the peak-RSS measurements (child processes)"))
          .add(params::field("skip_targets", &P::skip_targets).doc("Skip the issue's target measurements (R = 9 and 10, about a minute)"))
          .add(params::field("seed", &P::seed).doc("Field seed"))
          .add(params::field("child", &P::child).internal().doc("One memory measurement in a child process: TYPE,R,R2,WORKLOAD,RUN"));
  return table;
}

void run_solid_experiments(const SolidBenchOptions& o, const Context& context) {
  if (!o.child.empty()) {
    run_memory_child(o.child);
    return;
  }
  params::validate(o);
  if (o.exp1_from > o.exp1_to || o.exp2_from > o.exp2_to) fail("the first R must not exceed the last");
  fmt::print("Solid textures by 3-D random fractals: the experiments of Okada, Taga, Yokoi, Toriwaki (1990)\n");
  fmt::print("Seed {}, beta 0.6, corners 0. All four types give the same values bit for bit; only time and memory differ.\n", o.seed);
  experiment_1(o, context);
  experiment_2(o, context);
  memory_table(o, context);
  reach_table(o);
  if (!o.skip_targets) targets(o, context);
}

}  // namespace sansui::bench
