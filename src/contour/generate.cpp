// Contour-line generation (Misawa, Chiba, Saito 1987, Secs. 3-4): see generate.hpp.
#include "contour/generate.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>

#include "contour/clipping.hpp"
#include "contour/cols.hpp"
#include "contour/decimate.hpp"
#include "contour/fourier.hpp"
#include "contour/midpoint.hpp"
#include "contour/offset_field.hpp"
#include "contour/random_keys.hpp"
#include "contour/scale.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::contour {

std::optional<Method> method_from_name(std::string_view name) {
  if (name == "simple") return Method::simple;
  if (name == "midpoint") return Method::midpoint;
  if (name == "fourier") return Method::fourier;
  if (name == "revised") return Method::revised;
  return std::nullopt;
}

std::string_view name_of(Method method) {
  switch (method) {
    case Method::simple:
      return "simple";
    case Method::midpoint:
      return "midpoint";
    case Method::fourier:
      return "fourier";
    case Method::revised:
      return "revised";
  }
  return "?";
}

double GenerationParams::resolved_clip_factor() const {
  return clip_factor.value_or(method == Method::revised ? 3.0 : 1.4);
}
double GenerationParams::resolved_displacement_fraction() const {
  return displacement_fraction.value_or(method == Method::revised ? 0.5 : 0.3);
}
double GenerationParams::resolved_theta_min_deg() const {
  return theta_min_deg.value_or(method == Method::revised ? 20.0 : 0.0);
}
double GenerationParams::resolved_theta_max_deg() const {
  return theta_max_deg.value_or(method == Method::revised ? 40.0 : 20.0);
}

double GenerationParams::offset_for_level(int level) const {
  if (offset_schedule_m.empty() || level < 1) return resolved_offset_m();
  return offset_schedule_m[std::min(static_cast<std::size_t>(level - 1), offset_schedule_m.size() - 1)];
}

namespace {

/// Whole intervals from z0 down to base, and the fraction of one more (0 when base is a whole
/// number of intervals below z0).
std::pair<int, double> intervals_to_base(double z0, double base, double interval) {
  const double steps = (z0 - base) / interval;
  const int full = static_cast<int>(std::floor(steps + 1e-9));
  const double rest = steps - full;
  return {full, rest > 1e-6 ? rest : 0.0};
}

}  // namespace

int GenerationParams::resolved_outward_levels() const {
  if (!base_m) return outward_levels;
  const auto [full, rest] = intervals_to_base(resolved_z0_m(), *base_m, interval_m);
  const int to_base = full + (rest > 0.0 ? 1 : 0);
  return outward_levels > 0 ? std::min(outward_levels, to_base) : to_base;
}

double GenerationParams::last_outward_fraction() const {
  if (!base_m) return 1.0;
  const auto [full, rest] = intervals_to_base(resolved_z0_m(), *base_m, interval_m);
  if (rest == 0.0 || (outward_levels > 0 && outward_levels <= full)) return 1.0;
  return rest;
}

namespace {

using Clock = std::chrono::steady_clock;

/// Adds the time since construction to a shared total when destroyed.
class StepTimer {
 public:
  explicit StepTimer(std::atomic<double>* total) : total_(total), start_(Clock::now()) {}
  ~StepTimer() {
    if (total_ == nullptr) return;
    // A compare-exchange loop, not fetch_add: atomic<double>::fetch_add is C++20 library that the
    // browser build's libc++ (Emscripten 3.1.6) lacks.
    const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    for (double old = total_->load(); !total_->compare_exchange_weak(old, old + seconds);) {}
  }
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;

 private:
  std::atomic<double>* total_;
  Clock::time_point start_;
};

struct Timers {
  std::atomic<double> offset{0}, midpoint{0}, fourier{0}, decimate{0}, loops{0}, clip{0};
};

bool overlaps(const Box& a, const Box& b) {
  return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
}

std::vector<Ring> larger_than(std::vector<Ring> rings, double min_area) {
  std::erase_if(rings, [&](const Ring& r) { return r.size() < 3 || signed_area(r) < min_area; });
  return rings;
}

class Generator {
 public:
  Generator(const GenerationParams& params, double seed_mean_segment, const OffsetField& field, Timers* timers)
      : p_(params), d0_(seed_mean_segment), field_(field), timers_(timers) {}

