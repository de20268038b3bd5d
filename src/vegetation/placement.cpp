// Plant placement (SPEC 3.3, seed 003 Sec. 4.1.6): a jittered grid in world coordinates.
//
// Grid cell (i, j) of side s covers [i s, (i + 1) s) x [j s, (j + 1) s) in world metres, and
// holds at most one plant, at a point jittered inside it. Everything about that plant (whether it
// is there, where, which species, its size, turn and shape) comes from counter-based random
// numbers keyed by (seed, layer and purpose, i, j), and from the ground under it, so a plant does
// not depend on which heightfield it is placed on: a tile and the whole world agree exactly, in any
// order and with any number of threads. A jittered grid and not Poisson-disc sampling because the
// latter's dart throwing depends on the order of the darts, which would break that; with jitter
// the gaps still look natural from above, and density is simply the share of cells kept.
//
// Forests are not even, though: trees stand in groves, leave clearings and thin out at edges, on
// steep slopes and toward the tree line (Oka et al. 1997 place by climate only). So each tree
// cell holds up to trees_per_cell candidates, kept with the probability density x field / count,
// where the field is value noise at three scales (groves of a few hundred metres, clumps of a few
// tens) looked up at the cell's centre on lattices at integer world coordinates: an
// inhomogeneous Poisson (Cox) process, clustered where the field varies (Clark-Evans R < 1) and
// with the climate's density on average. Species are picked by a smooth patch field as well as
// per tree, so neighbours are often of one species, and each tree's age (many young and small,
// few old and large) sets its size.
#include "vegetation/placement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>

#include "core/budget.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"

