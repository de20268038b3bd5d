// Node kinds that make masks (select_height, select_slope, select_curvature, select_flow,
// mask_polygon) and that combine grids (blend, max, min, add). See node_kinds.hpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "contour/edt.hpp"
#include "contour/geometry.hpp"
#include "contour/grid_frame.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/text_file.hpp"
#include "scene/node_kinds.hpp"
#include "scene/seed_files.hpp"
#include "water/flow.hpp"

namespace sansui::scene {

/// The share of a soft window: 1 inside [low, high], 0 beyond an edge of `edge` width centred on
/// each bound (a bound that is unset is open).
struct Window {
  std::optional<double> low, high;
  double edge = 0.0;
  float at(double v) const {
    double m = 1.0;
    const auto side = [&](double distance_inside) {
      if (edge <= 0.0) return distance_inside >= 0.0 ? 1.0 : 0.0;
      return std::clamp(0.5 + distance_inside / edge, 0.0, 1.0);
    };
    if (low) m = std::min(m, side(v - *low));
    if (high) m = std::min(m, side(*high - v));
    return static_cast<float>(m);
  }
};

/// Heights between min and max. [[node]] kind = "select_height"
struct SelectHeightNode {
  std::optional<double> min_m = 0.0, max_m;
  double edge_m = 10.0;
};
const params::Table<SelectHeightNode>& parameter_table(const SelectHeightNode*) {
  using P = SelectHeightNode;
  static const auto table =
      params::Table<P>("select_height", "A mask: 1 where the heights lie between min and max, with soft edges")
          .add(params::field("min", &P::min_m).in(-1e5, 1e5).units("m").unset("no lower bound").doc("Lowest height selected"))
          .add(params::field("max", &P::max_m).in(-1e5, 1e5).units("m").unset("no upper bound").doc("Highest height selected"))
          .add(params::field("edge", &P::edge_m).at_least(0).at_most(1e5).units("m").doc("Width of the soft edge, centred on each bound"));
  return table;
}

/// Slopes steeper than a threshold. [[node]] kind = "select_slope"
struct SelectSlopeNode {
  double min_deg = 30.0;
  std::optional<double> max_deg;
  double edge_deg = 0.0;
};
const params::Table<SelectSlopeNode>& parameter_table(const SelectSlopeNode*) {
  using P = SelectSlopeNode;
  static const auto table =
      params::Table<P>("select_slope", "A mask: 1 where the slope is at least min (and at most max), softened below over edge")
          .add(params::field("min", &P::min_deg).in(0, 90).units("deg").doc("Least slope selected"))
          .add(params::field("max", &P::max_deg).in(0, 90).units("deg").unset("no upper bound").doc("Steepest slope selected"))
          .add(params::field("edge", &P::edge_deg).in(0, 90).units("deg").doc("Width of the soft edge outside each bound"));
  return table;
}

/// Convex or concave ground. [[node]] kind = "select_curvature"
struct SelectCurvatureNode {
  std::optional<double> min_per_m = 0.0, max_per_m;
  double edge_per_m = 0.002;
};
const params::Table<SelectCurvatureNode>& parameter_table(const SelectCurvatureNode*) {
  using P = SelectCurvatureNode;
  static const auto table =
      params::Table<P>("select_curvature",
                       "A mask by curvature (minus the Laplacian: positive on ridges and summits, negative in valleys and hollows)")
          .add(params::field("min", &P::min_per_m).in(-10, 10).units("1/m").unset("no lower bound").doc("Least curvature selected"))
          .add(params::field("max", &P::max_per_m).in(-10, 10).units("1/m").unset("no upper bound").doc("Largest curvature selected"))
          .add(params::field("edge", &P::edge_per_m).in(0, 10).units("1/m").doc("Width of the soft edge, centred on each bound"));
  return table;
}

/// Where water gathers. [[node]] kind = "select_flow"
struct SelectFlowNode {
  double min_area_m2 = 1e5;
  double edge_decades = 0.5;
};
const params::Table<SelectFlowNode>& parameter_table(const SelectFlowNode*) {
  using P = SelectFlowNode;
  static const auto table =
      params::Table<P>("select_flow", "A mask: 1 where the drainage area is at least min_area (channels, valley floors)")
          .add(params::field("min_area", &P::min_area_m2).above(0).at_most(1e14).units("m^2").doc("Least drainage area selected"))
          .add(params::field("edge", &P::edge_decades).in(0, 10).no_unit().doc("Width of the soft edge in powers of ten of the area"));
  return table;
}

/// Inside a polygon. [[node]] kind = "mask_polygon"
struct MaskPolygonNode {
  std::string file;
  double edge_m = 50.0;
};
const params::Table<MaskPolygonNode>& parameter_table(const MaskPolygonNode*) {
  using P = MaskPolygonNode;
  static const auto table =
      params::Table<P>("mask_polygon", "A mask: 1 inside the polygons of a file, 0 outside, soft across their edge")
          .add(params::path("file", &P::file).doc("Polygons (.geojson .json .csv .txt), metres as the outputs' GeoJSON: x east, y north"))
          .add(params::field("edge", &P::edge_m).at_least(0).at_most(1e6).units("m").doc("Width of the soft edge, centred on the line"));
  return table;
}

/// No parameters: blend, max, min, add.
struct NoParams {};
const params::Table<NoParams>& parameter_table(const NoParams*) {
  static const auto table = params::Table<NoParams>("combine", "No parameters");
  return table;
}

namespace {

Grid<float> mask_like(const Grid<float>& heights) {
  Grid<float> mask(heights.width(), heights.height(), 0.0f, heights.cell_size_m);
  mask.copy_metadata_from(heights);
  return mask;
}

/// f(x, y) for every interior sample (edge samples copy their inward neighbour's value).
template <class F>
Grid<float> interior_map(const Grid<float>& h, F&& f) {
  Grid<float> out = mask_like(h);
  const int w = h.width(), ht = h.height();
  parallel_for(0, ht, [&](int y) {
    const int cy = std::clamp(y, 1, std::max(1, ht - 2));
    for (int x = 0; x < w; ++x) out(x, y) = (w >= 3 && ht >= 3) ? f(std::clamp(x, 1, std::max(1, w - 2)), cy) : 0.0f;
  });
  return out;
}

Grid<float> run_select_height(const SelectHeightNode& p, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
  const Window window{p.min_m, p.max_m, p.edge_m};
  Grid<float> mask = mask_like(*in[0]);
  for (std::size_t i = 0; i < mask.size(); ++i) mask.values()[i] = window.at(in[0]->values()[i]);
  return mask;
}

Grid<float> run_select_slope(const SelectSlopeNode& p, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
  const Grid<float>& h = *in[0];
  // The soft edge lies outside the bounds: 1 exactly where the slope is within them.
  const Window window{p.min_deg - 0.5 * p.edge_deg, p.max_deg ? std::optional<double>(*p.max_deg + 0.5 * p.edge_deg) : std::nullopt,
                      p.edge_deg};
  const double c = h.cell_size_m;
  return interior_map(h, [&](int x, int y) {
    const double dx = (static_cast<double>(h(x + 1, y)) - h(x - 1, y)) / (2 * c),
                 dy = (static_cast<double>(h(x, y + 1)) - h(x, y - 1)) / (2 * c);
    return window.at(std::atan(std::hypot(dx, dy)) * 180.0 / std::numbers::pi);
  });
}

Grid<float> run_select_curvature(const SelectCurvatureNode& p, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
  const Grid<float>& h = *in[0];
  const Window window{p.min_per_m, p.max_per_m, p.edge_per_m};
  const double c2 = h.cell_size_m * h.cell_size_m;
  return interior_map(h, [&](int x, int y) {
    const double laplacian = (static_cast<double>(h(x + 1, y)) + h(x - 1, y) + h(x, y + 1) + h(x, y - 1) - 4.0 * h(x, y)) / c2;
    return window.at(-laplacian);
  });
}

/// select_flow on heights routed as `flow` (a flow node's routing, or its own).
NodeOutput select_flow_of(const SelectFlowNode& p, std::span<const Grid<float>* const> in, const water::FlowRouting& flow,
                          const GraphWorld&, const Context&) {
  const Window window{std::log10(p.min_area_m2), std::nullopt, p.edge_decades};
  Grid<float> mask = mask_like(*in[0]);
  for (std::size_t i = 0; i < mask.size(); ++i) mask.values()[i] = window.at(std::log10(flow.area_m2.values()[i]));
  return mask;
}

NodeOutput run_select_flow(const SelectFlowNode& p, std::span<const Grid<float>* const> in, const GraphWorld& world,
                           const Context& context) {
  return select_flow_of(p, in, water::route_flow(*in[0], water::Outlets{world.sea_level_m}, context), world, context);
}

/// Cells whose centre lies inside an odd number of `rings` (scanline, even-odd).
Grid<std::uint8_t> inside_cells(const std::vector<contour::Ring>& rings, const Grid<float>& like) {
  Grid<std::uint8_t> inside(like.width(), like.height(), 0);
  const contour::GridFrame frame = contour::GridFrame::of(like);
  parallel_for(0, like.height(), [&](int y) {
    const double north = frame.north(y);
    std::vector<double> crossings;
    for (const contour::Ring& ring : rings)
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const contour::Point a = ring[i], b = ring[(i + 1) % ring.size()];
        if ((a.y > north) != (b.y > north)) crossings.push_back(a.x + (north - a.y) / (b.y - a.y) * (b.x - a.x));
      }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
      for (int x = std::max(0, static_cast<int>(std::ceil(frame.column(crossings[k]))));
           x <= std::min(like.width() - 1, static_cast<int>(std::floor(frame.column(crossings[k + 1])))); ++x)
        inside(x, y) = 1;
  });
  return inside;
}

Grid<float> run_mask_polygon(const MaskPolygonNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context&) {
  if (p.file.empty()) fail("a mask_polygon node needs file: the polygons");
  const auto format = io::seed_format_for(p.file);
  if (!format || *format == io::SeedFormat::svg)
    fail("the mask_polygon node's {} has an unknown extension: allowed are .geojson .json .csv .txt", p.file);
  const std::filesystem::path path = world.resolve(p.file);
  const SeedContours polygons = parse_seeds(io::read_text_file(path), *format, p.file);
  const Grid<float> like(world.width, world.height, 0.0f, world.cell_m);
  const Grid<std::uint8_t> inside = inside_cells(polygons.rings, like);
  // Signed distance to the line: to the nearest outside cell from inside, and back.
  Grid<float> mask = mask_like(like);
  Grid<std::uint8_t> outside(inside.width(), inside.height(), 0);
  for (std::size_t i = 0; i < inside.size(); ++i) outside.values()[i] = inside.values()[i] ? 0 : 1;
  const double half_cell = 0.5 * world.cell_m;
  const auto fill = [&](const Grid<std::uint8_t>& sources, bool in_polygon) {
    contour::visit_nearest_sources(sources, [&](int x, int y, int sx, int sy) {
      if ((inside(x, y) != 0) != in_polygon) return;
      // From a cell's centre to the line, about: to the nearest centre across it, less half a cell.
      const double d = sx < 0 ? 1e30 : std::hypot(x - sx, y - sy) * world.cell_m - half_cell;
      const double signed_m = in_polygon ? d : -d;
      mask(x, y) = p.edge_m > 0 ? static_cast<float>(std::clamp(0.5 + signed_m / p.edge_m, 0.0, 1.0)) : (in_polygon ? 1.0f : 0.0f);
    });
  };
  fill(outside, true);
  fill(inside, false);
  return mask;
}

/// a and b of the same size, or a message naming the node kind.
void same_size(const Grid<float>& a, const Grid<float>& b, std::string_view kind) {
  if (a.width() != b.width() || a.height() != b.height())
    fail("a {} node's inputs are {}x{} and {}x{}: they must be the same size", kind, a.width(), a.height(), b.width(), b.height());
}

template <class F>
NodeKind pairwise(std::string name, std::string help, F&& f) {
  const std::string kind_name = name;
  return kind_of<NoParams>(std::move(name), "combining", std::move(help), {{"a", ValueType::heights}, {"b", ValueType::heights}},
                           ValueType::heights,
                           [f, kind_name](const NoParams&, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
                             same_size(*in[0], *in[1], kind_name);
                             Heightfield out = *in[0];
                             for (std::size_t i = 0; i < out.size(); ++i) out.values()[i] = f(in[0]->values()[i], in[1]->values()[i]);
                             return out;
                           });
}

}  // namespace