  /// The spacing the midpoint displacement works at for offset d: the seed's mean segment d0, as
  /// in the paper, but at least d, so that a densely sampled seed (a real contour traced at a fine
  /// resolution) gets displacements of d'' too (issue 17 item 2). A split of a segment of length
  /// 2l moves by min(d'', l tan theta), tiny when l is; segments longer than 2d have l > d, and
  /// l tan(theta_max) reaches d'' there with the paper's values (0.3 d and 20 degrees for
  /// midpoint, 0.5 d and 40 for revised). The paper's seeds are coarser than 2d anyway.
  double spacing(double d) const { return std::max(d0_, d); }

  /// The local scale of the spacing and the displacement: the offset field's factor (inward).
  std::function<double(Point)> local_scale(int level) const {
    if (field_.constant() || level < 0) return {};
    return [this](Point p) { return field_.factor(p); };
  }

  /// The perturbation of one new contour (before loop removal), by method.
  Ring perturb(Ring ring, double d, int level, std::uint64_t identity) const {
    const double long_segment = 2.0 * spacing(d);
    if (p_.method == Method::midpoint || p_.method == Method::revised) {
      StepTimer timer(timers_ ? &timers_->midpoint : nullptr);
      if (p_.method == Method::midpoint && spacing(d) > d0_) {
        // A seed denser than d has few segments to split: first drop its flattest points
        // until some are long (as the revised method does after its Fourier step).
        ring = drop_collinear_points(ring, {long_segment, p_.long_fraction, 8, local_scale(level)});
      }
      MidpointDisplacementParams mp{long_segment, p_.resolved_displacement_fraction() * d, p_.resolved_theta_min_deg(),
                                    p_.resolved_theta_max_deg(), local_scale(level)};
      ring = displace_midpoints(ring, mp, contour_key(p_.seed, Stream::midpoint_sign, level, identity),
                                contour_key(p_.seed, Stream::midpoint_angle, level, identity));
    }
    if (p_.method == Method::fourier || p_.method == Method::revised) {
      {
        StepTimer timer(timers_ ? &timers_->fourier : nullptr);
        ring = randomise_phases(ring, {p_.samples, p_.f0}, contour_key(p_.seed, Stream::fourier_phase, level, identity));
      }
      if (p_.method == Method::revised) {
        StepTimer timer(timers_ ? &timers_->decimate : nullptr);
        ring = drop_collinear_points(ring, {long_segment, p_.long_fraction, 8, local_scale(level)});
      }
    }
    return ring;
  }

  std::vector<Ring> without_loops(const Ring& ring) const {
    if (p_.method == Method::simple) return {ring};  // offsets of simple rings are simple
    StepTimer timer(timers_ ? &timers_->loops : nullptr);
    return remove_loops(ring, p_.loops);
  }

  OffsetParams offset_params(double d, bool outward) const {
    OffsetParams params{d, p_.resolved_join(), p_.resolved_clip_factor(), p_.arc_step_deg, outward, {}};
    if (!field_.constant() && !outward) params.edge_distance = [this, d](Point a, Point b) { return d * field_.factor(0.5 * (a + b)); };
    return params;
  }

  PrecleanParams preclean_params(double d) const { return {p_.preclean_segment_fraction * d, p_.preclean_angle_deg}; }

  /// The contours one level above `parent`, inside it: shrink, perturb, remove loops, clip.
  std::vector<Ring> children_of(const Ring& parent, int parent_id, int level) const {
    return children_of(parent, parent_id, level, p_.offset_for_level(level), p_.resolved_min_area_m2());
  }

