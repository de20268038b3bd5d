// Seed contours from text files (GeoJSON, CSV, SVG): see seed_files.hpp.
#include "io/seed_files.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <utility>

#include <fmt/format.h>
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

SeedOutlines parse_svg(std::string_view text, std::string_view source, double metres_per_unit) {
  if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit))
    fail("SVG scale {} is not allowed: give metres per SVG unit > 0", metres_per_unit);
  // Every <polygon>, <polyline> and <path> in document order; every subpath of a path.
  std::vector<std::pair<Ring, bool>> rings;
  std::vector<std::string> names;
  for (std::size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at + 1)) {
    const auto starts = [&](std::string_view tag) {
      const std::size_t end = at + 1 + tag.size();
      return text.substr(at + 1, tag.size()) == tag && end < text.size() &&
             (std::isspace(static_cast<unsigned char>(text[end])) || text[end] == '/' || text[end] == '>');
    };
    const bool polygon = starts("polygon"), polyline = starts("polyline"), path = starts("path");
    if (!polygon && !polyline && !path) continue;
    const std::string element = fmt::format("<{}> {}", path ? "path" : polygon ? "polygon" : "polyline", names.size() + 1);
    if (path) {
      const auto d = attribute(text, at, "d");
      if (!d) fail("{}: the <path> has no d attribute", source);
      const auto subpaths = path_points(*d, source);
      for (std::size_t k = 0; k < subpaths.size(); ++k) {
        rings.push_back(subpaths[k]);
        names.push_back(subpaths.size() > 1 ? fmt::format("{}, subpath {}", element, k + 1) : element);
      }
    } else {
      const auto points = attribute(text, at, "points");
      if (!points) fail("{}: the <{}> has no points attribute", source, polygon ? "polygon" : "polyline");
      PathLexer lex(*points);
      Ring ring;
      while (!lex.at_end()) {
        const auto x = lex.number(), y = lex.number();
        if (!x || !y) fail("{}: the points attribute must hold pairs of numbers", source);
        ring.push_back({*x, *y});
      }
      rings.emplace_back(std::move(ring), polygon);
      names.push_back(element);
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
