// The streaming contour-map reader (io/contour_lines_geojson.cpp) against the reader it replaced,
// which parsed the whole text into an nlohmann tree first (kept here as the reference): the same
// lines, spot heights and messages for the examples, members in any order, and thousands of
// mutated files; and a message naming the value for each kind of bad input.
#include <cmath>
#include <cstdlib>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/geojson_crs.hpp"
#include "io/json_text.hpp"
#include "io/text_file.hpp"
#include "tests/fuzz/mutate.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

// ---- the reference: the reader before streaming, unchanged but for its name -------------------

namespace reference {

using Point = PlanePoint;

Point position(const nlohmann::json& p, std::string_view source, std::size_t feature) {
  if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
    fail("{}: feature {}: position {} must be [x, y] with numbers in metres", source, feature, p.dump());
  const Point at{p[0].get<double>(), p[1].get<double>()};
  if (!std::isfinite(at.x) || !std::isfinite(at.y)) fail("{}: feature {}: position {} is not finite", source, feature, p.dump());
  return at;
}

void add_line(ContourMap& map, const nlohmann::json& positions, bool ring, double z, std::string_view source, std::size_t feature) {
  if (!positions.is_array()) fail("{}: feature {}: coordinates must be an array of [x, y] positions", source, feature);
  ContourLine line;
  line.elevation_m = z;
  for (const auto& p : positions) line.points.push_back(position(p, source, feature));
  if (line.points.size() < 2)
    fail("{}: feature {}: a contour line needs at least 2 positions, it has {}", source, feature, line.points.size());
  line.closed = ring || line.points.front() == line.points.back();
  if (line.closed && line.points.size() > 2 && line.points.front() == line.points.back()) line.points.pop_back();
  map.lines.push_back(std::move(line));
}

double elevation_of(const nlohmann::json& properties, const std::string& attribute, std::string_view source, std::size_t feature) {
  const nlohmann::json* value = nullptr;
  std::string name = attribute;
  if (properties.is_object()) {
    if (!attribute.empty()) {
      if (properties.contains(attribute)) value = &properties[attribute];
    } else {
      for (const char* candidate : io::default_elevation_attributes)
        if (properties.contains(candidate)) {
          value = &properties[candidate];
          name = candidate;
          break;
        }
    }
  }
  if (value == nullptr) {
    if (attribute.empty())
      fail(
          "{}: feature {} has no elevation attribute (tried elev, ELEV, elevation, elevation_m, ELEVATION): name it with "
          "--elevation-attribute",
          source, feature);
    fail("{}: feature {} has no attribute \"{}\" (--elevation-attribute)", source, feature, attribute);
  }
  double z = NAN;
  if (value->is_number())
    z = value->get<double>();
  else if (value->is_string()) {
    const std::string text = value->get<std::string>();
    char* end = nullptr;
    z = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') z = NAN;
  }
  if (!std::isfinite(z)) fail("{}: feature {}: elevation {} = {} is not a finite number of metres", source, feature, name, value->dump());
  return z;
}

ContourMap parse_contour_map(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights) {
  const nlohmann::json root = io::parse_json(text, source);
  if (!root.is_object() || io::string_member(root, "type") != "FeatureCollection" || !root.contains("features") ||
      !root["features"].is_array())
    fail("{}: not a GeoJSON FeatureCollection of contour lines", source);
  ContourMap map;
  const auto& features = root["features"];
  for (std::size_t f = 0; f < features.size(); ++f) {
    const auto& feature = features[f];
    if (!feature.is_object() || !feature.contains("geometry") || !feature["geometry"].is_object()) continue;
    const auto& geometry = feature["geometry"];
    const std::string type = io::string_member(geometry, "type");
    const bool line = type == "LineString" || type == "MultiLineString" || type == "Polygon" || type == "MultiPolygon";
    const bool point = type == "Point" || type == "MultiPoint";
    if (!line && !(point && spot_heights)) continue;
    const double z = elevation_of(feature.value("properties", nlohmann::json()), attribute, source, f);
    if (!geometry.contains("coordinates") || !geometry["coordinates"].is_array())
      fail("{}: feature {}: the {} has no coordinates", source, f, type);
    const auto& c = geometry["coordinates"];
    if (type == "LineString") {
      add_line(map, c, false, z, source, f);
    } else if (type == "MultiLineString") {
      for (const auto& part : c) add_line(map, part, false, z, source, f);
    } else if (type == "Polygon") {
      for (const auto& ring : c) add_line(map, ring, true, z, source, f);
    } else if (type == "MultiPolygon") {
      for (const auto& polygon : c) {
        if (!polygon.is_array()) fail("{}: feature {}: a MultiPolygon's polygons must be arrays of rings", source, f);
        for (const auto& ring : polygon) add_line(map, ring, true, z, source, f);
      }
    } else if (type == "Point") {
      map.spots.push_back({position(c, source, f), z});
    } else {
      for (const auto& p : c) map.spots.push_back({position(p, source, f), z});
    }
  }
  if (map.lines.empty()) fail("{}: no contour lines (LineString, MultiLineString, Polygon or MultiPolygon features)", source);
  return map;
}

}  // namespace reference