  /// The same with offset `d` and smallest area `min_area` (a crater's levels).
  std::vector<Ring> children_of(const Ring& parent, int parent_id, int level, double d, double min_area) const {
    const double clearance = p_.clearance_fraction * d;
    std::vector<Ring> islands;
    {
      StepTimer timer(timers_ ? &timers_->offset : nullptr);
      islands = larger_than(offset_ring(preclean(parent, preclean_params(d)), offset_params(d, false)), min_area);
    }
    // Larger islands first, so a small one can never swallow a larger sibling when clipped.
    std::stable_sort(islands.begin(), islands.end(), [](const Ring& a, const Ring& b) { return signed_area(a) > signed_area(b); });
    std::vector<Ring> accepted;
    std::vector<Ring> grown;  // accepted siblings grown by the clearance, each once
    std::vector<Box> grown_bounds;
    std::vector<Ring> inside;  // the parent less the clearance, computed when first needed
    for (std::size_t s = 0; s < islands.size(); ++s) {
      const std::uint64_t identity = (static_cast<std::uint64_t>(parent_id) << 20) | s;
      std::vector<Ring> rings = without_loops(perturb(islands[s], d, level, identity));
      if (p_.method == Method::simple && field_.constant()) {
        // Offsets of a simple ring lie at distance d inside it and apart from each other (a varied
        // d can make them touch: clipped below like the other methods' contours).
        for (Ring& r : larger_than(std::move(rings), min_area)) accepted.push_back(std::move(r));
        continue;
      }
      StepTimer timer(timers_ ? &timers_->clip : nullptr);
      if (inside.empty()) inside = clearance > 0.0 ? inflate({parent}, -clearance) : std::vector<Ring>{parent};
      rings = intersection(rings, inside);
      // Only the grown siblings whose bounds meet these rings' bounds can cut them.
      std::vector<Ring> near;
      const Box box = bounds(rings);
      for (std::size_t k = 0; k < grown.size(); ++k)
        if (!box.empty() && overlaps(box, grown_bounds[k])) near.push_back(grown[k]);
      if (!near.empty()) rings = difference(rings, near);
      for (Ring& r : larger_than(std::move(rings), min_area)) {
        for (Ring& g : clearance > 0.0 ? inflate({r}, clearance) : std::vector<Ring>{r}) {
          grown_bounds.push_back(bounds(g));
          grown.push_back(std::move(g));
        }
        accepted.push_back(std::move(r));
      }
    }
    return accepted;
  }

  /// The contour one level below `inner` (the current outermost), around it.
  std::optional<Ring> expansion_of(const Ring& inner, int level, double d) const {
    const double clearance = p_.clearance_fraction * d;
    std::vector<Ring> grown;
    {
      StepTimer timer(timers_ ? &timers_->offset : nullptr);
      grown = offset_ring(preclean(inner, preclean_params(d)), offset_params(d, true));
    }
    if (grown.empty()) return std::nullopt;
    std::vector<Ring> rings = without_loops(perturb(largest(grown), d, level, 0));
    StepTimer timer(timers_ ? &timers_->clip : nullptr);
    // It must enclose the inner contour with the clearance: add the inner contour, grown a little.
    std::vector<Ring> around = clearance > 0.0 ? inflate({inner}, clearance) : std::vector<Ring>{inner};
    rings.insert(rings.end(), around.begin(), around.end());
    rings = positive_region(rings);
    if (rings.empty()) return std::nullopt;
    // The piece holding the grown inner contour (a varied offset can leave a larger stray piece).
    for (const Ring& r : rings)
      if (contains(r, inner.front())) return r;
    return largest(rings);
  }

  /// The contours one level below several outermost contours (islands), around them: each is
  /// grown and perturbed as above, then all are united (with the inner contours grown by the
  /// clearance), so the foot contours of islands that come close merge into one. Each result
  /// comes with the indices of the inner contours it encloses.
  std::vector<std::pair<Ring, std::vector<std::size_t>>> expansion_of(const std::vector<const Ring*>& inner, int level, double d) const {
    const double clearance = p_.clearance_fraction * d;
    std::vector<Ring> rings;
    for (std::size_t i = 0; i < inner.size(); ++i) {
      std::vector<Ring> grown;
      {
        StepTimer timer(timers_ ? &timers_->offset : nullptr);
        grown = offset_ring(preclean(*inner[i], preclean_params(d)), offset_params(d, true));
      }
      if (grown.empty()) continue;
      for (Ring& r : without_loops(perturb(largest(grown), d, level, i))) rings.push_back(std::move(r));
    }
    StepTimer timer(timers_ ? &timers_->clip : nullptr);
    for (const Ring* r : inner)
      for (Ring& g : clearance > 0.0 ? inflate({*r}, clearance) : std::vector<Ring>{*r}) rings.push_back(std::move(g));
    std::vector<std::pair<Ring, std::vector<std::size_t>>> out;
    for (Ring& r : positive_region(rings)) {
      std::vector<std::size_t> holds;
      for (std::size_t i = 0; i < inner.size(); ++i)
        if (contains(r, inner[i]->front())) holds.push_back(i);
      if (!holds.empty()) out.emplace_back(std::move(r), std::move(holds));  // stray pieces go
    }
    return out;
  }

