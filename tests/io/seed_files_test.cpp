#include "scene/seed_files.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/seed_files.hpp"
#include "tests/contour/contour_test_util.hpp"
#include "tests/test_paths.hpp"

namespace sansui::contour {
namespace {

using io::seed_format_for;
using io::SeedFormat;
using scene::parse_seed;

std::string read(const std::string& relative) {
  std::ifstream in(std::string(sansui::test::source_dir) + "/" + relative);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_error(std::string_view text, SeedFormat format, const std::string& fragment, double scale = 1.0) {
  try {
    parse_seed(text, format, "seed", scale);
    ADD_FAILURE() << "no error; expected one mentioning " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SeedInput, ExamplesParseCounterClockwiseAndSimple) {
  for (const char* name : {"ridge.geojson", "neck.geojson", "c_shape.geojson", "c_shape.csv"}) {
    const auto format = seed_format_for(name);
    ASSERT_TRUE(format) << name;
    const SeedContour seed = parse_seed(read(std::string("examples/contours/") + name), *format, name);
    EXPECT_GT(seed.ring.size(), 50u) << name;
    EXPECT_GT(signed_area(seed.ring), 0.0) << name;
    EXPECT_TRUE(seed.notes.empty()) << name << ": " << (seed.notes.empty() ? "" : seed.notes[0]);
  }
  // The SVG neck is the GeoJSON neck in units of 10 m with y down.
  const SeedContour svg = parse_seed(read("examples/contours/neck.svg"), SeedFormat::svg, "neck.svg", 10.0);
  const SeedContour json = parse_seed(read("examples/contours/neck.geojson"), SeedFormat::geojson, "neck.geojson");
  EXPECT_NEAR(signed_area(svg.ring), signed_area(json.ring), 1e-3 * signed_area(json.ring));
}

TEST(SeedInput, GeoJsonGeometriesAndOrientation) {
  // Clockwise polygon: reversed to counter-clockwise.
  const auto cw = parse_seed(R"({"type":"Polygon","coordinates":[[[0,0],[0,10],[10,10],[10,0],[0,0]]]})", SeedFormat::geojson, "s");
  EXPECT_NEAR(signed_area(cw.ring), 100.0, 1e-12);
  EXPECT_EQ(cw.ring.size(), 4u);
  // A LineString that closes exactly.
  const auto line = parse_seed(R"({"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[10,0],[10,10],[0,10],[0,0]]}})",
                               SeedFormat::geojson, "s");
  EXPECT_EQ(line.ring.size(), 4u);
  EXPECT_TRUE(line.notes.empty());
  // Almost closed: closed with a note.
  const auto almost = parse_seed(R"({"type":"LineString","coordinates":[[0,0],[10,0],[10,10],[0,10],[0,0.2]]})", SeedFormat::geojson, "s");
  ASSERT_EQ(almost.notes.size(), 1u);
  EXPECT_NE(almost.notes[0].find("closed it"), std::string::npos);
}

TEST(SeedInput, CsvWithHeaderAndComments) {
  const auto seed = parse_seed("x,y\n# a square\n0,0\n10,0\n10,10\n0,10\n", SeedFormat::csv, "s");
  EXPECT_EQ(seed.ring.size(), 4u);
  expect_error("0,0\n10,0\nten,10\n", SeedFormat::csv, "seed:3: 'ten,10' is not a point");
}

TEST(SeedInput, SvgPathsPolygonsAndScale) {
  const auto path = parse_seed(R"(<svg><path d="M0,0 h10 v-10 H0 z"/></svg>)", SeedFormat::svg, "s", 2.0);
  EXPECT_NEAR(signed_area(path.ring), 400.0, 1e-9);  // y flipped: (0,0) (20,0) (20,20) (0,20)
  const auto polygon = parse_seed(R"(<svg><polygon points="0,0 10,0 10,10 0,10"/></svg>)", SeedFormat::svg, "s");
  EXPECT_NEAR(signed_area(polygon.ring), 100.0, 1e-9);
  const auto curve = parse_seed(R"(<svg><path d="M0,0 C0,-10 10,-10 10,0 Z"/></svg>)", SeedFormat::svg, "s");
  EXPECT_GT(curve.ring.size(), 10u);
  expect_error(R"(<svg><path d="M0,0 A5,5 0 0 1 10,0 Z"/></svg>)", SeedFormat::svg, "arc commands (A) are not supported");
  expect_error(R"(<svg><path d="M0,0 h10 v-10 z 14,3"/></svg>)", SeedFormat::svg, "path command 'z' takes no numbers");
  expect_error(R"(<svg><rect width="3"/></svg>)", SeedFormat::svg, "no <polygon>, <polyline> or <path>");
  expect_error(R"(<svg><polygon points="0,0 10,0 10,10"/></svg>)", SeedFormat::svg, "SVG scale 0", 0.0);
}

