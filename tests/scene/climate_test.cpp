// Climate, season and weather to look values (scene/climate.hpp, data/climate.toml): ranges over
// every combination, Table 4 exactly (TABLES-003.md), the choices docs/climate.md documents, and
// a strict loader that catches typos in the data file.
#include "scene/climate.hpp"

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "scene/look.hpp"
#include "scene/recipe.hpp"
#include "tests/test_paths.hpp"

namespace sansui::scene {
namespace {

constexpr std::array<Climate, 14> all_climates{Climate::Af, Climate::Am, Climate::Aw,  Climate::BW,  Climate::BS,
                                               Climate::Cs, Climate::Cw, Climate::Cfa, Climate::Cfb, Climate::Cfc,
                                               Climate::Df, Climate::Dw, Climate::ET,  Climate::EF};
constexpr std::array<Season, 4> all_seasons{Season::spring, Season::summer, Season::autumn, Season::winter};
constexpr std::array<Weather, 6> all_weathers{Weather::clear, Weather::cloudy, Weather::overcast,
                                              Weather::rain,  Weather::snow,   Weather::fog};

/// Table 4 as TABLES-003.md prints it: tree density, tree line, snow line per season (%).
struct Table4Row {
  double density, tree_line;
  std::array<double, 4> snow;  ///< spring, summer, autumn, winter; one value repeated where Table 4 gives one
};
const std::map<Climate, Table4Row> table4 = {
    {Climate::Af, {90, 80, {90, 90, 90, 90}}},  {Climate::Am, {80, 80, {90, 90, 90, 90}}},  {Climate::Aw, {15, 60, {75, 75, 75, 75}}},
    {Climate::BW, {3, 50, {90, 90, 90, 90}}},   {Climate::BS, {20, 50, {80, 80, 80, 80}}},  {Climate::Cs, {30, 50, {75, 75, 75, 75}}},
    {Climate::Cw, {40, 50, {75, 75, 75, 75}}},  {Climate::Cfa, {40, 50, {75, 75, 75, 75}}}, {Climate::Cfb, {40, 50, {75, 75, 75, 75}}},
    {Climate::Cfc, {40, 50, {75, 75, 75, 75}}}, {Climate::Df, {75, 60, {20, 60, 20, 0}}},   {Climate::Dw, {75, 60, {13, 60, 3, 0}}},
    {Climate::ET, {3, 40, {0, 3, 0, 0}}},       {Climate::EF, {0, 0, {0, 0, 0, 0}}},
};

bool has_seasonal_snow_line(Climate climate) {
  return climate == Climate::Df || climate == Climate::Dw || climate == Climate::ET;
}

std::size_t season_index(Season season) {
  return static_cast<std::size_t>(season);
}

std::vector<const Derived<look::Rgb>*> colours_of(const Look& look) {
  return {&look.beach, &look.forest_low, &look.forest_high,   &look.cliff,     &look.snow,
          &look.earth, &look.seabed,     &look.water_shallow, &look.water_deep};
}

std::string describe(Climate climate, Season season, Weather weather) {
  return std::string(name_of(climate)) + " " + std::string(name_of(season)) + " " + std::string(name_of(weather));
}

/// `text` with the first `from` replaced by `to` (the test fails if `from` is absent).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The message check_climate_table throws for `text`, or "" if it accepts it.
std::string table_error(const std::string& text) {
  try {
    check_climate_table(text);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(Climate, EveryCombinationStaysInItsRanges) {
  for (Climate climate : all_climates)
    for (Season season : all_seasons)
      for (Weather weather : all_weathers) {
        SCOPED_TRACE(describe(climate, season, weather));
        const Look look = derive_look(climate, season, weather);
        for (const auto* colour : colours_of(look))
          for (float channel : {colour->value.r, colour->value.g, colour->value.b}) {
            EXPECT_GE(channel, 0.0f);
            EXPECT_LE(channel, 1.0f);
          }
        for (const auto* fraction : {&look.tree_line, &look.snow_line, &look.tree_density, &look.cloud_cover, &look.sun_strength}) {
          EXPECT_GE(fraction->value, 0.0);
          EXPECT_LE(fraction->value, 1.0);
        }
        EXPECT_GT(look.cloud_hurst.value, 0.0);
        EXPECT_LE(look.cloud_hurst.value, 1.0);
        EXPECT_GE(look.fog_density.value, 0.0);
        EXPECT_LE(look.fog_density.value, 10.0);  // the renderer's limit
        EXPECT_GE(look.turbidity.value, 2.0);
        EXPECT_LE(look.turbidity.value, 10.0);
      }
}

TEST(Climate, EveryDerivedValueNamesItsSource) {
  for (Climate climate : all_climates)
    for (Season season : all_seasons)
      for (Weather weather : all_weathers) {
        const auto values = explain(derive_look(climate, season, weather));
        ASSERT_EQ(values.size(), 20u);  // 9 colours and 11 numbers
        for (const auto& value : values) {
          EXPECT_FALSE(value.key.empty());
          EXPECT_FALSE(value.value.empty()) << value.key;
          EXPECT_FALSE(value.source.empty()) << describe(climate, season, weather) << " " << value.key;
        }
      }
}

TEST(Climate, TreeDensityAndTreeLineAreTable4s) {
  for (const auto& [climate, row] : table4)
    for (Season season : all_seasons)
      for (Weather weather : all_weathers) {
        const Look look = derive_look(climate, season, weather);
        EXPECT_EQ(look.tree_density.value, row.density / 100.0) << describe(climate, season, weather);
        EXPECT_EQ(look.tree_line.value, row.tree_line / 100.0) << describe(climate, season, weather);
      }
}

// Df, Dw and ET: Table 4's four seasons. The others: Table 4's one value in spring, summer and
// autumn (winter lowers it, see below).
TEST(Climate, SnowLineIsTable4sInClearWeather) {
  for (const auto& [climate, row] : table4)
    for (Season season : all_seasons) {
      if (season == Season::winter && !has_seasonal_snow_line(climate)) continue;
      const Look look = derive_look(climate, season, Weather::clear);
      EXPECT_EQ(look.snow_line.value, row.snow[season_index(season)] / 100.0) << describe(climate, season, Weather::clear);
      EXPECT_NE(look.snow_line.source.find("Table 4 (" + std::string(name_of(climate))), std::string::npos) << look.snow_line.source;
    }
}

// The paper: snow lines fall in winter, for every climate. Where Table 4 gives one value, winter
// lowers it by 0.15 of the maximum elevation (data/climate.toml), never below 0.
TEST(Climate, WinterLowersTheSnowLineOfOneValueClimates) {
  for (const auto& [climate, row] : table4) {
    if (has_seasonal_snow_line(climate)) continue;
    const double summer = derive_look(climate, Season::summer, Weather::clear).snow_line.value;
    const Look winter = derive_look(climate, Season::winter, Weather::clear);
    EXPECT_NEAR(winter.snow_line.value, std::max(0.0, summer - 0.15), 1e-12) << name_of(climate);
    EXPECT_NE(winter.snow_line.source.find("season winter: snow line -0.15"), std::string::npos) << winter.snow_line.source;
  }
}

TEST(Climate, SnowfallLowersTheSnowLine) {
  for (Climate climate : all_climates)
    for (Season season : all_seasons) {
      const Look clear = derive_look(climate, season, Weather::clear);
      const Look snowing = derive_look(climate, season, Weather::snow);
      SCOPED_TRACE(describe(climate, season, Weather::snow));
      if (clear.snow_line.value > 0.0)
        EXPECT_LT(snowing.snow_line.value, clear.snow_line.value);
      else
        EXPECT_EQ(snowing.snow_line.value, 0.0);
      EXPECT_NE(snowing.snow_line.source.find("weather snow: snow line"), std::string::npos) << snowing.snow_line.source;
    }
}

TEST(Climate, IceCapIsAllSnowWithoutVegetation) {
  for (Season season : all_seasons)
    for (Weather weather : all_weathers) {
      const Look look = derive_look(Climate::EF, season, weather);
      EXPECT_EQ(look.snow_line.value, 0.0);
      EXPECT_EQ(look.tree_line.value, 0.0);
      EXPECT_EQ(look.tree_density.value, 0.0);
      // "Forest" colours are ice: pale and bluish, never green.
      for (const auto* colour : {&look.forest_low, &look.forest_high}) {
        EXPECT_GE(std::min({colour->value.r, colour->value.g, colour->value.b}), 0.8f) << describe(Climate::EF, season, weather);
        EXPECT_GE(colour->value.b, colour->value.g);
        EXPECT_GE(colour->value.g, colour->value.r);
      }
    }
}

// BW: Table 4's 3 % trees, and the forest band drawn as sand and gravel: warm (red >= green >=
// blue), bright, and close to the desert's beach sand.
TEST(Climate, DesertHasFewTreesAndSandColouredForest) {
  const Look look = derive_look(Climate::BW, Season::summer, Weather::clear);
  EXPECT_EQ(look.tree_density.value, 0.03);
  for (const auto* colour : {&look.forest_low, &look.forest_high}) {
    const look::Rgb c = colour->value;
    EXPECT_GE(c.r, c.g);
    EXPECT_GE(c.g, c.b);
    EXPECT_GT(c.r, 0.6f);
    const look::Rgb sand = look.beach.value;
    EXPECT_LT(std::abs(c.r - sand.r) + std::abs(c.g - sand.g) + std::abs(c.b - sand.b), 0.45f);
  }
}

// Autumn colours only where the climate has deciduous forest: Cfa, Cfb, Cfc, Df, Dw.
TEST(Climate, AutumnTurnsDeciduousForestsOnly) {
  const std::array<Climate, 5> deciduous{Climate::Cfa, Climate::Cfb, Climate::Cfc, Climate::Df, Climate::Dw};
  for (Climate climate : all_climates) {
    const Look summer = derive_look(climate, Season::summer, Weather::clear);
    const Look autumn = derive_look(climate, Season::autumn, Weather::clear);
    const bool turns = std::find(deciduous.begin(), deciduous.end(), climate) != deciduous.end();
    EXPECT_EQ(autumn.forest_low.value != summer.forest_low.value, turns) << name_of(climate);
    EXPECT_EQ(autumn.forest_high.value != summer.forest_high.value, turns) << name_of(climate);
    EXPECT_EQ(autumn.beach.value, summer.beach.value) << name_of(climate);
  }
  const Look summer = derive_look(Climate::Cfb, Season::summer, Weather::clear);
  const Look autumn = derive_look(Climate::Cfb, Season::autumn, Weather::clear);
  EXPECT_GT(autumn.forest_low.value.r, summer.forest_low.value.r + 0.2f);  // toward orange
  EXPECT_NE(autumn.forest_low.source.find("season autumn: deciduous colours"), std::string::npos) << autumn.forest_low.source;
  for (Season season : all_seasons) {
    const Look af = derive_look(Climate::Af, season, Weather::clear);
    EXPECT_EQ(af.forest_low.value, derive_look(Climate::Af, Season::summer, Weather::clear).forest_low.value);
  }
}

TEST(Climate, WinterBrownsTheLowGroundOfTemperateAndBorealClimates) {
  for (Climate climate : {Climate::Cw, Climate::Cfa, Climate::Cfb, Climate::Cfc, Climate::Df, Climate::Dw}) {
    const Look summer = derive_look(climate, Season::summer, Weather::clear);
    const Look winter = derive_look(climate, Season::winter, Weather::clear);
    EXPECT_NE(winter.beach.value, summer.beach.value) << name_of(climate);
    EXPECT_NE(winter.beach.source.find("season winter: dormant low ground"), std::string::npos) << winter.beach.source;
  }
  for (Climate climate : {Climate::Af, Climate::BW, Climate::Cs, Climate::EF})
    EXPECT_EQ(derive_look(climate, Season::winter, Weather::clear).beach.value,
              derive_look(climate, Season::summer, Weather::clear).beach.value)
        << name_of(climate);
}

TEST(Climate, WeatherSetsSkyValues) {
  const Look clear = derive_look(Climate::Cfb, Season::summer, Weather::clear);
  const Look overcast = derive_look(Climate::Cfb, Season::summer, Weather::overcast);
  const Look fog = derive_look(Climate::Cfb, Season::summer, Weather::fog);
  EXPECT_LT(overcast.sun_strength.value, clear.sun_strength.value);
  EXPECT_GT(overcast.cloud_cover.value, clear.cloud_cover.value);
  EXPECT_GE(clear.fog_density.value, 0.1);
  EXPECT_LE(clear.fog_density.value, 0.2);
  EXPECT_GE(fog.fog_density.value, 2.5);
  EXPECT_GT(fog.turbidity.value, clear.turbidity.value);
  EXPECT_EQ(clear.fog_density.source, "weather clear");
}

TEST(Climate, SourcesSayWhereValuesCameFrom) {
  const Look look = derive_look(Climate::Cfb, Season::summer, Weather::clear);
  EXPECT_EQ(look.tree_line.source, "Table 4 (Cfb): 50 %");
  EXPECT_EQ(look.snow_line.source, "Table 4 (Cfb): 75 %");
  EXPECT_EQ(look.tree_density.source, "Table 4 (Cfb): 40 %");
  EXPECT_EQ(look.forest_low.source, "climate table: Cfb palette");
  EXPECT_EQ(look.turbidity.source, "climate table: Cfb haze 3");
  const Look df = derive_look(Climate::Df, Season::winter, Weather::snow);
  EXPECT_EQ(df.snow_line.source, "Table 4 (Df, winter): 0 %; weather snow: snow line -0.25 (stopped at 0)");
}

TEST(Climate, ExplainNamesTheSceneKeys) {
  const auto values = explain(derive_look(Climate::Cfb, Season::summer, Weather::clear));
  std::map<std::string, std::string> sources;
  for (const auto& value : values) sources[value.key] = value.source;
  EXPECT_EQ(sources.size(), values.size());  // no key twice
  EXPECT_EQ(sources.at("land.tree_line"), "Table 4 (Cfb): 50 %");
  EXPECT_EQ(sources.at("vegetation.density"), "Table 4 (Cfb): 40 %");
  EXPECT_EQ(sources.at("sea.shallow"), "climate table: Cfb palette");
  EXPECT_EQ(sources.at("sky.cloud_fineness"), "weather clear");
  EXPECT_EQ(sources.at("atmosphere.fog"), "weather clear");
  EXPECT_EQ(values.front().key, "land.beach");
  EXPECT_EQ(values.front().value, "0.720,0.660,0.520");
}

// Issue 49: a wet climate's plant cover holds on steep slopes, a dry or cold one's does not. The
// picture's soil blends in over 8 degrees from the cover slope, and the patch noise moves a
// slope by up to 7: a 45-degree face stays green where the cover slope is 52 or more, and a
// 30-degree one is bare where it is 22 or less (render/shaders.cpp, ground_albedo).
TEST(Climate, WetClimatesHoldPlantsOnSteepSlopesAndDryAndColdOnesAreBare) {
  for (Climate climate : {Climate::Af, Climate::Cfb, Climate::Df})
    EXPECT_GE(derive_look(climate, Season::summer, Weather::clear).cover_slope.value, 52.0) << name_of(climate);
  for (Climate climate : {Climate::BW, Climate::ET})
    EXPECT_LE(derive_look(climate, Season::summer, Weather::clear).cover_slope.value + 8.0, 30.0 + 4.0) << name_of(climate);
  // A recipe takes its climate's unless it sets its own, and --explain says which.
  Recipe recipe;
  recipe.climate.koppen = Climate::Af;
  Recipe own = recipe;
  own.render.land.cover_slope_deg = 40.0;
  std::map<std::string, std::string> sources;
  for (const auto& line : resolve_look(recipe)) sources[line.key] = line.source;
  resolve_look(own);
  EXPECT_EQ(recipe.render.land.cover_slope_deg, 62.0);
  EXPECT_EQ(sources.at("land.cover_slope"), "climate table: Af cover slope");
  EXPECT_EQ(own.render.land.cover_slope_deg, 40.0);
  // Without a climate the picture keeps the old rule: soil from 4 degrees below the cliff slope.
  EXPECT_EQ(look::with_fallbacks(look::RenderParams{}).land.cover_slope_deg, look::Land{}.cliff_slope_deg - 4.0);
}

TEST(Climate, DerivationIsDeterministic) {
  for (Climate climate : all_climates) {
    const auto first = explain(derive_look(climate, Season::autumn, Weather::rain));
    const auto second = explain(derive_look(climate, Season::autumn, Weather::rain));
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].value, second[i].value);
      EXPECT_EQ(first[i].source, second[i].source);
    }
  }
}

TEST(Climate, NamesRoundTrip) {
  for (const auto& [name, climate] : climate_choices()) {
    EXPECT_EQ(climate_from_name(name), climate);
    EXPECT_EQ(name_of(climate), name);
    EXPECT_FALSE(climate_title(climate).empty());
  }
  for (const auto& [name, season] : season_choices()) {
    EXPECT_EQ(season_from_name(name), season);
    EXPECT_EQ(name_of(season), name);
  }
  for (const auto& [name, weather] : weather_choices()) {
    EXPECT_EQ(weather_from_name(name), weather);
    EXPECT_EQ(name_of(weather), name);
  }
  EXPECT_EQ(climate_choices().size(), 14u);
  EXPECT_EQ(season_choices().size(), 4u);
  EXPECT_EQ(weather_choices().size(), 6u);
  EXPECT_EQ(climate_from_name("cfb"), std::nullopt);
  EXPECT_EQ(climate_from_name(""), std::nullopt);
  EXPECT_EQ(season_from_name("Winter"), std::nullopt);
  EXPECT_EQ(weather_from_name("sunny"), std::nullopt);
}

// The library carries the file's text; a stale copy means CMake did not re-run after an edit.
TEST(Climate, EmbeddedTableIsTheDataFile) {
  std::ifstream in(std::filesystem::path(sansui::test::source_dir) / "data" / "climate.toml", std::ios::binary);
  ASSERT_TRUE(in) << "data/climate.toml";
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(climate_table_text(), text.str());
  EXPECT_EQ(table_error(text.str()), "");
}

TEST(Climate, TableTyposAreCaughtWithTheirLine) {
  const std::string good(climate_table_text());
  const std::vector<std::pair<std::string, std::string>> typos = {
      {"forest_high = [0.13, 0.24, 0.11]", "forest_hihg = [0.13, 0.24, 0.11]"},  // misspelt key
      {"[climate.Cfb]", "[climate.Cbf]"},                                        // misspelt climate
      {"climates = [\"Cfa\", \"Cfb\"", "climates = [\"Cfa\", \"cfb\""},          // misspelt name in a list
      {"haze = 3.0", "haze = 30"},                                               // out of range
      {"beach = [0.72, 0.66, 0.52]", "beach = [0.72, 0.66]"},                    // a colour of two
      {"beach = [0.72, 0.66, 0.52]", "beach = [0.72, 0.66, 1.52]"},              // channel out of range
      {"snow_line_pct = [20, 60, 20, 0]", "snow_line_pct = [20, 60, 20]"},       // three seasons
      {"tree_line_pct = 50\n", ""},                                              // missing key
      {"[weather.fog]", "[weather.mist]"},                                       // unknown weather
      {"colours = [\"beach\"]", "colours = [\"sand\"]"},                         // unknown palette key
      {"by_deciduous = true", "by_deciduous = \"yes\""},                         // not a flag
      {"climates = [\"Cw\", \"Cfa\"", "climates = [\"Cw\", \"Cs\", \"Cfa\""},    // ok: no deciduous scaling
      {"climates = [\"Cfa\", \"Cfb\"", "climates = [\"Af\", \"Cfa\", \"Cfb\""},  // by_deciduous on Af (share 0)
      {"schema = 1", "schema = 2"},
      {"cloud_cover = 0.1", "cloud_cover = 0.1\ncloud_covre = 0.2"},  // an extra, unknown key
  };
  for (const auto& [from, to] : typos) {
    const std::string message = table_error(replaced(good, from, to));
    if (to.find("\"Cs\"") != std::string::npos) {
      EXPECT_EQ(message, "") << to;  // a plain tint may list any climate
      continue;
    }
    EXPECT_NE(message, "") << to;
    EXPECT_EQ(message.rfind("data/climate.toml:", 0), 0u) << message;
  }
  EXPECT_NE(table_error("schema = [").find("not valid TOML"), std::string::npos);
  EXPECT_NE(table_error(replaced(good, "haze = 3.0", "haze = 30")).find("haze"), std::string::npos);
}

}  // namespace
}  // namespace sansui::scene