// ---- comparing ------------------------------------------------------------------------------------

/// The map, or the message: one text to compare.
template <class Parse>
std::string outcome(Parse&& parse) {
  try {
    const ContourMap map = parse();
    std::string out = fmt::format("{} lines, {} spots\n", map.lines.size(), map.spots.size());
    for (const ContourLine& line : map.lines) {
      out += fmt::format("{} {} {}:", line.elevation_m, line.closed, line.points.size());
      for (const PlanePoint& p : line.points) out += fmt::format(" {} {}", p.x, p.y);
      out += '\n';
    }
    for (const auto& spot : map.spots) out += fmt::format("spot {} {} {}\n", spot.at.x, spot.at.y, spot.elevation_m);
    return out;
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

std::string streamed(const std::string& text, const std::string& attribute = "", bool spots = true) {
  return outcome([&] { return io::parse_contour_map(text, "t.geojson", attribute, spots); });
}

std::string parsed(const std::string& text, const std::string& attribute = "", bool spots = true) {
  return outcome([&] { return reference::parse_contour_map(text, "t.geojson", attribute, spots); });
}

/// Whether the two outcomes agree: the same map, or both an error (with the same message unless
/// it is a JSON syntax error, whose wording is each parser's own).
bool agree(const std::string& a, const std::string& b) {
  const bool syntax_a = a.find("not valid JSON") != std::string::npos, syntax_b = b.find("not valid JSON") != std::string::npos;
  if (syntax_a || syntax_b) return syntax_a && syntax_b;
  return a == b;
}

const std::string examples = std::string(sansui::test::source_dir) + "/examples/contours/";

TEST(ContourMapGeoJson, ReadsTheExamplesAsTheTreeReaderDid) {
  for (const char* name : {"jacksboro_40m.geojson", "ridge.geojson", "neck.geojson", "c_shape.geojson"}) {
    const std::string text = io::read_text_file(examples + name);
    for (bool spots : {false, true}) EXPECT_EQ(streamed(text, "", spots), parsed(text, "", spots)) << name;
  }
}

TEST(ContourMapGeoJson, ReadsInPlaceFromSpareCapacityAsFromACopy) {
  const std::string text = io::read_text_file(examples + "jacksboro_40m.geojson", std::size_t(1) << 30, io::contour_map_padding);
  ASSERT_GE(text.capacity() - text.size(), io::contour_map_padding);
  EXPECT_EQ(outcome([&] { return io::parse_contour_map(text, "t.geojson", "", false, text.capacity() - text.size()); }),
            parsed(text, "", false));
}

TEST(ContourMapGeoJson, MembersInAnyOrderGiveTheSameMap) {
  const std::string usual = R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"elev":10},"geometry":{"type":"LineString","coordinates":[[0,0],[1,2],[3,4.5]]}},
    {"type":"Feature","properties":{"ELEV":20,"elev":"21.5"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[9,0],[9,9],[0,0]]]}},
    {"type":"Feature","properties":{"elev":30},"geometry":{"type":"MultiPoint","coordinates":[[5,5],[6,6,7]]}}]})";
  const std::string reordered = R"({"features":[
    {"geometry":{"coordinates":[[0,0],[1,2],[3,4.5]],"type":"LineString"},"properties":{"elev":10},"type":"Feature"},
    {"geometry":{"coordinates":[[[0,0],[9,0],[9,9],[0,0]]],"type":"Polygon"},"type":"Feature","properties":{"elev":"21.5","ELEV":20}},
    {"properties":{"elev":30},"geometry":{"coordinates":[[5,5],[6,6,7]],"type":"MultiPoint"}}],"type":"FeatureCollection"})";
  EXPECT_EQ(streamed(usual), parsed(usual));
  EXPECT_EQ(streamed(reordered), parsed(reordered));
  EXPECT_EQ(streamed(usual), streamed(reordered));
  EXPECT_THAT(streamed(usual), HasSubstr("2 lines, 2 spots"));
  // A repeated member: the last one counts, as in a parsed tree.
  const std::string repeated = R"({"type":"FeatureCollection","features":[{"properties":{"elev":1},"geometry":{"type":"Point",
    "coordinates":[[0,0],[5,5]],"type":"LineString"},"properties":{"elev":2}}]})";
  EXPECT_EQ(streamed(repeated), parsed(repeated));
}