/// The outlines of an SVG as the reader gives them (before normalising), in metres, y north.
io::SeedOutlines svg_outlines(std::string_view text) {
  return io::read_seed_outlines(text, SeedFormat::svg, "s");
}

TEST(SeedInput, SvgTransformsOfGroupsAndShapesApply) {
  // Inkscape's layers: a group moved and a shape scaled inside it; after </g> the next shape is
  // untouched; a shape in a comment is not read. SVG's y points down; the reader's north is up.
  const auto seeds = svg_outlines(R"svg(<svg><!-- <path d="M0,0 h1 v1 z"/> --><g id="layer1" transform="translate(100,50)">
      <polygon points="0,0 10,0 10,10 0,10" transform="scale(2)"/></g><polygon points="0,0 1,0 1,1"/></svg>)svg");
  ASSERT_EQ(seeds.outlines.size(), 2u);
  const PlaneRing& moved = seeds.outlines[0].ring;
  EXPECT_EQ(moved[0], (PlanePoint{100.0, -50.0}));
  EXPECT_EQ(moved[2], (PlanePoint{120.0, -70.0}));
  EXPECT_EQ(seeds.outlines[1].ring[1], (PlanePoint{1.0, 0.0}));
  // A transform list applies right to left: scale first, then translate.
  const std::string listed = R"svg(<svg><polygon points="1,0 2,0 2,1" transform="translate(10) scale(3,2)"/></svg>)svg";
  EXPECT_EQ(svg_outlines(listed).outlines[0].ring[2], (PlanePoint{16.0, -2.0}));
  // matrix() is SVG's (a b c d e f); nested groups compose.
  const std::string nested = R"svg(<svg><g transform="matrix(1,0,0,1,5,5)"><g transform="scale(2)">
      <path d="M1,1 L2,1 L2,2 Z"/></g></g></svg>)svg";
  EXPECT_EQ(svg_outlines(nested).outlines[0].ring[0], (PlanePoint{7.0, -7.0}));
  // rotate(90 about (1, 1)) takes (2, 1) to (1, 2).
  const std::string rotated = R"svg(<svg><polygon points="2,1 3,1 3,2" transform="rotate(90 1 1)"/></svg>)svg";
  const PlanePoint turned = svg_outlines(rotated).outlines[0].ring[0];
  EXPECT_NEAR(turned.x, 1.0, 1e-12);
  EXPECT_NEAR(turned.y, -2.0, 1e-12);
  // The area of a drawn square is kept through rotation and skew.
  const std::string skewed = R"svg(<svg><g transform="rotate(30) skewX(20)"><polygon points="0,0 10,0 10,10 0,10"/></g></svg>)svg";
  EXPECT_NEAR(signed_area(parse_seed(skewed, SeedFormat::svg, "s").ring), 100.0, 1e-9);
}