namespace sansui::scene {
namespace {

// Tree and snow lines in metres (land.lines = "climate"): from the latitude, then the climate,
// season and weather.
TEST(ClimateLines, SnowAndTreeLinesInMetresFollowLatitudeClimateAndSeason) {
  for (Climate climate : all_climates)
    for (Season season : all_seasons)
      for (Weather weather : all_weathers)
        for (double latitude : {0.0, 5.0, 23.0, 46.0, -46.0, 62.0, 78.0, 90.0}) {
          const Look look = derive_look(climate, season, weather, latitude);
          EXPECT_GE(look.snow_line_m.value, 0.0);
          EXPECT_LE(look.snow_line_m.value, 6500.0);
          EXPECT_GE(look.tree_line_m.value, 0.0);
          EXPECT_LE(look.tree_line_m.value, 4500.0);
          EXPECT_EQ(look.snow_line_m.value, derive_look(climate, season, weather, -latitude).snow_line_m.value);
        }
  // The main job's tropical island (Af, 5 deg N, a 744 m summit) has no snow and forest to its top.
  const Look tropical = derive_look(Climate::Af, Season::summer, Weather::clear, 5.0);
  EXPECT_GT(tropical.snow_line_m.value, 4500.0);
  EXPECT_GT(tropical.tree_line_m.value, 3500.0);
  // The ice cap has snow down to the sea.
  for (Season season : all_seasons) EXPECT_EQ(derive_look(Climate::EF, season, Weather::clear, 46.0).snow_line_m.value, 0.0);
  // An alpine summit of 3,000 m at 46 deg N holds snow in summer; a 100 m hill does not.
  const Look alps = derive_look(Climate::Df, Season::summer, Weather::clear, 46.0);
  EXPECT_LT(alps.snow_line_m.value, 3000.0);
  EXPECT_GT(alps.snow_line_m.value, 2500.0);
  EXPECT_LT(alps.tree_line_m.value, alps.snow_line_m.value);
  // Winter brings the boreal snow down to the coast; snowfall lowers the line.
  EXPECT_EQ(derive_look(Climate::Df, Season::winter, Weather::clear, 62.0).snow_line_m.value, 0.0);
  EXPECT_LT(derive_look(Climate::Cfb, Season::summer, Weather::snow, 46.0).snow_line_m.value,
            derive_look(Climate::Cfb, Season::summer, Weather::clear, 46.0).snow_line_m.value);
  // Higher latitudes, lower lines.
  EXPECT_GT(derive_look(Climate::Cfb, Season::summer, Weather::clear, 40.0).snow_line_m.value,
            derive_look(Climate::Cfb, Season::summer, Weather::clear, 60.0).snow_line_m.value);
}

TEST(ClimateLines, TheSeasonFollowsTheDateAndFlipsSouthOfTheEquator) {
  TimeParams time;
  time.date = "2026-07-15";
  time.latitude_deg = 45.0;
  EXPECT_EQ(season_of_date(time), Season::summer);
  time.latitude_deg = -45.0;
  EXPECT_EQ(season_of_date(time), Season::winter);
  time.date = "2026-04-02";
  EXPECT_EQ(season_of_date(time), Season::autumn);
  time.latitude_deg = 10.0;
  EXPECT_EQ(season_of_date(time), Season::spring);
  // A set season wins, with a warning when the date says otherwise.
  Recipe recipe;
  recipe.time.date = "2026-07-15";
  recipe.time.latitude_deg = 45.0;
  EXPECT_EQ(season_of(recipe), Season::summer);
  EXPECT_EQ(season_contradiction(recipe), "");
  recipe.season.season = Season::winter;
  EXPECT_EQ(season_of(recipe), Season::winter);
  EXPECT_NE(season_contradiction(recipe).find("season.season winter contradicts time.date 2026-07-15 at 45 deg N, which is summer"),
            std::string::npos)
      << season_contradiction(recipe);
  // Recipes before version 4 keep summer.
  EXPECT_EQ(default_recipe(SourceKind::midpoint, 3).season.season, Season::summer);
  EXPECT_FALSE(default_recipe(SourceKind::midpoint).season.season.has_value());
}

}  // namespace
}  // namespace sansui::scene