namespace sansui::vegetation {

const params::Table<VegetationParams>& parameter_table(const VegetationParams*) {
  using P = VegetationParams;
  static const auto table =
      params::Table<P>("vegetation", "Plants (Oka et al. 1997, Sec. 4.1.6): trees on a jittered grid and a dense ground layer, by climate")
          .add(params::field("enabled", &P::enabled).doc("Place and draw plants at all").grouped("vegetation"))
          .add(params::field("seed", &P::seed)
                   .doc("Seed of the placement: which grid cells hold a plant, its species, size and turn")
                   .grouped("vegetation"))
          .add(params::field("density", &P::density)
                   .in(0, 1)
                   .no_unit()
                   .unset("the climate's (Table 4)")
                   .doc("Share of the tree grid's cells that hold a tree, on flat land inside the forest band")
                   .grouped("vegetation"))
          .add(params::field("spacing", &P::spacing_m)
                   .in(1, 1000)
                   .units("m")
                   .doc("Side of a tree grid cell: at density 1 there is one tree per cell")
                   .grouped("vegetation"))
          .add(params::field("ground_density", &P::ground_density)
                   .in(0, 1)
                   .no_unit()
                   .unset("the climate's")
                   .doc("Share of the ground grid's cells holding grass or a small plant")
                   .grouped("vegetation"))
          .add(params::field("ground_spacing", &P::ground_spacing_m)
                   .in(0.2, 100)
                   .units("m")
                   .doc("Side of a ground grid cell")
                   .grouped("vegetation"))
          .add(params::field("size_factor", &P::scale)
                   .in(0.05, 20)
                   .no_unit()
                   .doc("Plants' sizes are multiplied by this")
                   .grouped("vegetation"))
          .add(
              params::field("clumping", &P::clumping)
                  .in(0, 1)
                  .no_unit()
                  .doc("How much a smooth noise field gathers trees into groves and opens clearings and edges, keeping the mean density; 0 "
                       "spreads them evenly")
                  .grouped("vegetation"))
          .add(params::field("water_edge", &P::water_edge)
                   .in(0, 1)
                   .no_unit()
                   .doc("Width of the water's-edge band where near-water species grow, as a fraction of the highest point above sea level")
                   .grouped("vegetation"));
  return table;
}

void VegetationParams::validate() const {
  params::validate(*this);
}

namespace {

/// What each random number of a plant decides; with the layer, the stream of rng::stream_key.
/// Candidate k > 0 of a cell draws its numbers from the streams of purpose + k * candidate_stride.
enum class Purpose : std::uint64_t { keep, jitter_x, jitter_y, band, pick, size, turn, shape, age, count };
constexpr std::uint64_t candidate_stride = 16;
/// How far a cell's further candidates stand from its first, at most, in cells.
constexpr double clump_spread = 0.3;
static_assert(static_cast<std::uint64_t>(Purpose::count) <= candidate_stride);

/// Species bands get soft edges: the height fraction a plant chooses its species by moves by up
/// to band_blend per tree and by up to band_wander with a smooth field, so that band borders mix
/// and wander instead of drawing a contour line through the forest.
constexpr double band_blend = 0.04, band_wander = 0.06;

/// The fields' lattices (stream, cell side in metres): groves and clearings, clumps, species
/// patches and the bands' wander.
enum class Field : std::uint64_t { cover_large, cover_mid, clump, clump_fine, patch, patch_fine, wander, count };
constexpr std::array<double, static_cast<std::size_t>(Field::count)> field_scale_m{420.0, 150.0, 45.0, 17.0, 110.0, 40.0, 260.0};
/// The mean of the raw grove-and-clump product over a large area (measured over 64 km^2 and
/// many seeds: tests/vegetation/placement_test.cpp, DensityFieldHasMeanOne), which
/// density_field() divides by.
constexpr double raw_field_mean = 0.5;

double smoothstep(double low, double high, double x) {
  const double t = std::clamp((x - low) / (high - low), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Value noise in [-1, 1): bilinear between lattice values with a smooth fade, the lattice at
/// integer multiples of `cell_m` in world metres, so the same point gives the same value in a
/// tile and in the whole world. The four lattice values of the last lattice cell are kept:
/// neighbouring grid cells mostly share them, which saves most of the hashing.
class ValueNoise {
 public:
  double at(std::uint64_t key, double x_m, double y_m, double cell_m) {
    const double fx = x_m / cell_m, fy = y_m / cell_m;
    const double ix = std::floor(fx), iy = std::floor(fy);
    const double tx = fx - ix, ty = fy - iy;
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    const auto i = static_cast<std::int32_t>(ix), j = static_cast<std::int32_t>(iy);
    if (!(valid_ && i == i_ && j == j_)) {
      auto lattice = [&](std::int32_t a, std::int32_t b) { return 2.0 * rng::to_uniform(rng::bits(key, rng::pack(a, b))) - 1.0; };
      corners_ = {lattice(i, j), lattice(i + 1, j), lattice(i, j + 1), lattice(i + 1, j + 1)};
      i_ = i, j_ = j, valid_ = true;
    }
    const double top = corners_[0] + (corners_[1] - corners_[0]) * sx;
    const double bottom = corners_[2] + (corners_[3] - corners_[2]) * sx;
    return top + (bottom - top) * sy;
  }

 private:
  std::array<double, 4> corners_{};
  std::int32_t i_ = 0, j_ = 0;
  bool valid_ = false;
};

/// The fields' keys of one seed.
struct FieldKeys {
  std::array<std::uint64_t, static_cast<std::size_t>(Field::count)> keys{};
  explicit FieldKeys(std::uint64_t seed) {
    for (std::size_t f = 0; f < keys.size(); ++f) keys[f] = rng::stream_key(seed, 0x666F72657374ull + f);  // "forest"
  }
  /// One lattice cache per field: a FieldKeys is used by one thread (copied into each block).
  mutable std::array<ValueNoise, static_cast<std::size_t>(Field::count)> cache{};
  double noise(Field field, double x_m, double y_m) const {
    const auto f = static_cast<std::size_t>(field);
    return cache[f].at(keys[f], x_m, y_m, field_scale_m[f]);
  }
  /// Groves and clearings times clumps, before normalising: 0 in clearings, up to 1.75.
  double raw_density(double x_m, double y_m) const {
    const double cover = smoothstep(-0.22, 0.12, 0.65 * noise(Field::cover_large, x_m, y_m) + 0.35 * noise(Field::cover_mid, x_m, y_m));
    if (cover <= 0.0) return 0.0;
    const double clump = smoothstep(-0.45, 0.45, noise(Field::clump, x_m, y_m) + 0.45 * noise(Field::clump_fine, x_m, y_m));
    return cover * (0.25 + 1.5 * clump * clump);
  }
  /// In [0, 1), about uniform: which species a patch favours.
  double patch(double x_m, double y_m) const {
    const double n = noise(Field::patch, x_m, y_m) + 0.5 * noise(Field::patch_fine, x_m, y_m);
    const double scaled = 1.3 * n;
    return scaled - std::floor(scaled);
  }
};

/// Sine and cosine by their Taylor series, with +, -, * and / only (as core/exact_math.hpp):
/// slope limits decide which plants exist, and libm's tan may differ in the last bit between
/// platforms. [Range: 0 <= radians <= pi / 2]
double exact_tan(double radians) {
  double sine = 0.0, cosine = 0.0, term_sin = radians, term_cos = 1.0;
  const double square = radians * radians;
  for (int k = 0; k < 24; ++k) {
    sine += term_sin;
    cosine += term_cos;
    term_sin *= -square / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    term_cos *= -square / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
  }
  return cosine > 0.0 ? sine / cosine : std::numeric_limits<double>::infinity();
}

/// One species a layer may pick, with everything the inner loop needs precomputed.
struct Candidate {
  std::uint16_t species = 0;  // index into species_library()
  double band_low = 0.0, band_high = 1.0, weight = 1.0;
  bool near_water = false;
  double max_gradient_squared = 0.0;  // tan(max slope)^2: compared with |grad h|^2, no atan per plant
  double height_jitter = 0.0;

  bool contains(double t) const { return t >= band_low && (t < band_high || band_high >= 1.0); }
};

/// The grid of one layer and what it needs to decide a plant.
struct LayerPlan {
  double spacing_m = 1.0;
  double density = 0.0;
  std::array<std::uint64_t, static_cast<std::size_t>(Purpose::count)> keys{};
  std::vector<Candidate> candidates_of_species;
  std::int32_t first_column = 0, last_column = -1;  // inclusive ranges of grid cells that may
  std::int32_t first_row = 0, last_row = -1;        // hold a point inside the heightfield

  std::vector<std::uint64_t> candidate_keys;  // the streams of candidates 1.. (Purpose + k * stride)
  bool trees = false;                         // the tree layer: the density field, ages, patches
  double clumping = 0.0;
  int candidates = 1;  // per cell
  FieldKeys fields{0};

  std::uint64_t key(Purpose purpose, int candidate = 0) const {
    return candidate == 0 ? keys[static_cast<std::size_t>(purpose)]
                          : candidate_keys[static_cast<std::size_t>(candidate - 1) * candidate_stride + static_cast<std::size_t>(purpose)];
  }
  double uniform(Purpose purpose, std::uint64_t cell, int candidate = 0) const {
    return rng::to_uniform(rng::bits(key(purpose, candidate), cell));
  }
  std::int64_t cells() const {
    return last_row < first_row ? 0 : std::int64_t(last_row - first_row + 1) * std::int64_t(last_column - first_column + 1);
  }
};

/// Where a world coordinate falls among a heightfield's samples along one axis: the column (or
/// row) of the sample before it and the fraction of the way to the next.
///
/// Tiles agree with the world bit for bit because the split is made in world samples,
/// `world_m / cell_m`, which does not depend on the heightfield, and only then shifted by the
/// heightfield's origin as a whole number of samples (integer arithmetic, exact): a tile and the
/// world see the same fraction, the same samples and the same membership. An origin that is not
/// a whole number of cells (to within rounding) moves the coordinate before the split instead:
/// consistent, but such heightfields are not tiles of one world.
struct Axis {
  double origin_whole = 0.0;     // floor of the origin in samples
  double origin_fraction = 0.0;  // the rest: 0 for tiles
  int samples = 0;

  Axis(double origin_m, double cell_m, int sample_count) : samples(sample_count) {
    const double cells = origin_m / cell_m;
    const double nearest = std::round(cells);
    const double origin = std::abs(cells - nearest) <= 1e-9 * std::max(1.0, std::abs(nearest)) ? nearest : cells;
    origin_whole = std::floor(origin);
    origin_fraction = origin - origin_whole;
  }
  /// The samples around world samples [low, high], widened by one on each side against
  /// rounding; false unless they all lie in the heightfield.
  bool span(double low, double high, int& first, int& last) const {
    first = static_cast<int>(std::floor(low - origin_fraction) - origin_whole) - 1;
    last = static_cast<int>(std::floor(high - origin_fraction) - origin_whole) + 2;
    return first >= 0 && last <= samples - 1;
  }
  /// False if the point lies outside [origin, origin + (samples - 1) cells).
  bool locate(double world_samples, int& index, double& fraction) const {
    const double shifted = world_samples - origin_fraction;  // exact when the origin is whole
    const double whole = std::floor(shifted);
    fraction = shifted - whole;
    const double local = whole - origin_whole;  // whole numbers: exact
    if (!(local >= 0.0 && local <= samples - 2)) return false;
    index = static_cast<int>(local);
    return true;
  }
};

/// The heightfield as the sampler sees it.
struct Ground {
  const float* samples = nullptr;
  int width = 0;
  double cell_m = 1.0;
  Axis x, y;

  /// Height and squared gradient (rise over run) at the point `ax`, `ay` of the way from sample
  /// (column, row) to (column + 1, row + 1).
  void sample(int column, int row, double ax, double ay, double& height_m, double& gradient_squared) const {
    const float* top = samples + static_cast<std::ptrdiff_t>(row) * width + column;
    const double h00 = top[0], h10 = top[1], h01 = top[width], h11 = top[width + 1];
    height_m = (h00 * (1.0 - ax) + h10 * ax) * (1.0 - ay) + (h01 * (1.0 - ax) + h11 * ax) * ay;
    const double dx = ((h10 - h00) * (1.0 - ay) + (h11 - h01) * ay) / cell_m;
    const double dy = ((h01 - h00) * (1.0 - ax) + (h11 - h10) * ax) / cell_m;
    gradient_squared = dx * dx + dy * dy;
  }

  /// Whether no point of the square [x0, x1] x [y0, y1] (world metres) can lie above `sea_m`
  /// and at or below `tree_line_m`: all the samples around it are at or under the sea, or all
  /// above the tree line (a bilinear height lies between its samples), with a margin for
  /// rounding. False when unsure, or when the square reaches past the heightfield. Skips the
  /// sea and the bare summits without changing which plants there are.
  bool bare(double x0, double x1, double y0, double y1, double sea_m, double tree_line_m) const {
    int first_column = 0, last_column = 0, first_row = 0, last_row = 0;
    if (!x.span(x0 / cell_m, x1 / cell_m, first_column, last_column) || !y.span(y0 / cell_m, y1 / cell_m, first_row, last_row))
      return false;
    const double margin = 1e-6 * (1.0 + std::abs(sea_m) + std::abs(tree_line_m));
    bool under = true, over = true;
    for (int row = first_row; row <= last_row && (under || over); ++row) {
      const float* line = samples + static_cast<std::ptrdiff_t>(row) * width;
      for (int column = first_column; column <= last_column; ++column) {
        const double h = line[column];
        under = under && h <= sea_m - margin;  // NaN: neither
        over = over && h > tree_line_m + margin;
      }
    }
    return under || over;
  }
};

/// Grid cells of side `spacing` whose points may fall in [low, low + length) (world metres),
/// widened by one on each side against rounding; the exact test is done per point.
std::pair<std::int32_t, std::int32_t> cell_range(double low_m, double length_m, double spacing_m, const char* axis) {
  const double first = std::floor(low_m / spacing_m) - 1.0, last = std::floor((low_m + length_m) / spacing_m) + 1.0;
  constexpr double limit = std::numeric_limits<std::int32_t>::max();
  if (!(first >= -limit && last <= limit))
    fail("vegetation: the heightfield's {} extent {} m .. {} m holds more than 2^31 grid cells of {} m", axis, low_m, low_m + length_m,
         spacing_m);
  return {static_cast<std::int32_t>(first), static_cast<std::int32_t>(last)};
}

/// Reports progress sparsely (about 32 times) and in order, from any thread.
class Progress {
 public:
  Progress(const Context& context, std::int64_t total_cells) : context_(context), total_(std::max<std::int64_t>(1, total_cells)) {}
  void add(std::int64_t cells) {
    std::lock_guard lock(mutex_);  // under the lock, so fractions reach the context in order
    done_ += cells;
    // The last step is left to place_plants, which reports 1 once everything is joined.
    const int step = static_cast<int>(std::min<std::int64_t>(steps - 1, done_ * steps / total_));
    if (step > reported_) {
      reported_ = step;
      context_.report("vegetation", double(step) / steps);
    }
  }

 private:
  static constexpr int steps = 32;
  const Context& context_;
  std::int64_t total_, done_ = 0;
  int reported_ = 0;
  std::mutex mutex_;
};

std::uint16_t species_index(const std::string& name) {
  const auto& library = species_library();
  for (std::size_t i = 0; i < library.size(); ++i)
    if (library[i].name == name) return static_cast<std::uint16_t>(i);
  (void)species_named(name);  // throws, listing the names there are
  fail("vegetation: unknown species '{}'", name);
}

void check_rules(const PlacementRules& rules) {
  auto check_fraction = [](const char* key, double value) {
    if (!(value >= 0.0 && value <= 1.0)) fail("vegetation: {} {} is not allowed: it must be between 0 and 1", key, value);
  };
  check_fraction("tree density", rules.tree_density);
  check_fraction("ground density", rules.ground_density);
  if (!std::isfinite(rules.sea_level_m) || !std::isfinite(rules.tree_line_m))
    fail("vegetation: sea level {} m and tree line {} m must be finite numbers", rules.sea_level_m, rules.tree_line_m);
  if (!(rules.water_edge_m >= 0.0 && std::isfinite(rules.water_edge_m)))
    fail("vegetation: water edge {} m is not allowed: it must be >= 0", rules.water_edge_m);
  for (const ClimateSpecies& entry : rules.species) {
    if (!(entry.band_low >= 0.0 && entry.band_low < entry.band_high && entry.band_high <= 1.0))
      fail("vegetation: species {} has the band {}..{}: it must be low..high with 0 <= low < high <= 1", entry.species, entry.band_low,
           entry.band_high);
    if (!(entry.weight > 0.0 && std::isfinite(entry.weight)))
      fail("vegetation: species {} has the weight {}: it must be > 0", entry.species, entry.weight);
  }
}

LayerPlan plan_layer(Layer layer, double spacing_m, double density, const Heightfield& heights, const VegetationParams& params,
                     const PlacementRules& rules) {
  LayerPlan plan;
  plan.spacing_m = spacing_m;
  plan.density = density;
  // The layers' streams: "tree" and "grnd" in ASCII, shifted to leave room for the purposes.
  const std::uint64_t layer_streams = (layer == Layer::tree ? 0x74726565ull : 0x67726E64ull) << 8;
  for (std::size_t p = 0; p < plan.keys.size(); ++p) plan.keys[p] = rng::stream_key(params.seed, layer_streams + p);
  plan.trees = layer == Layer::tree;
  plan.clumping = plan.trees ? params.clumping : 0.0;
  plan.candidates = plan.clumping > 0.0 ? trees_per_cell : 1;
  for (int k = 1; k < plan.candidates; ++k)
    for (std::uint64_t p = 0; p < candidate_stride; ++p)
      plan.candidate_keys.push_back(rng::stream_key(params.seed, layer_streams + static_cast<std::uint64_t>(k) * candidate_stride + p));
  plan.fields = FieldKeys(params.seed);

  const auto& library = species_library();
  for (const ClimateSpecies& entry : rules.species) {
    const std::uint16_t index = species_index(entry.species);
    const Species& species = library[index];
    if (species.layer != layer) continue;
    if (entry.summer_only && rules.season != Season::summer) continue;
    const double max_gradient = exact_tan(std::clamp(species.max_slope_deg, 0.0, 90.0) * (std::numbers::pi / 180.0));
    plan.candidates_of_species.push_back(Candidate{index, entry.band_low, entry.band_high, entry.weight, entry.near_water,
                                                   max_gradient * max_gradient, species.height_jitter});
  }
  if (plan.density <= 0.0 || plan.candidates_of_species.empty() || heights.width() < 2 || heights.height() < 2) return plan;  // no cells

  std::tie(plan.first_column, plan.last_column) =
      cell_range(heights.origin_x_m, (heights.width() - 1) * heights.cell_size_m, spacing_m, "east-west");
  std::tie(plan.first_row, plan.last_row) =
      cell_range(heights.origin_y_m, (heights.height() - 1) * heights.cell_size_m, spacing_m, "north-south");
  return plan;
}

/// The most plants the two layers can hold (every cell on land, in the band, not too steep) and
/// what placing and writing them takes. Measured against `sansui run` with a plants output (CSV):
/// about 48 bytes a plant at the peak (24 in each block's list, 24 again in the joined one) and
/// 1.1 microseconds a plant, most of it the writing (tests/cli/budget_cli_test.cpp).
budget::Cost placement_cost(const LayerPlan& trees, const LayerPlan& ground, const VegetationParams& params) {
  const double tree_plants = static_cast<double>(trees.cells()) * trees.density;
  const double ground_plants = static_cast<double>(ground.cells()) * ground.density;
  const double plants = tree_plants + ground_plants;
  budget::Cost cost;
  cost.bytes = 2.0 * static_cast<double>(sizeof(Instance)) * plants;
  cost.seconds = 1.1e-6 * plants + 0.05e-6 * static_cast<double>(trees.cells() + ground.cells());
  cost.what = fmt::format(
      "vegetation: up to {:.3g} trees (spacing {:g} m, density {:g}) and {:.3g} ground plants (ground_spacing {:g} m, ground_density "
      "{:g})",
      tree_plants, params.spacing_m, trees.density, ground_plants, params.ground_spacing_m, ground.density);
  cost.smaller = "give a larger spacing or ground_spacing, or a lower density or ground_density";
  cost.force.clear();  // no force: the placement has no such switch; the limit is its parameters'
  return cost;
}

/// The share of a tree kept by the ground under it: fewer trees on steep slopes (thin soil)
/// and toward the tree line (the forest opens into scattered, stunted trees).
double ground_factor(double gradient_squared, double max_gradient_squared, double t) {
  const double steepness = max_gradient_squared > 0.0 ? std::min(gradient_squared / max_gradient_squared, 1.0) : 0.0;
  return (1.0 - 0.6 * steepness) * (1.0 - 0.75 * smoothstep(0.8, 1.0, t));
}

/// The candidate `k` of grid cell (i, j), kept with probability `expected / plan.candidates`
/// (times the ground's factor for trees): appends it to `out`.
void place_candidate(const LayerPlan& plan, const Ground& ground, const PlacementRules& rules, double scale, std::int32_t i, std::int32_t j,
                     int k, double expected, std::vector<Instance>& out) {
  const std::uint64_t cell = rng::pack(i, j);
  const double share = expected / plan.candidates;
  const double keep = plan.uniform(Purpose::keep, cell, k);
  if (!(keep < share)) return;

  // Where: a jittered point of the cell, kept only by the heightfield whose half-open extent holds it.
  // A cell's further candidates stand near its first one, a few metres off, so that a cell
  // the field fills holds a clump of trees (crowns that touch), not an even scatter.
  double fx = plan.uniform(Purpose::jitter_x, cell), fy = plan.uniform(Purpose::jitter_y, cell);
  if (k > 0) {
    fx = std::clamp(0.2 + 0.6 * fx + clump_spread * (2.0 * plan.uniform(Purpose::jitter_x, cell, k) - 1.0), 0.0, 0.999);
    fy = std::clamp(0.2 + 0.6 * fy + clump_spread * (2.0 * plan.uniform(Purpose::jitter_y, cell, k) - 1.0), 0.0, 0.999);
  }
  const double x_m = (i + fx) * plan.spacing_m;
  const double y_m = (j + fy) * plan.spacing_m;
  int column = 0, row = 0;
  double ax = 0.0, ay = 0.0;
  if (!ground.x.locate(x_m / ground.cell_m, column, ax) || !ground.y.locate(y_m / ground.cell_m, row, ay)) return;

  double height_m = 0.0, gradient_squared = 0.0;
  ground.sample(column, row, ax, ay, height_m, gradient_squared);
  if (!(height_m > rules.sea_level_m && height_m <= rules.tree_line_m)) return;  // also drops NaN heights

  // Which species: those whose (softened) band holds the height, weighted. Trees pick by their
  // patch's number as much as by their own, so that neighbours are often of one species.
  const double t = (height_m - rules.sea_level_m) / (rules.tree_line_m - rules.sea_level_m);
  const double wander = plan.trees ? band_wander * plan.fields.noise(Field::wander, x_m, y_m) : 0.0;
  const double band_t = std::clamp(t + wander + (2.0 * plan.uniform(Purpose::band, cell, k) - 1.0) * band_blend, 0.0, 1.0);
  const bool by_water = height_m < rules.sea_level_m + rules.water_edge_m;
  double total = 0.0;
  for (const Candidate& c : plan.candidates_of_species)
    if (c.contains(band_t) && (by_water || !c.near_water)) total += c.weight;
  if (total <= 0.0) return;
  double pick_draw = plan.uniform(Purpose::pick, cell, k);
  if (plan.trees) {
    const double mixed = plan.fields.patch(x_m, y_m) + 0.2 * pick_draw;
    pick_draw = mixed - std::floor(mixed);
  }
  double pick = pick_draw * total;
  const Candidate* chosen = nullptr;
  for (const Candidate& c : plan.candidates_of_species) {
    if (!c.contains(band_t) || (c.near_water && !by_water)) continue;
    chosen = &c;  // the last fitting one catches rounding at the top of the sum
    pick -= c.weight;
    if (pick < 0.0) break;
  }
  if (gradient_squared > chosen->max_gradient_squared) return;  // too steep for it: no plant, no second choice
  // The ground thins trees with the same draw, so a steeper slope keeps a subset of the trees.
  if (plan.trees && !(keep < share * ground_factor(gradient_squared, chosen->max_gradient_squared, t))) return;

  constexpr double two_pi = 2.0 * std::numbers::pi;
  Instance plant;
  plant.x_m = static_cast<float>(x_m);
  plant.y_m = static_cast<float>(y_m);
  plant.height_m = static_cast<float>(height_m);
  const double jitter = 2.0 * plan.uniform(Purpose::size, cell, k) - 1.0;
  if (plan.trees) {
    // Age sets the size; the species' own spread adds to it at half strength; trees near the
    // tree line are stunted.
    const double stunted = 1.0 - 0.4 * smoothstep(0.75, 1.0, t);
    plant.scale = static_cast<float>(size_of_age(plan.uniform(Purpose::age, cell, k)) * (1.0 + 0.5 * chosen->height_jitter * jitter) *
                                     stunted * scale);
  } else {
    plant.scale = static_cast<float>((1.0 + chosen->height_jitter * jitter) * scale);
  }
  plant.rotation_rad = static_cast<float>(plan.uniform(Purpose::turn, cell, k) * two_pi);
  if (plant.rotation_rad >= static_cast<float>(two_pi)) plant.rotation_rad = 0.0f;  // float rounding up to 2 pi is a full turn
  plant.species = chosen->species;
  plant.variant = static_cast<std::uint16_t>(
      std::min(variants_per_species - 1, static_cast<int>(plan.uniform(Purpose::shape, cell, k) * variants_per_species)));
  out.push_back(plant);
}

/// The plants of grid cell (i, j): appends them to `out`.
void place_in_cell(const LayerPlan& plan, const Ground& ground, const PlacementRules& rules, double scale, std::int32_t i, std::int32_t j,
                   std::vector<Instance>& out) {
  if (plan.clumping > 0.0 && ground.bare(i * plan.spacing_m, (i + 1) * plan.spacing_m, j * plan.spacing_m, (j + 1) * plan.spacing_m,
                                         rules.sea_level_m, rules.tree_line_m))
    return;
  double expected = plan.density;
  if (plan.clumping > 0.0) {
    // The field at the cell's centre: groves and clumps are many cells wide.
    const double field = plan.fields.raw_density((i + 0.5) * plan.spacing_m, (j + 0.5) * plan.spacing_m) / raw_field_mean;
    expected *= std::min(1.0 + plan.clumping * (field - 1.0), plan.candidates / std::max(plan.density, 1e-9));
  }
  for (int k = 0; k < plan.candidates; ++k) place_candidate(plan, ground, rules, scale, i, j, k, expected, out);
}

/// Every plant of one layer, in (row, column) order. Rows are cut into a fixed number of blocks
/// placed in parallel and joined in order, so the result does not depend on the threads.
std::vector<Instance> place_layer(const LayerPlan& plan, const Ground& ground, const PlacementRules& rules, double scale,
                                  Progress& progress, const Context& context) {
  if (plan.cells() == 0) return {};
  const std::int64_t rows = std::int64_t(plan.last_row) - plan.first_row + 1;
  const std::int64_t columns = std::int64_t(plan.last_column) - plan.first_column + 1;
  const std::int64_t rows_per_block = std::max<std::int64_t>(1, (rows + 255) / 256);
  const std::int64_t blocks = (rows + rows_per_block - 1) / rows_per_block;
  std::vector<std::vector<Instance>> placed(static_cast<std::size_t>(blocks));

  parallel_for(std::int64_t(0), blocks, [&](std::int64_t block) {
    context.check_cancelled();
    const std::int64_t row_begin = plan.first_row + block * rows_per_block;
    const std::int64_t row_end = std::min<std::int64_t>(plan.last_row + 1, row_begin + rows_per_block);
    std::vector<Instance>& out = placed[static_cast<std::size_t>(block)];
    const LayerPlan block_plan = plan;  // with its own lattice caches (FieldKeys::cache)
    // Room for the expected count, capped: most cells may lie under the sea or above the tree line.
    out.reserve(static_cast<std::size_t>(std::min(65536.0, double(row_end - row_begin) * double(columns) * plan.density)));
    for (std::int64_t j = row_begin; j < row_end; ++j)
      for (std::int64_t i = plan.first_column; i <= plan.last_column; ++i)
        place_in_cell(block_plan, ground, rules, scale, static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), out);
    progress.add((row_end - row_begin) * columns);
  });

  std::size_t total = 0;
  for (const auto& block : placed) total += block.size();
  std::vector<Instance> all;
  all.reserve(total);
  for (const auto& block : placed) all.insert(all.end(), block.begin(), block.end());
  return all;
}

}  // namespace

double density_field(std::uint64_t seed, double x_m, double y_m) {
  const FieldKeys fields(seed);
  return fields.raw_density(x_m, y_m) / raw_field_mean;
}

Placement place_plants(const Heightfield& heights, const VegetationParams& params, const PlacementRules& rules, const Context& context) {
  params.validate();
  check_rules(rules);
  if (!(heights.cell_size_m > 0.0 && std::isfinite(heights.cell_size_m)))
    fail("vegetation: the heightfield's cell size {} m is not allowed: it must be > 0", heights.cell_size_m);
  if (!std::isfinite(heights.origin_x_m) || !std::isfinite(heights.origin_y_m))
    fail("vegetation: the heightfield's origin {}, {} m must be finite", heights.origin_x_m, heights.origin_y_m);
  if (!params.enabled || !(rules.tree_line_m > rules.sea_level_m)) {
    context.report("vegetation", 1.0);
    return {};
  }

  const LayerPlan trees = plan_layer(Layer::tree, params.spacing_m, params.density.value_or(rules.tree_density), heights, params, rules);
  const LayerPlan ground_layer =
      plan_layer(Layer::ground, params.ground_spacing_m, params.ground_density.value_or(rules.ground_density), heights, params, rules);
  budget::check(placement_cost(trees, ground_layer, params));
  const Ground ground{heights.data(), heights.width(), heights.cell_size_m, Axis(heights.origin_x_m, heights.cell_size_m, heights.width()),
                      Axis(heights.origin_y_m, heights.cell_size_m, heights.height())};

  Progress progress(context, trees.cells() + ground_layer.cells());
  Placement placement;
  placement.trees = place_layer(trees, ground, rules, params.scale, progress, context);
  placement.ground = place_layer(ground_layer, ground, rules, params.scale, progress, context);
  context.report("vegetation", 1.0);
  return placement;
}

}  // namespace sansui::vegetation