TEST(SeedInput, BadSvgTransformsAreRefusedNamingThem) {
  expect_error(R"svg(<svg><g transform="perspective(3)"><polygon points="0,0 10,0 10,10"/></g></svg>)svg", SeedFormat::svg,
               "unknown SVG transform 'perspective'");
  expect_error(R"svg(<svg><polygon points="0,0 10,0 10,10" transform="rotate(10 3)"/></svg>)svg", SeedFormat::svg,
               "rotate() takes 1 or 3 numbers, not 2");
  expect_error(R"svg(<svg><polygon points="0,0 10,0 10,10" transform="matrix(1 0 0 1)"/></svg>)svg", SeedFormat::svg,
               "matrix() takes 6 numbers, not 4");
  expect_error(R"svg(<svg><polygon points="0,0 10,0 10,10" transform="translate(1"/></svg>)svg", SeedFormat::svg,
               "is not a list of name(numbers)");
  expect_error(R"svg(<svg><polygon points="0,0 10,0 10,10" transform="scale(x)"/></svg>)svg", SeedFormat::svg, "not a number");
  expect_error(R"svg(<svg><polygon points="0,0 10,0 10,10" transform="scale(1e300) scale(1e300)"/></svg>)svg", SeedFormat::svg,
               "moves a point past any number");
  std::string deep = "<svg>";
  for (int i = 0; i < 300; ++i) deep += "<g>";
  expect_error(deep + R"svg(<polygon points="0,0 10,0 10,10"/></svg>)svg", SeedFormat::svg, "nested deeper than 256 levels");
}

TEST(SeedInput, SmallSelfCrossingIsRepairedWithANote) {
  // A square whose bottom edge has a tiny outward twist.
  const auto seed = parse_seed("0,0\n40,0\n42,0\n42,-1\n41,-1\n41,0.5\n100,0.5\n100,100\n0,100\n", SeedFormat::csv, "s");
  ASSERT_EQ(seed.notes.size(), 1u);
  EXPECT_NE(seed.notes[0].find("repaired to its outline"), std::string::npos) << seed.notes[0];
  EXPECT_GT(signed_area(seed.ring), 9900.0);
}

TEST(SeedInput, EveryBadSeedIsRejectedWithItsValue) {
  expect_error("0,0\n10,10\n10,0\n0,10\n", SeedFormat::csv, "crosses itself at (5, 5) and splits");
  expect_error(R"({"type":"LineString","coordinates":[[0,0],[10,0],[10,10],[0,10]]})", SeedFormat::geojson,
               "the seed contour is open: its ends are 10 m apart");
  expect_error("0,0\n10,0\n", SeedFormat::csv, "has 2 distinct vertices: a contour needs at least 3");
  expect_error("0,0\n10,0\n0,0\n10,0\n", SeedFormat::csv, "distinct vertices");
  expect_error("0,0\n5,5\n10,10\n", SeedFormat::csv, "zero area");
  expect_error("0,0\nnan,0\n10,10\n", SeedFormat::csv, "vertex 1 is (nan, 0): coordinates must be finite");
  expect_error("0,0\n10,0\ninf,10\n", SeedFormat::csv, "vertex 2 is (inf, 10)");
  expect_error(R"({"type":"Point","coordinates":[0,0]})", SeedFormat::geojson, "no Polygon, MultiPolygon or LineString");
  // A "type" that is not a string (a fuzzed file: nlohmann's value() threw type_error, an internal error).
  expect_error(R"({"type":"FeatureCollection","features":[{"type":{"type":"Polygon"}}]})", SeedFormat::geojson,
               "no Polygon, MultiPolygon or LineString");
  expect_error("{not json", SeedFormat::geojson, "not valid JSON");
  expect_error(R"({"type":"Polygon","coordinates":[[[0,0],["a",1],[1,1]]]})", SeedFormat::geojson, "position 1 is");
}

TEST(SeedInput, HugeCoordinatesAreRefusedBeforeAnyWorkNamingTheVertexAndTheRange) {
  // The fuzzer's seeds: finite coordinates of 1e77..1e114 overflowed the clipping's integer
  // lattice and escaped as Clipper's exception (an internal error).
  expect_error("0,0\n100,0\n100,1e77\n0,100\n", SeedFormat::csv, "vertex 2 is (100, 1e+77): coordinates must lie within +-100000 km");
  expect_error(R"({"type":"Polygon","coordinates":[[[0,0],[1e114,0],[10,10],[0,0]]]})", SeedFormat::geojson, "vertex 1 is (1e+114, 0)");
  expect_error(R"(<svg><polygon points="0,0 100,0 100,-3e9 0,100"/></svg>)", SeedFormat::svg, "vertex 2 is (100, 3e+09)");
  expect_error(R"(<svg><polygon points="0,0 100,0 100,-200 0,100"/></svg>)", SeedFormat::svg, "vertex 2 is (1e+08, 2e+08)", 1e6);
  // UTM northings (up to 10,000 km) and the limit itself are fine.
  const auto seed = parse_seed("500000,9999000\n501000,9999000\n501000,1e8\n500000,1e8\n", SeedFormat::csv, "s");
  EXPECT_EQ(seed.ring.size(), 4u);
}

TEST(SeedInput, FormatFromExtension) {
  EXPECT_EQ(seed_format_for("a.GeoJSON"), SeedFormat::geojson);
  EXPECT_EQ(seed_format_for("a.json"), SeedFormat::geojson);
  EXPECT_EQ(seed_format_for("a.csv"), SeedFormat::csv);
  EXPECT_EQ(seed_format_for("a.svg"), SeedFormat::svg);
  EXPECT_FALSE(seed_format_for("a.shp"));
}

}  // namespace
}  // namespace sansui::contour