TEST(ContourMapGeoJson, NumbersAreReadAsStrtodReadsThem) {
  // gdal_contour writes up to 20 significant digits; 1e-400 underflows to 0; big integers.
  const std::string text = R"({"type":"FeatureCollection","features":[{"properties":{"elev":123456789012345678901234567890},
    "geometry":{"type":"LineString","coordinates":[[10392.75,31676.589363589500863],[-0.0,1e-400],[1.7976931348623157e308,2.2250738585072014e-308],
    [5e-324,0.1e1],[31699.749953437730,-4.9406564584124654e-324]]}}]})";
  EXPECT_EQ(streamed(text), parsed(text));
  EXPECT_THAT(streamed(text), HasSubstr("1 lines"));
}

TEST(ContourMapGeoJson, BadInputGivesOneLineNamingTheValue) {
  const auto map = [](const std::string& feature) { return R"({"type":"FeatureCollection","features":[)" + feature + "]}"; };
  const auto line = [&](const std::string& coordinates) {
    return map(R"({"properties":{"elev":5},"geometry":{"type":"LineString","coordinates":)" + coordinates + "}}");
  };
  const std::pair<std::string, std::string> cases[] = {
      {line(R"([[0,0],["1",2]])"), "feature 0: position [\"1\",2] must be [x, y] with numbers in metres"},
      {line(R"([[0,0],[1]])"), "feature 0: position [1] must be [x, y] with numbers in metres"},
      {line(R"([[0,0],7])"), "feature 0: position 7 must be [x, y] with numbers in metres"},
      {line(R"([[0,0]])"), "feature 0: a contour line needs at least 2 positions, it has 1"},
      {line(R"("none")"), "feature 0: the LineString has no coordinates"},
      {map(R"({"properties":{"elev":5},"geometry":{"type":"MultiPolygon","coordinates":[7]}})"),
       "feature 0: a MultiPolygon's polygons must be arrays of rings"},
      {map(R"({"properties":{"elev":5},"geometry":{"type":"MultiLineString","coordinates":[{}]}})"),
       "feature 0: coordinates must be an array of [x, y] positions"},
      {map(R"({"properties":{"elev":[1]},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}})"),
       "feature 0: elevation elev = [1] is not a finite number of metres"},
      {map(R"({"properties":{"elev":"12 m"},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}})"),
       "feature 0: elevation elev = \"12 m\" is not a finite number of metres"},
      {map(R"({"properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}})"), "feature 0 has no elevation attribute"},
      // The elevation is checked before the coordinates, as before.
      {map(R"({"geometry":{"type":"LineString","coordinates":[[0,0]]},"properties":{"height":3}})"),
       "feature 0 has no elevation attribute"},
      {line(R"([[0,0],[1,1e400]])"), "not valid JSON"},
      {line(R"([[0,0],[1,01]])"), "not valid JSON"},
      {line(R"([[0,0],[1,1]])") + " x", "not valid JSON"},
      {R"({"type":"FeatureCollection","features":[{"properties":{"elev":5},"geometry":{"type":"LineString","coordinates":[[0,0]]}},
         {"bad": tru}]})",
       "not valid JSON"},  // a syntax error anywhere wins over an earlier feature's problem, as when the text was parsed first
      {R"({"type":"FeatureCollection","features":[{"properties":{"name":"a\x"},"geometry":null}]})", "not valid JSON"},
      {std::string(70, '[') + std::string(70, ']'), "nested more than 64 deep"},
      {"7", "not a GeoJSON FeatureCollection"},
      {"", "not valid JSON"},
  };
  for (const auto& [text, message] : cases) {
    const std::string got = streamed(text);
    EXPECT_THAT(got, HasSubstr(message)) << text;
    EXPECT_THAT(got, HasSubstr("t.geojson: ")) << text;
    EXPECT_EQ(got.find('\n'), std::string::npos) << text;
    EXPECT_TRUE(agree(got, parsed(text))) << text << "\nstreamed: " << got << "\nparsed: " << parsed(text);
  }
}