  static Ring largest(const std::vector<Ring>& rings) {
    return *std::max_element(rings.begin(), rings.end(), [](const Ring& a, const Ring& b) { return signed_area(a) < signed_area(b); });
  }

 private:
  const GenerationParams& p_;
  double d0_;
  const OffsetField& field_;
  Timers* timers_;
};

/// Adds the children of each frontier contour (children[i] of frontier[i], in order) to the
/// tree at `level` and elevation `z`. Returns their ids, in the order added.
std::vector<int> add_children(ContourTree& tree, const std::vector<int>& frontier, std::vector<std::vector<Ring>>& children, int level,
                              double z) {
  std::vector<int> added;
  for (std::size_t i = 0; i < frontier.size(); ++i)
    for (Ring& ring : children[i]) {
      const int id = static_cast<int>(tree.nodes.size());
      tree.nodes.push_back({std::move(ring), level, z, frontier[i], {}});
      tree.nodes[static_cast<std::size_t>(frontier[i])].children.push_back(id);
      added.push_back(id);
    }
  return added;
}

/// Levels descending inside the rim (the largest summit contour when `rim` < 0) by dz, the
/// last at exactly rim - depth, spaced so that the floor keeps crater_floor of the rim's inradius.
void grow_crater(ContourTree& tree, int rim, const GenerationParams& params, const Generator& generator) {
  if (rim < 0) {
    for (int s : tree.summits())
      if (tree.nodes[static_cast<std::size_t>(s)].level >= 0 &&
          (rim < 0 ||
           signed_area(tree.nodes[static_cast<std::size_t>(s)].ring) > signed_area(tree.nodes[static_cast<std::size_t>(rim)].ring)))
        rim = s;
  }
  const double depth = *params.crater_depth_m;
  const double rim_z = tree.nodes[static_cast<std::size_t>(rim)].elevation_m;
  double foot = rim_z;
  for (const ContourNode& node : tree.nodes) foot = std::min(foot, node.elevation_m);
  if (params.base_m) foot = std::min(foot, *params.base_m);
  if (rim_z - depth < foot - 1e-9)
    fail(
        "contour.crater_depth {:g} m is not allowed: the crater's floor would be at {:g} m, below the map's base {:g} m (the rim is at "
        "{:g} m); it must be > 0 and at most {:g} m here",
        depth, rim_z - depth, foot, rim_z, rim_z - foot);
  const int levels = std::max(1, static_cast<int>(std::ceil(depth / params.interval_m - 1e-9)));
  const double d = (1.0 - params.crater_floor) * inradius(tree.nodes[static_cast<std::size_t>(rim)].ring) / levels;
  const int rim_level = tree.nodes[static_cast<std::size_t>(rim)].level;
  std::vector<int> frontier{rim};
  for (int k = 1; k <= levels && !frontier.empty(); ++k) {
    const int level = rim_level + k;
    const double z = k == levels ? rim_z - depth : rim_z - k * params.interval_m;
    std::vector<std::vector<Ring>> children(frontier.size());
    parallel_for(std::size_t{0}, frontier.size(), [&](std::size_t i) {
      const int parent = frontier[i];
      children[i] = generator.children_of(tree.nodes[static_cast<std::size_t>(parent)].ring, parent, level, d, 0.25 * d * d);
    });
    std::vector<int> next = add_children(tree, frontier, children, level, z);
    if (next.empty()) {
      // Nothing fits one level further in: the deepest contours so far are the floor.
      for (int f : frontier)
        if (f != rim) tree.nodes[static_cast<std::size_t>(f)].elevation_m = rim_z - depth;
      if (frontier.size() == 1 && frontier[0] == rim) fail("the crater's rim ({:g} m) is too small for a crater", rim_z);
    }
    frontier = std::move(next);
  }
}

/// The seeds must be counter-clockwise polygons; InputError otherwise, or without any.
void check_seeds(const std::vector<Ring>& seeds) {
  if (seeds.empty()) fail("no seed contour: give at least one");
  for (const Ring& seed : seeds)
    if (seed.size() < 3 || !(signed_area(seed) > 0.0)) fail("the seed contour must be a counter-clockwise polygon with area > 0");
}

/// Refuses runaway work before any: first a cheap bound (half the narrower side of the bounds
/// is at least the inradius), then the estimate (the most levels of any seed, the time of all).
void refuse_runaway_work(const std::vector<Ring>& seeds, const GenerationParams& params) {
  double d_min = params.resolved_offset_m();
  for (double d : params.offset_schedule_m) d_min = std::min(d_min, d);
  double levels_bound = 0.0, seconds_bound = 0.0;
  for (const Ring& seed : seeds) {
    const Box box = bounds(seed);
    const double levels = 0.5 * std::min(box.width(), box.height()) / d_min + params.resolved_outward_levels();
    levels_bound = std::max(levels_bound, levels);
    seconds_bound += 4e-6 * std::max(static_cast<double>(seed.size()), static_cast<double>(params.samples)) * levels;
  }
  if (levels_bound > level_limit || seconds_bound > seconds_limit) {
    WorkEstimate all;
    for (const Ring& seed : seeds) {
      const WorkEstimate e = estimate_work(seed, params);
      if (e.levels > all.levels) all.inward_levels = e.inward_levels, all.outward_levels = e.outward_levels, all.levels = e.levels;
      all.vertices += e.vertices, all.seconds += e.seconds;
    }
    check_work(all, params);
  }
}

/// What the growth needs to know of the seeds together.
struct SeedsMeasure {
  Box box;
  double perimeters = 0.0, vertices = 0.0;  // sums over the seeds
  double largest_area = 0.0, area = 0.0;    // the largest seed's area, and all seeds' [Units: m^2]
};

SeedsMeasure measure_seeds(const std::vector<Ring>& seeds) {
  SeedsMeasure m;
  for (const Ring& seed : seeds) {
    for (const Point& p : seed) m.box.add(p);
    m.perimeters += perimeter(seed), m.vertices += static_cast<double>(seed.size());
    m.largest_area = std::max(m.largest_area, signed_area(seed)), m.area += signed_area(seed);
  }
  return m;
}

/// The level's largest contour is the main branch; once no wider than the rim, it is the rim:
/// taken out of `next` (the main branch stops there). Returns the rim, or -1.
int take_crater_rim(const ContourTree& tree, std::vector<int>& next, double rim_area) {
  auto largest = next.begin();
  for (auto it = next.begin(); it != next.end(); ++it)
    if (signed_area(tree.nodes[static_cast<std::size_t>(*it)].ring) > signed_area(tree.nodes[static_cast<std::size_t>(*largest)].ring))
      largest = it;
  if (!(signed_area(tree.nodes[static_cast<std::size_t>(*largest)].ring) <= rim_area)) return -1;
  const int rim = *largest;
  next.erase(largest);
  return rim;
}

/// Inward from the seeds (the tree's first nodes), level by level; the contours of one level in
/// parallel. Several seeds grow side by side, each inside its own ring, as the islands of a
/// split do. Returns the crater's rim (-1 without a crater).
int grow_inward(ContourTree& tree, std::size_t seed_count, const Generator& generator, const GenerationParams& params,
                const SeedsMeasure& seeds, const Context& context) {
  std::vector<int> frontier;
  for (std::size_t i = 0; i < seed_count; ++i) frontier.push_back(static_cast<int>(i));
  const double seed_area = seeds.area;
  const bool crater = params.crater_depth_m.has_value();
  const double rim_area = params.crater_width * params.crater_width * seeds.largest_area;
  int rim = -1;  // the crater's rim: the main branch stops there
  for (int level = 1; level <= params.max_levels && !frontier.empty(); ++level) {
    context.check_cancelled();
    std::vector<std::vector<Ring>> children(frontier.size());
    parallel_for(std::size_t{0}, frontier.size(), [&](std::size_t i) {
      const int parent = frontier[i];
      children[i] = generator.children_of(tree.nodes[static_cast<std::size_t>(parent)].ring, parent, level);
    });
    std::vector<int> next = add_children(tree, frontier, children, level, params.resolved_z0_m() + level * params.interval_m);
    double remaining_area = 0.0;
    for (int id : next) remaining_area += signed_area(tree.nodes[static_cast<std::size_t>(id)].ring);
    if (crater && rim < 0 && !next.empty()) rim = take_crater_rim(tree, next, rim_area);
    frontier = std::move(next);
    context.report("contours", 1.0 - std::sqrt(std::max(0.0, remaining_area / seed_area)));
  }
  return rim;
}

/// Outward, toward the foot: each new contour becomes the parent of the previous outermost
/// (the seeds at first); the foot contours of islands that come close merge into one.
void grow_outward(ContourTree& tree, std::size_t seed_count, const Generator& generator, const GenerationParams& params,
                  const Context& context) {
  const int outward = params.resolved_outward_levels();
  std::vector<int> outermost(seed_count);
  for (std::size_t i = 0; i < seed_count; ++i) outermost[i] = static_cast<int>(i);
  for (int k = 1; k <= outward && !outermost.empty(); ++k) {
    context.check_cancelled();
    // The last level stops at base exactly: its offset is d times the interval's remaining
    // fraction (at least d / 4, so it does not crowd the one above).
    const double fraction = k == outward ? params.last_outward_fraction() : 1.0;
    const double d = params.resolved_offset_m() * std::max(0.25, fraction);
    const double z = fraction < 1.0 ? *params.base_m : params.resolved_z0_m() - k * params.interval_m;
    if (outermost.size() == 1) {
      auto ring = generator.expansion_of(tree.nodes[static_cast<std::size_t>(outermost[0])].ring, -k, d);
      if (!ring) break;
      const int id = static_cast<int>(tree.nodes.size());
      tree.nodes.push_back({std::move(*ring), -k, z, -1, {outermost[0]}});
      tree.nodes[static_cast<std::size_t>(outermost[0])].parent = id;
      outermost = {id};
      continue;
    }
    std::vector<const Ring*> inner;
    inner.reserve(outermost.size());
    for (int id : outermost) inner.push_back(&tree.nodes[static_cast<std::size_t>(id)].ring);
    auto made = generator.expansion_of(inner, -k, d);
    if (made.empty()) break;
    std::vector<int> next;
    for (auto& [ring, holds] : made) {
      const int id = static_cast<int>(tree.nodes.size());
      std::vector<int> children;
      for (std::size_t i : holds) children.push_back(outermost[i]);
      tree.nodes.push_back({std::move(ring), -k, z, -1, children});
      for (int child : children) tree.nodes[static_cast<std::size_t>(child)].parent = id;
      next.push_back(id);
    }
    outermost = std::move(next);
  }
}

void add_times(GenerationTimes& times, const Timers& timers) {
  times.offset_s += timers.offset.load();
  times.midpoint_s += timers.midpoint.load();
  times.fourier_s += timers.fourier.load();
  times.decimate_s += timers.decimate.load();
  times.loops_s += timers.loops.load();
  times.clip_s += timers.clip.load();
}

}  // namespace

