// Properties every parameter table must have, checked over every params struct: each member has
// a row (so a new field cannot be forgotten), each default is allowed by its own row, each row
// has help and, where the value has one, a unit; keys and option names are unique. Plus the
// behaviour of the row machinery itself (parsing, checks, messages).
#include "core/params.hpp"

#include <regex>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bench/harness/solid_experiments.hpp"
#include "core/error.hpp"
#include "scene/recipe.hpp"
#include "tests/test_util.hpp"
#include "vegetation/species.hpp"

namespace sansui {
namespace {

using test::message_of;

using ::testing::HasSubstr;

template <class S>
class ParamTable : public ::testing::Test {};

using Structs =
    ::testing::Types<terrain::MidpointParams, terrain::StageFilterParams, contour::GenerationParams, contour::LoopRemovalParams,
                     contour::DemParams, contour::MapStyle, contour::CompareParams, solid::FieldParams, solid::RockParams,
                     mesh::SubdivideParams, mesh::SketchParams, look::Camera, look::Land, look::Sea, look::Sky, look::Atmosphere,
                     look::RenderParams, scene::WorldParams, scene::FileSourceParams, scene::ContourSeedParams, scene::DemGridParams,
                     scene::MeshSourceParams, scene::HeightmapOutputParams, scene::SolidParams, scene::CompareSetup, scene::ShapeStep,
                     scene::Output, scene::ClimateParams, scene::SeasonParams, scene::WeatherParams, scene::TimeParams, scene::TreeParams,
                     vegetation::VegetationParams, vegetation::Species, bench::SolidBenchOptions>;
TYPED_TEST_SUITE(ParamTable, Structs);

TYPED_TEST(ParamTable, EveryMemberOfTheStructHasARow) {
  const auto& table = params::table_of<TypeParam>();
  EXPECT_EQ(params::covered_fields(table), params::field_count<TypeParam>())
      << "[" << table.section << "]: add a row for the new member to its parameter table";
}

TYPED_TEST(ParamTable, EveryDefaultIsAllowedByItsRow) {
  const auto& table = params::table_of<TypeParam>();
  const TypeParam defaults{};
  for (const auto& row : table.rows) EXPECT_EQ(params::check(row, row.get(defaults)), "") << table.section << "." << row.key;
  EXPECT_NO_THROW(params::validate(defaults));
}

TYPED_TEST(ParamTable, RowsHaveHelpUnitsAndUniqueNames) {
  const auto& table = params::table_of<TypeParam>();
  EXPECT_FALSE(table.title.empty());
  std::set<std::string> keys, flags;
  const std::regex key_form("[a-z][a-z0-9_]*(\\.[a-z][a-z0-9_]*)*");
  for (const auto& row : table.rows) {
    EXPECT_TRUE(keys.insert(row.key).second) << "duplicate key " << row.key;
    EXPECT_TRUE(std::regex_match(row.key, key_form)) << row.key;
    if (!row.exposed) continue;
    EXPECT_TRUE(flags.insert(row.flag).second) << "duplicate option --" << row.flag;
    EXPECT_FALSE(row.help.empty()) << table.section << "." << row.key << " has no help";
    EXPECT_EQ(row.help.find('\n'), std::string::npos) << row.key << ": help is one line";
    const bool number = row.kind == params::Kind::real || row.kind == params::Kind::reals;
    if (number) {
      EXPECT_TRUE(!row.unit.empty() || row.unitless) << table.section << "." << row.key << ": say its unit, or .no_unit()";
    }
    EXPECT_EQ(row.unset_means.find('\n'), std::string::npos);
  }
}

TYPED_TEST(ParamTable, EveryValueSurvivesTextAndBack) {
  const auto& table = params::table_of<TypeParam>();
  TypeParam object{};
  for (const auto& row : table.rows) {
    if (!row.exposed) continue;
    const params::Value value = row.get(object);
    if (std::holds_alternative<std::monostate>(value)) continue;
    const std::string text = params::format_value(value);
    if (text.empty()) continue;  // an empty file name has no text form on the command line
    const params::Value back = params::parse_text(row, text, row.key);
    EXPECT_EQ(back, value) << row.key << " = " << text;
  }
}

// ---- the row machinery ------------------------------------------------------------------------

struct Example {
  double length_m = 2.0;
  int count = 3;
  std::optional<double> maybe_m;
  std::uint64_t seed = 1;
  std::array<double, 2> pair{0.0, 1.0};
};

const params::Table<Example>& parameter_table(const Example*) {
  static const auto table = params::Table<Example>("example", "An example")
                                .add(params::field("length", &Example::length_m).above(0).units("m").doc("A length"))
                                .add(params::field("count", &Example::count).in(1, 10).doc("A count"))
                                .add(params::field("maybe", &Example::maybe_m).at_least(0).units("m").unset("none").doc("Maybe"))
                                .add(params::field("seed", &Example::seed).doc("A seed"))
                                .add(params::field("pair", &Example::pair).in(0, 1).no_unit().doc("A pair"));
  return table;
}

TEST(Params, FieldCountSeesEveryMember) {
  EXPECT_EQ(params::field_count<Example>(), 5u);
  EXPECT_EQ(params::covered_fields(parameter_table(static_cast<const Example*>(nullptr))), 5u);
}

TEST(Params, MessagesNameTheKeyTheValueAndWhatIsAllowed) {
  Example e;
  e.length_m = -1.0;
  EXPECT_EQ(message_of([&] { params::validate(e); }), "example.length -1 is not allowed: it must be > 0 m");
  e = {};
  e.count = 11;
  EXPECT_EQ(message_of([&] { params::validate(e); }), "example.count 11 is not allowed: it must be between 1 and 10");
  e = {};
  e.pair = {0.5, 2.0};
  EXPECT_EQ(message_of([&] { params::validate(e); }), "example.pair 0.5,2 is not allowed: it must be 2 numbers, each between 0 and 1");
  e = {};
  e.length_m = std::nan("");
  EXPECT_EQ(message_of([&] { params::validate(e); }), "example.length nan is not allowed: it must be > 0 m");
}

TEST(Params, CommandLineTextIsParsedOrRefusedByName) {
  const auto& table = parameter_table(static_cast<const Example*>(nullptr));
  EXPECT_EQ(params::parse_text(*table.find("length"), "2.5", "--length"), params::Value(2.5));
  EXPECT_EQ(params::parse_text(*table.find("pair"), "0.25, 0.5", "--pair"), params::Value(std::vector<double>{0.25, 0.5}));
  EXPECT_EQ(message_of([&] { params::parse_text(*table.find("length"), "abc", "--length"); }),
            "--length 'abc' is not allowed: it must be a number > 0 m");
  EXPECT_EQ(message_of([&] { params::parse_text(*table.find("count"), "2.5", "--count"); }),
            "--count '2.5' is not allowed: it must be a whole number between 1 and 10");
  // Seeds are whole numbers from 0: -1 does not wrap around to 2^64 - 1.
  const params::Value negative = params::parse_text(*table.find("seed"), "-1", "--seed");
  EXPECT_THAT(message_of([&] { params::require_allowed(*table.find("seed"), negative, "--seed"); }),
              HasSubstr("--seed -1 is not allowed: it must be a whole number between 0 and"));
  EXPECT_EQ(message_of([&] { params::parse_text(*table.find("seed"), "18446744073709551615", "--seed"); }),
            "--seed '18446744073709551615' is not allowed: it must be a whole number between 0 and 2^63 - 1");
}

TEST(Params, NumbersAreWrittenInTheFewestDigitsThatReadBack) {
  EXPECT_EQ(params::format_number(0.1), "0.1");
  EXPECT_EQ(params::format_number(400.0), "400");
  EXPECT_EQ(params::format_number(-0.0), "0");
  EXPECT_EQ(params::float_as_written(0.95f), 0.95);
  EXPECT_EQ(static_cast<float>(params::float_as_written(0.95f)), 0.95f);
  for (double v : {1.0 / 3.0, 2.0 / 7.0, 1e-300, 6.02214076e23})
    EXPECT_EQ(std::get<double>(
                  params::parse_text(*parameter_table(static_cast<const Example*>(nullptr)).find("maybe"), params::format_number(v), "x")),
              v);
}

}  // namespace
}  // namespace sansui
