// Contour-line generation of a mountain from one seed contour:
//   M. Misawa, N. Chiba, N. Saito, "Simulation of natural scenes: procedure modeling for
//   mountains" (IPSJ, 1987; seeds/000; SPEC 1.2). Four methods:
//   simple   (Sec. 3)   repeat the polygon shrink (shrink.hpp) until nothing is left;
//   midpoint (Sec. 4.1) shrink, then midpoint displacement of long segments (midpoint.hpp);
//   fourier  (Sec. 4.2) shrink, then random phases of the high Fourier descriptors (fourier.hpp);
//   revised  (Sec. 4.3) shrink, midpoint displacement, random phases, then drop nearly collinear
//            points (decimate.hpp). The paper's best, and our default.
// After the perturbation, loops are removed (loop_removal.hpp), and every contour is clipped
// inside its parent (less a small clearance) and outside its earlier siblings, so nested contours
// never cross or touch. Expanding toward the foot (outward) is the same with the opposite side.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "contour/contour_tree.hpp"
#include "contour/loop_removal.hpp"
#include "contour/shrink.hpp"
#include "core/context.hpp"

namespace sansui::contour {

enum class Method { simple, midpoint, fourier, revised };

std::optional<Method> method_from_name(std::string_view name);
std::string_view name_of(Method method);

/// Parameters of one generation. Empty optionals take the paper's value for the method (the
/// resolved_*() functions below hold them; the table in contour_params.cpp says them to users).
/// Table: contour_params.cpp (section [contour]).
struct GenerationParams {
  /// Generation method. [Default: revised]
  Method method = Method::revised;
  /// d: horizontal offset between neighbouring contours. [Units: m] [Range: > 0]
  /// [Default: unset: 10 m; the pipeline derives it from the seed's size (scale.hpp) or, for a
  /// seed from a DEM, from its slope]
  std::optional<double> offset_m;
  /// dz: contour interval. [Units: m] [Range: > 0] [Default: 10]
  double interval_m = 10.0;
  /// z0: elevation of the seed contour. [Units: m] [Default: unset: 0; a seed from a DEM: its level]
  std::optional<double> z0_m;
  /// Join of the offset step. [Default: clipped]
  std::optional<Join> join;
  /// c of the clipped join (d' = c d). [Range: >= 1] [Default: by method]
  std::optional<double> clip_factor;
  /// d'' as a fraction of d: the largest midpoint displacement. [Range: >= 0] [Default: by method]
  std::optional<double> displacement_fraction;
  /// Range of theta of the midpoint displacement. [Units: degrees] [Range: 0 <= min <= max < 90]
  /// [Default: by method]
  std::optional<double> theta_min_deg, theta_max_deg;
  /// n: samples of the Fourier step. [Range: power of two, 8..65536] [Default: 1024]
  int samples = 1024;
  /// f0: lowest randomised frequency; n/2 turns randomisation off. [Range: 0..n/2] [Default: 256]
  int f0 = 256;
  /// Fraction of segments longer than 2 d0 kept by the revised method. [Range: 0 < f < 1] [Default: 0.2]
  double long_fraction = 0.2;
  /// Random seed: the same seed gives the same contours. [Default: 1]
  std::uint64_t seed = 1;
  /// Loop removal method and threshold. [Default: method 2, threshold 16]
  LoopRemovalParams loops;
  /// Levels generated outward, toward the foot. [Range: >= 0] [Default: 0]
  int outward_levels = 0;
  /// Generate outward down to this elevation: floor((z0 - base) / dz) full levels, then, when
  /// base is not a whole number of intervals below z0, one last contour at exactly base (its
  /// offset d times the remaining fraction, at least d / 4). At most outward_levels levels when
  /// that is set too (then base may not be reached). [Units: m]
  std::optional<double> base_m;
  /// Depth of a summit crater: the main branch stops at the rim (the first of its contours no
  /// wider than crater_width of the seed) and levels descend inside it by dz, the last at exactly
  /// rim - depth: a closed depression with a flat floor. [Units: m] [Range: > 0] [Default: unset: no crater]
  std::optional<double> crater_depth_m;
  /// Width of the crater's rim as a fraction of the seed's (square root of the area ratio).
  /// [Range: 0 < w < 1] [Default: 0.3]
  double crater_width = 0.3;
  /// Width of the crater's floor as a fraction of the rim's inradius. [Range: 0 < f < 1] [Default: 0.4]
  double crater_floor = 0.4;
  /// Depth of the cols between summits: at every split, the contours from the split level down
  /// are cut along the col's line (cols.hpp), so the saddle dips this far below the split level,
  /// in whole intervals (at least one). 0: the saddle stays at the split level.
  /// [Units: m] [Range: 0..100000] [Default: 0]
  double col_depth_m = 0.0;
  /// Most levels generated inward (a guard against runaway seeds). [Range: >= 1] [Default: 10000]
  int max_levels = 10000;
  /// Generate even when the estimate (scale.hpp) is over the level or time limit. [Default: false]
  bool force = false;
  /// A contour smaller than this is a summit's end: dropped. [Units: m^2] [Range: >= 0] [Default: d^2 / 4]
  std::optional<double> min_area_m2;
  /// Pre-clean before each shrink: segments shorter than this fraction of d lose an end point.
  /// [Range: 0..1] [Default: 0.02]
  double preclean_segment_fraction = 0.02;
  /// Pre-clean: vertices sharper than this are dropped. [Units: degrees] [Range: 0..60] [Default: 5]
  double preclean_angle_deg = 5.0;
  /// Per-level d for inward levels 1, 2, ...; the last value repeats. Empty: d everywhere. [Units: m]
  std::vector<double> offset_schedule_m;
  /// How much d varies over the plane: d(p) = d m (1 + v f(p)), f a smooth fractal field in
  /// [-1, 1], m so that the mean of 1 / (m (1 + v f)) over the seed is 1 (offset_field.hpp).
  /// The default makes the slope distribution as wide as the real DEM's in examples/dem
  /// (docs/contour.md: the 90th / 50th percentile gradient ratio, measured). [Range: 0 <= v < 1]
  /// [Default: 0.4]
  double offset_variation = 0.4;
  /// Hurst exponent of that field: higher is smoother. [Range: 0 < H <= 1] [Default: 0.7]
  double offset_hurst = 0.7;
  /// Angle per segment of arc joins. [Units: degrees] [Range: 1..45] [Default: 15]
  double arc_step_deg = 15.0;
  /// Clearance kept between a contour and its parent and siblings, as a fraction of d.
  /// [Range: 0..0.5] [Default: 0.02]
  double clearance_fraction = 0.02;

