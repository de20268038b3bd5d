// Seed contours from text files (GeoJSON, CSV, SVG): see seed_files.hpp.
#include "io/seed_files.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/file_formats.hpp"
#include "io/json_text.hpp"
#include "io/number_pairs.hpp"

namespace sansui::io {
namespace {

using Point = PlanePoint;
using Ring = PlaneRing;

// ---- GeoJSON ------------------------------------------------------------------------------

Ring ring_of_positions(const nlohmann::json& positions, std::string_view source) {
  if (!positions.is_array()) fail("{}: coordinates must be an array of [x, y] positions", source);
  Ring ring;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto& p = positions[i];
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
      fail("{}: position {} is {}: it must be [x, y] with numbers in metres", source, i, p.dump());
    ring.push_back({p[0].get<double>(), p[1].get<double>()});
  }
  return ring;
}

/// One ring found in a file: its points, whether the format closed it, and where it was.
struct Found {
  Ring ring;
  bool closed = true;
  std::string where;  ///< e.g. "feature 2, polygon 1", for messages
};

void find_geometries(const nlohmann::json& node, std::string_view source, const std::string& where, std::vector<Found>& out,
                     std::vector<std::string>& notes) {
  if (!node.is_object()) return;
  const std::string type = string_member(node, "type");
  if (type == "FeatureCollection") {
    if (!node.contains("features") || !node["features"].is_array()) fail("{}: a FeatureCollection needs a features array", source);
    const auto& features = node["features"];
    for (std::size_t i = 0; i < features.size(); ++i) find_geometries(features[i], source, fmt::format("feature {}", i + 1), out, notes);
  } else if (type == "Feature") {
    if (node.contains("geometry")) find_geometries(node["geometry"], source, where, out, notes);
  } else if (type == "GeometryCollection") {
    const auto geometries = node.value("geometries", nlohmann::json::array());
    for (std::size_t i = 0; i < geometries.size(); ++i)
      find_geometries(geometries[i], source, fmt::format("{}{}geometry {}", where, where.empty() ? "" : ", ", i + 1), out, notes);
  } else if (type == "Polygon" || type == "MultiPolygon" || type == "LineString") {
    const auto& coords = node.contains("coordinates") ? node["coordinates"] : nlohmann::json();
    if (!coords.is_array() || coords.empty()) fail("{}: the {} has no coordinates", source, type);
    if (type == "LineString") {
      out.push_back({ring_of_positions(coords, source), false, where});
      return;
    }
    const std::size_t polygons = type == "Polygon" ? 1 : coords.size();
    for (std::size_t k = 0; k < polygons; ++k) {
      const auto& polygon = type == "Polygon" ? coords : coords[k];
      if (!polygon.is_array() || polygon.empty()) fail("{}: the {} has no rings", source, type);
      const std::string at = type == "Polygon" ? where : fmt::format("{}{}polygon {}", where, where.empty() ? "" : ", ", k + 1);
      out.push_back({ring_of_positions(polygon[0], source), true, at});
      if (polygon.size() > 1)
        notes.push_back(fmt::format("{}: {}{}the polygon's {} hole(s) are ignored (a seed is the outline of one mountain)", source, at,
                                    at.empty() ? "" : ": ", polygon.size() - 1));
    }
  }
}

SeedOutlines parse_geojson(std::string_view text, std::string_view source) {
  const nlohmann::json root = parse_json(text, source);
  std::vector<Found> found;
  SeedOutlines seeds;
  find_geometries(root, source, "", found, seeds.notes);
  if (found.empty()) fail("{}: no Polygon, MultiPolygon or LineString geometry found", source);
  for (Found& f : found) {
    std::string name = f.where.empty() || found.size() == 1 ? std::string(source) : fmt::format("{} ({})", source, f.where);
    seeds.outlines.push_back({std::move(f.ring), f.closed, std::move(name)});
  }
  return seeds;
}

// ---- CSV ----------------------------------------------------------------------------------

SeedOutlines parse_csv(std::string_view text, std::string_view source) {
  Ring ring;
  for (const auto& pair : detail::read_number_pairs(text, source, "a point: give x,y in metres")) ring.push_back({pair.first, pair.second});
  SeedOutlines seeds;
  seeds.outlines.push_back({std::move(ring), true, std::string(source)});
  return seeds;
}

// ---- SVG ----------------------------------------------------------------------------------

/// The value of attribute `name` in the tag starting at `tag`, or nullopt.
std::optional<std::string> attribute(std::string_view text, std::size_t tag, std::string_view name) {
  const std::size_t close = text.find('>', tag);
  const std::string_view element = text.substr(tag, close == std::string_view::npos ? std::string_view::npos : close - tag);
  std::size_t at = 0;
  while ((at = element.find(name, at)) != std::string_view::npos) {
    const bool boundary = at > 0 && std::isspace(static_cast<unsigned char>(element[at - 1]));
    std::size_t eq = at + name.size();
    while (eq < element.size() && std::isspace(static_cast<unsigned char>(element[eq]))) ++eq;
    if (boundary && eq < element.size() && element[eq] == '=') {
      std::size_t q = eq + 1;
      while (q < element.size() && std::isspace(static_cast<unsigned char>(element[q]))) ++q;
      if (q < element.size() && (element[q] == '"' || element[q] == '\'')) {
        const std::size_t end = element.find(element[q], q + 1);
        if (end != std::string_view::npos) return std::string(element.substr(q + 1, end - q - 1));
      }
    }
    at += name.size();
  }
  return std::nullopt;
}

/// Reads numbers and command letters of SVG point lists and path data.
class PathLexer {
 public:
  explicit PathLexer(std::string_view s) : s_(s) {}
  void skip() {
    while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])) || s_[i_] == ',')) ++i_;
  }
  bool at_end() {
    skip();
    return i_ >= s_.size();
  }
  bool at_command() {
    skip();
    return i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_])) && s_[i_] != 'e' && s_[i_] != 'E';
  }
  char command() { return s_[i_++]; }
  std::optional<double> number() {
    skip();
    std::size_t j = i_;
    if (j < s_.size() && (s_[j] == '-' || s_[j] == '+')) ++j;
    bool dot = false;
    while (j < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[j])) || (s_[j] == '.' && !dot))) dot |= s_[j++] == '.';
    if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
      ++j;
      if (j < s_.size() && (s_[j] == '-' || s_[j] == '+')) ++j;
      while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
    }
    std::string_view token = s_.substr(i_, j - i_);
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || token.empty()) return std::nullopt;
    i_ = j;
    return value;
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