void add_mask_kinds(std::vector<NodeKind>& kinds) {
  using V = ValueType;
  const InputSlot heights{"heights", V::heights, false};
  kinds.push_back(kind_of<SelectHeightNode>("select_height", "mask", "1 where the heights lie between min and max", {heights}, V::mask,
                                            run_select_height));
  kinds.push_back(
      kind_of<SelectSlopeNode>("select_slope", "mask", "1 where the slope is at least min degrees", {heights}, V::mask, run_select_slope));
  kinds.push_back(kind_of<SelectCurvatureNode>("select_curvature", "mask", "1 on convex (or, with max below 0, concave) ground", {heights},
                                               V::mask, run_select_curvature));
  kinds.push_back(kind_of<SelectFlowNode>("select_flow", "mask", "1 where the drainage area is at least min_area", {heights}, V::mask,
                                          run_select_flow));
  kinds.back().scratch_bytes_per_cell = 48.0;  // the flow routing's receivers, stack and areas
  set_run_routed<SelectFlowNode>(kinds.back(), select_flow_of);
  kinds.back().seconds = [](const std::any&, const GraphWorld& world) { return 2.5e-7 * world.cells(); };
  kinds.push_back(kind_of<MaskPolygonNode>("mask_polygon", "mask", "1 inside the polygons of a file, soft across their edge", {}, V::mask,
                                           run_mask_polygon));
  kinds.push_back(kind_of<NoParams>("blend", "combining", "a where the mask is 0, b where it is 1, mixed between",
                                    {{"a", V::heights}, {"b", V::heights}, {"mask", V::mask}}, V::heights,
                                    [](const NoParams&, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
                                      same_size(*in[0], *in[1], "blend");
                                      same_size(*in[0], *in[2], "blend");
                                      Heightfield out = *in[0];
                                      // a (1 - m) + b m: exactly a where m is 0 and exactly b where m is 1.
                                      for (std::size_t i = 0; i < out.size(); ++i) {
                                        const float m = in[2]->values()[i];
                                        out.values()[i] = in[0]->values()[i] * (1.0f - m) + in[1]->values()[i] * m;
                                      }
                                      return out;
                                    }));
  kinds.push_back(pairwise("max", "The higher of a and b", [](float a, float b) { return std::max(a, b); }));
  kinds.push_back(pairwise("min", "The lower of a and b", [](float a, float b) { return std::min(a, b); }));
  kinds.push_back(pairwise("add", "a plus b", [](float a, float b) { return a + b; }));
}

}  // namespace sansui::scene