  /// Throws InputError naming the first bad value.
  void validate() const;

  Join resolved_join() const { return join.value_or(Join::clipped); }
  double resolved_clip_factor() const;
  double resolved_displacement_fraction() const;
  double resolved_theta_min_deg() const;
  double resolved_theta_max_deg() const;
  double resolved_offset_m() const { return offset_m.value_or(10.0); }
  double resolved_z0_m() const { return z0_m.value_or(0.0); }
  double resolved_min_area_m2() const { return min_area_m2.value_or(0.25 * resolved_offset_m() * resolved_offset_m()); }
  /// d for inward level k >= 1.
  double offset_for_level(int level) const;
  /// Outward levels to generate (full levels and the last, partial one down to base).
  int resolved_outward_levels() const;
  /// The fraction of an interval the last outward level covers: 1, or less when it stops at base.
  double last_outward_fraction() const;
};

const params::Table<GenerationParams>& parameter_table(const GenerationParams*);

/// Seconds spent in each step, summed over all contours (for benchmarks and --verbose).
struct GenerationTimes {
  double offset_s = 0.0;    ///< raw offset curve and positive-winding union (Steps 1-4)
  double midpoint_s = 0.0;  ///< midpoint displacement
  double fourier_s = 0.0;   ///< resampling, FFT, random phases, inverse FFT
  double decimate_s = 0.0;  ///< dropping collinear points (revised)
  double loops_s = 0.0;     ///< loop removal
  double clip_s = 0.0;      ///< clipping inside the parent and outside siblings
};

/// Generates the mountain's contours from `seed` (counter-clockwise, simple; see seed_input.hpp).
/// Elevations are z0 + level * dz (see elevations.hpp to reshape them). Contours are generated
/// level by level, the contours of one level in parallel; the result does not depend on the
/// number of threads. Throws InputError for bad parameters, Cancelled when asked to stop.
ContourTree generate_contours(const Ring& seed, const GenerationParams& params, const Context& context = quiet_context(),
                              GenerationTimes* times = nullptr);

/// The same from several seed contours (islands, one mountain each: disjoint, each
/// counter-clockwise and simple), all at z0, grown side by side as the islands of a split; their
/// outward contours merge where they meet. tree.seed is the first seed; the others are the other
/// level-0 contours.
ContourTree generate_contours(const std::vector<Ring>& seeds, const GenerationParams& params, const Context& context = quiet_context(),
                              GenerationTimes* times = nullptr);

}  // namespace sansui::contour