/// The subpaths of path data `d` (points, and whether Z closed it), curves flattened into 16
/// pieces each.
std::vector<std::pair<Ring, bool>> path_points(std::string_view d, std::string_view source) {
  PathLexer lex(d);
  std::vector<std::pair<Ring, bool>> subpaths;
  Ring ring;
  Point current, start, last_control;
  char command = 0, previous = 0;
  bool closed = false;
  auto need = [&](char c) {
    const auto v = lex.number();
    if (!v) fail("{}: path command '{}' needs numbers in '{}'", source, c, d.substr(0, 80));
    return *v;
  };
  auto cubic = [&](Point p0, Point p1, Point p2, Point p3) {
    for (int k = 1; k <= 16; ++k) {
      const double t = k / 16.0, u = 1.0 - t;
      ring.push_back(u * u * u * p0 + 3.0 * u * u * t * p1 + 3.0 * u * t * t * p2 + t * t * t * p3);
    }
  };
  while (!lex.at_end()) {
    if (lex.at_command()) {
      command = lex.command();
    } else if (command == 0) {
      fail("{}: path data must start with a command letter (M)", source);
    } else if (command == 'Z' || command == 'z') {  // Z takes no numbers: repeating it would read nothing, forever
      fail("{}: path command '{}' takes no numbers, but numbers follow it in '{}': start the next subpath with M", source, command,
           d.substr(0, 80));
    }
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    const Point base = relative ? current : Point{};
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    if (c == 'M' && !ring.empty()) subpaths.emplace_back(std::exchange(ring, {}), std::exchange(closed, false));  // a new subpath
    if (c != 'M' && ring.empty() && !subpaths.empty()) ring.push_back(current);  // drawing on after Z: from the last start
    switch (c) {
      case 'M':
        current = base + Point{need(command), need(command)};
        start = current;
        ring.push_back(current);
        command = relative ? 'l' : 'L';  // following pairs are line-tos
        break;
      case 'L':
        current = base + Point{need(command), need(command)};
        ring.push_back(current);
        break;
      case 'H':
        current = {(relative ? current.x : 0.0) + need(command), current.y};
        ring.push_back(current);
        break;
      case 'V':
        current = {current.x, (relative ? current.y : 0.0) + need(command)};
        ring.push_back(current);
        break;
      case 'C':
      case 'S': {  // S: the first control point mirrors the last one of a C or S before it
        const char p = static_cast<char>(std::toupper(static_cast<unsigned char>(previous)));
        const Point p1 =
            c == 'C' ? base + Point{need(command), need(command)} : ((p == 'C' || p == 'S') ? current + (current - last_control) : current);
        const Point p2 = base + Point{need(command), need(command)};
        const Point p3 = base + Point{need(command), need(command)};
        cubic(current, p1, p2, p3);
        last_control = p2;
        current = p3;
        break;
      }
      case 'Q':
      case 'T': {
        const char p = static_cast<char>(std::toupper(static_cast<unsigned char>(previous)));
        const Point q1 =
            c == 'Q' ? base + Point{need(command), need(command)} : ((p == 'Q' || p == 'T') ? current + (current - last_control) : current);
        const Point q2 = base + Point{need(command), need(command)};
        cubic(current, current + (2.0 / 3.0) * (q1 - current), q2 + (2.0 / 3.0) * (q1 - q2), q2);
        last_control = q1;
        current = q2;
        break;
      }
      case 'Z':
        closed = true;
        current = start;
        break;
      case 'A':
        fail("{}: SVG arc commands (A) are not supported in seed paths: convert arcs to curves or lines", source);
      default:
        fail("{}: unknown SVG path command '{}'", source, command);
    }
    previous = command;
    if (closed) subpaths.emplace_back(std::exchange(ring, {}), std::exchange(closed, false));
  }
  if (!ring.empty()) subpaths.emplace_back(std::move(ring), closed);
  return subpaths;
}