ContourTree generate_contours(const Ring& seed, const GenerationParams& params, const Context& context, GenerationTimes* times) {
  return generate_contours(std::vector<Ring>{seed}, params, context, times);
}

ContourTree generate_contours(const std::vector<Ring>& seeds, const GenerationParams& params, const Context& context,
                              GenerationTimes* times) {
  params.validate();
  check_seeds(seeds);
  if (!params.force) refuse_runaway_work(seeds, params);
  Timers timers;
  const SeedsMeasure measure = measure_seeds(seeds);
  OffsetField field(params.offset_variation, params.offset_hurst, 0.5 * std::max(measure.box.width(), measure.box.height()),
                    params.resolved_offset_m(), params.seed);
  field.normalise_inside(seeds);
  const double d0 = seeds.size() == 1 ? mean_segment_length(seeds[0]) : measure.perimeters / measure.vertices;
  const Generator generator(params, d0, field, &timers);
  ContourTree tree;
  for (const Ring& seed : seeds) tree.nodes.push_back({seed, 0, params.resolved_z0_m(), -1, {}});
  tree.seed = 0;

  const int rim = grow_inward(tree, seeds.size(), generator, params, measure, context);
  grow_outward(tree, seeds.size(), generator, params, context);
  if (params.crater_depth_m.has_value()) grow_crater(tree, rim, params, generator);
  if (params.col_depth_m > 0.0) {
    StepTimer timer(&timers.clip);
    const int levels = std::max(1, static_cast<int>(std::lround(params.col_depth_m / params.interval_m)));
    dip_cols(tree, {levels, params.resolved_offset_m(), params.resolved_min_area_m2()});
  }
  context.report("contours", 1.0);
  if (times != nullptr) add_times(*times, timers);
  return tree;
}

}  // namespace sansui::contour
