// Parameter tables of the contour subsystem (see core/params.hpp), and the checks of the
// params structs that involve more than one value.
#include <cmath>

#include "contour/compare.hpp"
#include "contour/generate.hpp"
#include "contour/map_drawing.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "core/params.hpp"

namespace sansui::contour {

const params::Table<LoopRemovalParams>& parameter_table(const LoopRemovalParams*) {
  using P = LoopRemovalParams;
  static const auto table =
      params::Table<P>("loops", "Loop removal (Misawa, Chiba and Saito 1987, Sec. 4.4)")
          .add(params::field("removal", &P::method).in(1, 2).doc("Loop removal method: 1 (faces of the planar graph) or 2 (walk and cut)"))
          .add(params::field("threshold", &P::threshold)
                   .at_most(1e6)
                   .at_least(3)
                   .doc("Faces or stretches with fewer segments than this are loops"));
  return table;
}

namespace {

// The group of the rows that shape the contours themselves (the viewer's panel, the docs).
constexpr const char* shape = "generation";

/// The rows of the growth itself: the method, the offset and interval, the joins, the midpoint
/// and Fourier steps, the seed.
void add_growth_rows(params::Table<GenerationParams>& table) {
  using P = GenerationParams;
  table
      .add(params::choice(
               "method", &P::method,
               {{"simple", Method::simple}, {"midpoint", Method::midpoint}, {"fourier", Method::fourier}, {"revised", Method::revised}})
               .doc("Generation method: simple (Sec. 3), midpoint (4.1), fourier (4.2), revised (4.3, the paper's best)")
               .grouped(shape))
      .add(params::field("offset", &P::offset_m)
               .at_most(1e7)
               .above(0)
               .units("m")
               .unset("from the seed's size: inradius * dz / target relief (docs/contour.md); a seed from a DEM: dz / the "
                      "DEM's mean gradient inside the seed")
               .doc("d: horizontal offset between neighbouring contours")
               .grouped(shape))
      .add(params::field("interval", &P::interval_m).at_most(1e5).at_least(0.001).units("m").doc("dz: contour interval").grouped(shape))
      .add(params::field("z0", &P::z0_m)
               .in(-1e5, 1e5)
               .units("m")
               .unset("0, or the level the seed was taken at")
               .doc("Elevation of the seed contour")
               .grouped(shape))
      .add(params::choice("join", &P::join,
                          {{"extended", Join::extended}, {"straight", Join::straight}, {"arc", Join::arc}, {"clipped", Join::clipped}})
               .unset("clipped")
               .doc("Join of the offset step at reflex corners (Figs. 5, 7)")
               .grouped(shape))
      .add(params::field("c", &P::clip_factor)
               .at_most(100)
               .at_least(1)
               .no_unit()
               .unset("1.4; revised 3")
               .doc("c of the clipped join: d' = c d")
               .grouped(shape))
      .add(params::field("d2", &P::displacement_fraction)
               .at_most(10)
               .no_unit()
               .at_least(0)
               .unset("0.3; revised 0.5")
               .doc("d'' as a fraction of d: the largest midpoint displacement")
               .grouped(shape))
      .add(params::pair("theta", &P::theta_min_deg, &P::theta_max_deg)
               .at_least(0)
               .below(90)
               .units("deg")
               .unset("0,20; revised 20,40")
               .doc("MIN,MAX: range of theta of the midpoint displacement")
               .grouped(shape))
      .add(params::field("n", &P::samples)
               .in(8, 65536)
               .rule(
                   [](const params::Value& v) {
                     const auto n = std::get<std::int64_t>(v);
                     return (n & (n - 1)) == 0 ? std::string() : std::string("a power of two from 8 to 65536");
                   },
                   "a power of two")
               .doc("Samples of the Fourier step")
               .grouped(shape))
      .add(params::field("f0", &P::f0)
               .at_most(1 << 20)
               .at_least(0)
               .doc("Lowest randomised frequency; n/2 turns randomisation off (at most n/2)")
               .grouped(shape))
      .add(params::field("long_fraction", &P::long_fraction)
               .above(0)
               .below(1)
               .no_unit()
               .doc("Revised: fraction of segments longer than 2 d0 kept")
               .grouped(shape))
      .add(params::field("seed", &P::seed).doc("Random seed: the same seed gives the same contours").grouped(shape));
}

/// The rows after the loop removal's: the levels outward to the foot, the summit crater and the
/// cols; the guards against runaway seeds, the pre-cleaning, the varying offset, the clearance.
void add_outward_and_limit_rows(params::Table<GenerationParams>& table) {
  using P = GenerationParams;
  table
      .add(params::field("outward", &P::outward_levels)
               .at_most(10000)
               .at_least(0)
               .doc("Levels generated outward, toward the foot")
               .grouped("outward"))
      .add(params::field("base", &P::base_m)
               .in(-1e5, 1e5)
               .units("m")
               .unset("none")
               .doc("Generate outward down to this elevation, the last contour at exactly this elevation (at most `outward` "
                    "levels when that is set too)")
               .grouped("outward"))
      .add(params::field("crater_depth", &P::crater_depth_m)
               .at_most(1e5)
               .above(0)
               .units("m")
               .unset("no crater")
               .doc("Depth of a summit crater: the main branch stops at the rim and levels descend inside it to a flat floor "
                    "this far below the rim (not below the map's base)")
               .grouped("crater"))
      .add(params::field("crater_width", &P::crater_width)
               .above(0)
               .below(1)
               .no_unit()
               .doc("Width of the crater's rim as a fraction of the seed's (square root of the area ratio)")
               .grouped("crater"))
      .add(params::field("crater_floor", &P::crater_floor)
               .above(0)
               .below(1)
               .no_unit()
               .doc("Width of the crater's floor as a fraction of the rim's")
               .grouped("crater"))
      .add(params::field("col_depth", &P::col_depth_m)
               .in(0, 1e5)
               .units("m")
               .doc("Depth of the cols between summits below the level where their common contour split (whole intervals, "
                    "at least one; cut along each col's line); 0: none")
               .grouped("col"))
      .add(params::field("max_levels", &P::max_levels)
               .at_most(100000)
               .at_least(1)
               .doc("Most levels generated inward (a guard against runaway seeds)")
               .grouped(shape))
      .add(params::field("force", &P::force)
               .doc("Generate even when the estimate is over 3000 levels or ten minutes (refused otherwise, before any work)")
               .grouped(shape))
      .add(params::field("min_area", &P::min_area_m2)
               .at_most(1e14)
               .at_least(0)
               .units("m^2")
               .unset("d^2/4")
               .doc("A smaller contour ends a summit")
               .grouped(shape))
      .add(params::field("preclean_segment", &P::preclean_segment_fraction)
               .no_unit()
               .in(0, 1)
               .doc("Pre-clean: segments shorter than this fraction of d lose an end point")
               .grouped(shape))
      .add(params::field("preclean_angle", &P::preclean_angle_deg)
               .in(0, 60)
               .units("deg")
               .doc("Pre-clean: vertices sharper than this are dropped")
               .grouped(shape))
      .add(params::field("offset_schedule", &P::offset_schedule_m)
               .above(0)
               .units("m")
               .unset("d everywhere")
               .doc("D1,D2,...: d for inward levels 1, 2, ...; the last value repeats")
               .grouped(shape))
      .add(params::field("offset_variation", &P::offset_variation)
               .at_least(0)
               .below(1)
               .no_unit()
               .doc("v: d varies over the plane as d m (1 + v f), f a smooth fractal field in [-1, 1] (m keeps the mean slope): steep "
                    "and gentle sides; 0.4 gives the slope spread of the real DEM in examples/dem, 0 one slope")
               .grouped(shape))
      .add(params::field("offset_hurst", &P::offset_hurst)
               .above(0)
               .at_most(1)
               .no_unit()
               .doc("Hurst exponent of the offset's field: higher is smoother")
               .grouped(shape))
      .add(params::field("arc_step", &P::arc_step_deg).in(1, 45).units("deg").doc("Angle per segment of arc joins").grouped(shape))
      .add(params::field("clearance", &P::clearance_fraction)
               .in(0, 0.5)
               .no_unit()
               .doc("Clearance kept from parent and siblings, as a fraction of d")
               .grouped(shape));
}

}  // namespace

const params::Table<GenerationParams>& parameter_table(const GenerationParams*) {
  using P = GenerationParams;
  // Built in the order the rows are listed in the CLI's help, the docs and the viewer.
  static const auto table = [] {
    auto t = params::Table<P>("contour", "Contour lines of a mountain grown from one seed contour (Misawa, Chiba and Saito 1987)");
    add_growth_rows(t);
    t.nest("loop_", "loop-", &P::loops, parameter_table(static_cast<const LoopRemovalParams*>(nullptr)));
    add_outward_and_limit_rows(t);
    return t;
  }();
  return table;
}

void GenerationParams::validate() const {
  // theta is checked as the pair the method uses, so setting one end alone is checked too.
  GenerationParams resolved = *this;
  resolved.theta_min_deg = resolved_theta_min_deg();
  resolved.theta_max_deg = resolved_theta_max_deg();
  params::validate(resolved);
  const double t0 = resolved_theta_min_deg(), t1 = resolved_theta_max_deg();
  if (t0 > t1) fail("contour.theta {},{} is not allowed: MIN must not exceed MAX", t0, t1);
  if (f0 > samples / 2) fail("contour.f0 {} is not allowed: it must lie in 0..n/2 = {}", f0, samples / 2);
  if (base_m && *base_m > resolved_z0_m())
    fail("contour.base {} m is not allowed: it must be at or below z0 = {} m", *base_m, resolved_z0_m());
}

const params::Table<DemParams>& parameter_table(const DemParams*) {
  using P = DemParams;
  const std::string frame = "set by the pipeline: the DEM grid, from [dem] size and cell, or the source DEM's grid";
  static const auto table =
      params::Table<P>("contour_dem", "From contours to a grid DEM (Misawa, Chiba and Saito 1987, Sec. 5; as GRASS r.surf.contour)")
          .add(params::field("width", &P::width).in(2, 32768).unset(frame).internal())
          .add(params::field("height", &P::height).in(2, 32768).unset(frame).internal())
          .add(params::field("cell", &P::cell_m).above(0).units("m").unset(frame).internal())
          .add(params::field("origin_x", &P::origin_x_m).units("m").unset(frame).internal())
          .add(params::field("origin_y", &P::origin_y_m).units("m").unset(frame).internal())
          .add(params::field("base", &P::base_m).units("m").unset("set by the pipeline from [dem] fill").internal())
          .add(params::field("cap", &P::cap_m)
                   .at_most(1e5)
                   .at_least(0)
                   .units("m")
                   .unset("the contour interval")
                   .doc("Height of the cap above a summit contour (reached only by caps at least 2 d wide)"))
          .add(params::field("offset", &P::offset_m).above(0).units("m").unset("set by the pipeline: the generation's d").internal())
          .add(params::field("noise", &P::roughness_m)
                   .at_most(1e5)
                   .at_least(0)
                   .units("m")
                   .doc("Standard deviation of midpoint-displacement noise added to the DEM (Fig. 11), zero on the contours; 0: none"))
          .add(params::field("noise_hurst", &P::roughness_hurst).above(0).at_most(1).no_unit().doc("Hurst exponent of that noise"))
          .add(params::field("seed", &P::seed).unset("set by the pipeline: the contour seed").internal())
          .add(params::choice("surround", &P::surround, {{"flat", Surround::flat}, {"foothills", Surround::foothills}})
                   .doc("Outside the mountain's foot: flat at the base, or foothills (a fractal terrain about the base, blended in "
                        "from the foot; the DEM's frame then leaves a quarter of the contours' extent around them)"))
          .add(params::field("foothill_relief", &P::foothill_relief_m)
                   .at_most(1e5)
                   .at_least(0)
                   .units("m")
                   .unset("a tenth of the mountain's relief above the base")
                   .doc("Standard deviation of the foothills about the base"))
          .add(params::field("foothill_width", &P::foothill_width_m)
                   .at_most(1e7)
                   .above(0)
                   .units("m")
                   .unset("a tenth of the contours' larger extent")
                   .doc("Distance from the foot over which the foothills blend in from the base"))
          .add(params::field("foothill_hurst", &P::foothill_hurst).above(0).at_most(1).no_unit().doc("Hurst exponent of the foothills"));
  return table;
}

void DemParams::validate() const {
  params::validate(*this);
}

const params::Table<MapStyle>& parameter_table(const MapStyle*) {
  using P = MapStyle;
  static const auto table =
      params::Table<P>("map", "Contour maps (SVG and PNG), in the style of Figs. 9 and 16 of Misawa, Chiba and Saito 1987")
          .add(params::field("width", &P::width_px).in(64, 16384).units("px").doc("Width of the picture"))
          .add(params::field("index_every", &P::index_every)
                   .at_most(1000)
                   .at_least(1)
                   .doc("Every this many levels a bold, labelled index contour"))
          .add(params::field("line", &P::line_px).above(0).at_most(100).units("px").doc("Line width of ordinary contours"))
          .add(params::field("index_line", &P::index_line_px).above(0).at_most(100).units("px").doc("Line width of index contours"))
          .add(params::field("label", &P::label_px).above(0).at_most(500).units("px").doc("Height of label digits"))
          .add(params::field("contour", &P::contour).doc("Contour colour R,G,B,A (sepia, as on topographic maps)"))
          .add(params::field("paper", &P::paper).doc("Paper colour R,G,B,A"))
          .add(params::field("ink", &P::ink).doc("Colour of labels, scale bar and north arrow R,G,B,A"))
          .add(params::field("labels", &P::labels).doc("Label the index contours with their elevation"))
          .add(params::field("scale_bar", &P::scale_bar).doc("Draw a scale bar"))
          .add(params::field("north_arrow", &P::north_arrow).doc("Draw a north arrow"))
          .add(params::field("summits", &P::summits).doc("Mark the summits"));
  return table;
}

const params::Table<CompareParams>& parameter_table(const CompareParams*) {
  using P = CompareParams;
  static const auto table =
      params::Table<P>("compare", "How close a generated DEM is to a real one")
          .add(params::field("above", &P::above_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("all cells")
                   .doc("Only cells at or above this elevation count, e.g. the seed's level"))
          .add(params::opaque("inside_ring", &P::inside).unset("set by the pipeline from the file named by [compare] inside").internal())
          .add(params::field("interval", &P::interval_m)
                   .at_most(1e5)
                   .above(0)
                   .units("m")
                   .unset("the common relief / 20")
                   .doc("Interval of the compared contour levels"))
          .add(params::field("prominence", &P::prominence_m)
                   .at_most(1e5)
                   .above(0)
                   .units("m")
                   .unset("the interval")
                   .doc("Smallest prominence of a summit"));
  return table;
}

}  // namespace sansui::contour