/// An SVG transform, x' = a x + c y + e and y' = b x + d y + f (SVG's own matrix(a b c d e f)).
struct Affine {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;
  Affine then(const Affine& inner) const {  // this applied after inner: a parent's after its child's
    return {a * inner.a + c * inner.b, b * inner.a + d * inner.b,     a * inner.c + c * inner.d,
            b * inner.c + d * inner.d, a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
  Point operator()(Point p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
};

/// One transform function of a transform list, from its name and numbers.
Affine transform_function(std::string_view name, const std::vector<double>& v, std::string_view source) {
  const auto takes = [&](std::initializer_list<std::size_t> counts) {
    if (std::ranges::find(counts, v.size()) == counts.end())
      fail("{}: the SVG transform {}() takes {} numbers, not {}", source, name, fmt::join(counts, " or "), v.size());
  };
  constexpr double radians = 3.14159265358979323846 / 180.0;
  if (name == "matrix") {
    takes({6});
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  if (name == "translate") {
    takes({1, 2});
    return {1.0, 0.0, 0.0, 1.0, v[0], v.size() > 1 ? v[1] : 0.0};
  }
  if (name == "scale") {
    takes({1, 2});
    return {v[0], 0.0, 0.0, v.size() > 1 ? v[1] : v[0], 0.0, 0.0};
  }
  if (name == "skewX" || name == "skewY") {
    takes({1});
    const double shear = std::tan(v[0] * radians);
    return name == "skewX" ? Affine{1.0, 0.0, shear, 1.0, 0.0, 0.0} : Affine{1.0, shear, 0.0, 1.0, 0.0, 0.0};
  }
  if (name == "rotate") {  // rotate(a), or rotate(a cx cy) about (cx, cy)
    takes({1, 3});
    const double cos = std::cos(v[0] * radians), sin = std::sin(v[0] * radians);
    const Affine turn{cos, sin, -sin, cos, 0.0, 0.0};
    if (v.size() == 1) return turn;
    return Affine{1.0, 0.0, 0.0, 1.0, v[1], v[2]}.then(turn).then(Affine{1.0, 0.0, 0.0, 1.0, -v[1], -v[2]});
  }
  fail("{}: unknown SVG transform '{}' (allowed: matrix, translate, scale, rotate, skewX, skewY)", source, name.substr(0, 40));
}

/// A transform attribute's list ("translate(10 20) scale(2)"), applied right to left as SVG says.
Affine parse_transform(std::string_view list, std::string_view source) {
  Affine result;
  std::size_t at = 0;
  while (true) {
    while (at < list.size() && (std::isspace(static_cast<unsigned char>(list[at])) || list[at] == ',')) ++at;
    if (at >= list.size()) return result;
    const std::size_t open = list.find('(', at), close = list.find(')', at);
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      fail("{}: the SVG transform '{}' is not a list of name(numbers)", source, list.substr(0, 80));
    std::string_view name = list.substr(at, open - at);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.remove_suffix(1);
    PathLexer lex(list.substr(open + 1, close - open - 1));
    std::vector<double> numbers;
    while (!lex.at_end()) {
      const auto number = lex.number();
      if (!number) fail("{}: the SVG transform '{}' holds something that is not a number", source, list.substr(0, 80));
      numbers.push_back(*number);
    }
    result = result.then(transform_function(name, numbers, source));
    at = close + 1;
  }
}

/// The rings of one <path>, <polygon> or <polyline> starting at `at`, in the user space of the
/// document (its own transform and its groups' applied), with their names for messages.
void add_shape(std::string_view text, std::size_t at, std::string_view tag, const Affine& transform, std::string_view source,
               std::vector<std::pair<Ring, bool>>& rings, std::vector<std::string>& names) {
  const std::string element = fmt::format("<{}> {}", tag, names.size() + 1);
  std::vector<std::pair<Ring, bool>> shapes;
  if (tag == "path") {
    const auto d = attribute(text, at, "d");
    if (!d) fail("{}: the <path> has no d attribute", source);
    shapes = path_points(*d, source);
  } else {
    const auto points = attribute(text, at, "points");
    if (!points) fail("{}: the <{}> has no points attribute", source, tag);
    PathLexer lex(*points);
    Ring ring;
    while (!lex.at_end()) {
      const auto x = lex.number(), y = lex.number();
      if (!x || !y) fail("{}: the points attribute must hold pairs of numbers", source);
      ring.push_back({*x, *y});
    }
    shapes.emplace_back(std::move(ring), tag == "polygon");
  }
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    for (Point& p : shapes[k].first) {
      p = transform(p);
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("{}: the transform of {} moves a point past any number", source, element);
    }
    rings.push_back(std::move(shapes[k]));
    names.push_back(shapes.size() > 1 ? fmt::format("{}, subpath {}", element, k + 1) : element);
  }
}

/// The deepest nesting of SVG elements read (a drawing program's files nest a few levels).
constexpr std::size_t max_svg_depth = 256;

SeedOutlines parse_svg(std::string_view text, std::string_view source, double metres_per_unit) {
  if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit))
    fail("SVG scale {} is not allowed: give metres per SVG unit > 0", metres_per_unit);
  // Every <polygon>, <polyline> and <path> in document order; every subpath of a path. Each
  // open element's transform (Inkscape puts layers in <g transform="...">) applies to what it
  // holds: a stack of them, popped by closing tags. Comments, <?...?> and <!...> are skipped.
  std::vector<std::pair<Ring, bool>> rings;
  std::vector<std::string> names;
  std::vector<Affine> open{Affine{}};
  for (std::size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at + 1)) {
    if (text.substr(at, 4) == "<!--") {
      at = text.find("-->", at);
      if (at == std::string_view::npos) break;
      continue;
    }
    if (at + 1 < text.size() && (text[at + 1] == '?' || text[at + 1] == '!')) continue;
    if (at + 1 < text.size() && text[at + 1] == '/') {
      if (open.size() > 1) open.pop_back();
      continue;
    }
    std::size_t end = at + 1;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == ':' || text[end] == '_' || text[end] == '-'))
      ++end;
    const std::string_view tag = text.substr(at + 1, end - at - 1);
    if (tag.empty()) continue;
    const std::size_t close = text.find('>', at);
    const bool self_closing = close != std::string_view::npos && close > at && text[close - 1] == '/';
    const auto own = attribute(text, at, "transform");
    const Affine transform = own ? open.back().then(parse_transform(*own, source)) : open.back();
    if (tag == "path" || tag == "polygon" || tag == "polyline") add_shape(text, at, tag, transform, source, rings, names);
    if (!self_closing) {
      if (open.size() > max_svg_depth) fail("{}: elements nested deeper than {} levels", source, max_svg_depth);
      open.push_back(transform);
    }
  }
  if (rings.empty()) fail("{}: no <polygon>, <polyline> or <path> element found", source);
  SeedOutlines seeds;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    auto& [ring, closed] = rings[k];
    for (Point& p : ring) p = {p.x * metres_per_unit, -p.y * metres_per_unit};  // y down -> north up
    seeds.outlines.push_back({std::move(ring), closed, rings.size() == 1 ? std::string(source) : fmt::format("{} ({})", source, names[k])});
  }
  return seeds;
}

}  // namespace

std::optional<SeedFormat> seed_format_for(std::string_view file_name) {
  const std::filesystem::path path(file_name);
  if (const FileFormat* vector = file_format_for(path, FormatData::vector, Access::read))
    return vector->name == "svg" ? SeedFormat::svg : SeedFormat::geojson;
  const FileFormat* pairs = file_format_for(path, FormatData::table, Access::read);
  if (pairs && pairs->name != "json") return SeedFormat::csv;  // .csv, .txt: x,y lines
  return std::nullopt;
}

SeedOutlines read_seed_outlines(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit) {
  switch (format) {
    case SeedFormat::csv:
      return parse_csv(text, source);
    case SeedFormat::svg:
      return parse_svg(text, source, metres_per_unit);
    case SeedFormat::geojson:
      break;
  }
  return parse_geojson(text, source);
}

}  // namespace sansui::io