TEST(ContourMapGeoJson, MutatedFilesAgreeWithTheTreeReader) {
  // Thousands of mutations of a small map with every geometry: the same map or message, or (for
  // text that is not JSON) a JSON error from both; never a crash or another exception.
  const std::string seed = R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:2193"}},"features":[
    {"type":"Feature","properties":{"elev":10,"ID":1},"geometry":{"type":"LineString","coordinates":[[0,0],[1,2],[3,4.5]]}},
    {"type":"Feature","properties":{"ELEV":"20"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[9,0],[9,9],[0,0]],[[1,1],[2,1],[2,2]]]}},
    {"type":"Feature","properties":{"elevation":30},"geometry":{"type":"MultiLineString","coordinates":[[[5,5],[6,6]],[[7,7],[8,8]]]}},
    {"type":"Feature","properties":{"elev":40.25},"geometry":{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]]]}},
    {"type":"Feature","properties":{"elev":50},"geometry":{"type":"Point","coordinates":[4,4]}},
    {"type":"Feature","properties":{"elev":60},"geometry":{"type":"MultiPoint","coordinates":[[3,3],[2,2]]}},
    {"type":"Feature","properties":null,"geometry":null}]})";
  int same_map = 0, runs = 0;
  for (std::uint64_t n = 0; n < 4000; ++n) {
    std::string text = mutate(seed, n);
    if (n % 3 == 0) text = mutate(text, n + 100000);
    const std::string a = streamed(text, "", n % 2 == 0), b = parsed(text, "", n % 2 == 0);
    EXPECT_TRUE(agree(a, b)) << "input:\n" << text << "\nstreamed: " << a << "\nparsed: " << b;
    if (a == b && a.rfind("error", 0) != 0) ++same_map;
    ++runs;
    try {  // the streamed CRS reader: a CRS, or a clear error
      (void)io::geojson_input_crs(text, "t.geojson", n % 2 == 0);
    } catch (const InputError&) {}
  }
  EXPECT_EQ(runs, 4000);
  EXPECT_GT(same_map, 100);  // many mutations still read: the reader was really exercised
}

}  // namespace
}  // namespace sansui::test
