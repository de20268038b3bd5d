#include "scene/look.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/params.hpp"
#include "core/params_text.hpp"
#include "look/sky_dome.hpp"
#include "terrain/midpoint.hpp"
#include "vegetation/species.hpp"

namespace sansui::scene {
namespace {

/// Whole numbers separated by `separator`, each exactly `digits` long (0: any length).
bool split_numbers(std::string_view text, char separator, std::initializer_list<int> digits, std::vector<int>& out) {
  out.clear();
  std::size_t start = 0;
  for (int width : digits) {
    const std::size_t end = std::min(text.find(separator, start), text.size());
    const std::string_view part = text.substr(start, end - start);
    int value = 0;
    const auto [stop, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || error != std::errc() || stop != part.data() + part.size() || (width > 0 && static_cast<int>(part.size()) != width))
      return false;
    out.push_back(value);
    start = end + 1;
    if (end == text.size()) break;
  }
  return start > text.size() && out.size() >= 2;
}

int days_in(int year, int month) {
  static constexpr int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : days[month - 1];
}

std::string text_of(const look::Rgb& c) {
  return fmt::format("{},{},{}", params::format_number(params::float_as_written(c.r)), params::format_number(params::float_as_written(c.g)),
                     params::format_number(params::float_as_written(c.b)));
}
std::string text_of(double v) {
  return params::format_number(v);
}

/// Sets `value` from `derived` unless the recipe set it; says which.
template <class T, class D>
void settle(std::vector<ExplainedValue>& lines, std::string key, std::optional<T>& value, const Derived<D>& derived) {
  if (value) {
    lines.push_back({std::move(key), text_of(*value), "set in the recipe"});
    return;
  }
  value = static_cast<T>(derived.value);
  lines.push_back({std::move(key), text_of(*value), derived.source});
}

}  // namespace

std::string date_problem(std::string_view text) {
  std::vector<int> n;
  if (!split_numbers(text, '-', {4, 2, 2}, n) || n.size() != 3) return "a date YYYY-MM-DD";
  if (n[0] < 1583 || n[0] > 3000) return "a date YYYY-MM-DD with the year 1583..3000";
  if (n[1] < 1 || n[1] > 12) return "a date YYYY-MM-DD with the month 01..12";
  if (n[2] < 1 || n[2] > days_in(n[0], n[1]))
    return fmt::format("a date YYYY-MM-DD with the day 01..{} in that month", days_in(n[0], n[1]));
  return "";
}

std::string time_problem(std::string_view text) {
  std::vector<int> n;
  if (!split_numbers(text, ':', {2, 2, 2}, n)) return "a time HH:MM or HH:MM:SS";
  if (n[0] > 23 || n[1] > 59 || (n.size() > 2 && n[2] > 59)) return "a time HH:MM or HH:MM:SS, 00:00 to 23:59:59";
  return "";
}

look::SolarTime solar_time_of(const TimeParams& time) {
  if (const auto problem = date_problem(time.date); !problem.empty())
    fail("time.date '{}' is not allowed: it must be {}", time.date, problem);
  if (const auto problem = time_problem(time.time); !problem.empty())
    fail("time.time '{}' is not allowed: it must be {}", time.time, problem);
  std::vector<int> d, t;
  split_numbers(time.date, '-', {4, 2, 2}, d);
  split_numbers(time.time, ':', {2, 2, 2}, t);
  look::SolarTime when;
  when.year = d[0], when.month = d[1], when.day = d[2];
  when.hour = t[0], when.minute = t[1], when.second = t.size() > 2 ? t[2] : 0;
  when.utc_offset_hours = time.utc_offset_h;
  return when;
}

Season season_of_date(const TimeParams& time) {
  const look::SolarTime when = solar_time_of(time);
  // December-February, March-May, June-August, September-November; flipped south of the equator.
  static constexpr std::array<Season, 12> northern{Season::winter, Season::winter, Season::spring, Season::spring,
                                                   Season::spring, Season::summer, Season::summer, Season::summer,
                                                   Season::autumn, Season::autumn, Season::autumn, Season::winter};
  const Season season = northern[static_cast<std::size_t>(when.month - 1)];
  if (time.latitude_deg >= 0.0) return season;
  static constexpr std::array<Season, 4> opposite{Season::autumn, Season::winter, Season::spring, Season::summer};
  return opposite[static_cast<std::size_t>(season)];
}

Season season_of(const Recipe& recipe) {
  return recipe.season.season ? *recipe.season.season : season_of_date(recipe.time);
}

namespace {

std::string place_of(const TimeParams& time) {
  return fmt::format("{} at {:g} deg {}", time.date, std::abs(time.latitude_deg), time.latitude_deg >= 0.0 ? "N" : "S");
}

}  // namespace

std::string season_contradiction(const Recipe& recipe) {
  if (!recipe.season.season) return "";
  const Season dated = season_of_date(recipe.time);
  if (dated == *recipe.season.season) return "";
  return fmt::format("season.season {} contradicts time.date {}, which is {}; the picture shows {} (unset the season to follow the date)",
                     name_of(*recipe.season.season), place_of(recipe.time), name_of(dated), name_of(*recipe.season.season));
}

std::vector<ExplainedValue> resolve_look(Recipe& recipe) {
  std::vector<ExplainedValue> lines;
  look::RenderParams& r = recipe.render;
  const TimeParams& time = recipe.time;
  if (const std::string problem = look::mixed_lines_problem(r.land); !problem.empty()) fail("{}", problem);

  // The season: set, or the date's at the latitude.
  if (recipe.season.season) {
    const std::string contradiction = season_contradiction(recipe);
    lines.push_back({"season.season", std::string(name_of(*recipe.season.season)),
                     contradiction.empty() ? "set in the recipe" : "set in the recipe; warning: " + contradiction});
  } else {
    recipe.season.season = season_of_date(time);
    lines.push_back({"season.season", std::string(name_of(*recipe.season.season)), "the date's season: " + place_of(time)});
  }

  // The sun, and the clock for the ripples.
  const look::SolarTime when = solar_time_of(time);
  r.time_s = when.hour * 3600.0 + when.minute * 60.0 + when.second;
  if (time.sun_deg) {
    r.sun_azimuth_deg = (*time.sun_deg)[0], r.sun_elevation_deg = (*time.sun_deg)[1];
    lines.push_back({"time.sun", fmt::format("{},{}", text_of(*r.sun_azimuth_deg), text_of(*r.sun_elevation_deg)), "set in the recipe"});
  } else {
    const look::SunPosition sun = look::solar_position(when, time.latitude_deg, time.longitude_deg);
    r.sun_azimuth_deg = sun.azimuth_deg, r.sun_elevation_deg = sun.elevation_deg;
    lines.push_back({"time.sun", fmt::format("{:.2f},{:.2f}", sun.azimuth_deg, sun.elevation_deg),
                     fmt::format("NOAA solar position: {} {} (UTC{:+g} h) at {:.4g}, {:.4g}", time.date, time.time, time.utc_offset_h,
                                 time.latitude_deg, time.longitude_deg)});
  }

  // Everything the climate, season and weather decide.
  const Look look = derive_look(recipe.climate.koppen, *recipe.season.season, recipe.weather.weather, time.latitude_deg);
  if (r.land.lines == look::LandLines::climate) {
    settle(lines, "land.tree_line_m", r.land.tree_line_m, look.tree_line_m);
    settle(lines, "land.snow_line_m", r.land.snow_line_m, look.snow_line_m);
  } else {
    settle(lines, "land.tree_line", r.land.tree_line, look.tree_line);
    settle(lines, "land.snow_line", r.land.snow_line, look.snow_line);
  }
  const Derived<double> sunny{
      time.latitude_deg >= 0.0 ? 180.0 : 0.0,
      fmt::format("toward the equator from {:.4g} deg {}", std::abs(time.latitude_deg), time.latitude_deg >= 0.0 ? "N" : "S")};
  settle(lines, "land.sunny_side", r.land.sunny_azimuth_deg, sunny);
  settle(lines, "land.cover_slope", r.land.cover_slope_deg, look.cover_slope);
  settle(lines, "land.beach", r.land.beach, look.beach);
  settle(lines, "land.forest_low", r.land.forest_low, look.forest_low);
  settle(lines, "land.forest_high", r.land.forest_high, look.forest_high);
  settle(lines, "land.cliff", r.land.cliff, look.cliff);
  settle(lines, "land.snow", r.land.snow, look.snow);
  settle(lines, "land.earth", r.land.earth, look.earth);
  settle(lines, "sea.shallow", r.water.shallow, look.water_shallow);
  settle(lines, "sea.deep", r.water.deep, look.water_deep);
  settle(lines, "sea.seabed", r.water.seabed, look.seabed);
  settle(lines, "sky.turbidity", r.sky.turbidity, look.turbidity);
  settle(lines, "sky.sun_strength", r.sky.sun_strength, look.sun_strength);
  settle(lines, "sky.cloud_cover", r.sky.cloud_cover, look.cloud_cover);
  settle(lines, "sky.cloud_fineness", r.sky.cloud_fineness, look.cloud_hurst);
  settle(lines, "atmosphere.fog", r.atmosphere.fog, look.fog_density);
  const Derived<look::Rgb> sunlight{look::sun_colour(*r.sun_elevation_deg),
                                    fmt::format("Table 3: the sun's colour at {:.1f} degrees", *r.sun_elevation_deg)};
  settle(lines, "sky.sunlight", r.sky.sunlight, sunlight);
  settle(lines, "vegetation.density", recipe.vegetation.density, look.tree_density);
  const std::string_view koppen = name_of(recipe.climate.koppen);
  const Derived<double> ground{vegetation::ground_density_of_climate(koppen), fmt::format("data/species.toml: climate {}", koppen)};
  settle(lines, "vegetation.ground_density", recipe.vegetation.ground_density, ground);
  return lines;
}

std::string sky_key(const Recipe& looked) {
  const look::RenderParams resolved = look::with_fallbacks(looked.render);
  return fmt::format("sky {}|sun {},{}", params::text_of(resolved.sky), *resolved.sun_azimuth_deg, *resolved.sun_elevation_deg);
}

Grid<float> scene_clouds(const Recipe& looked, const Context& context) {
  // Samples per side of the cloud image: the cloud layer is seen from below, spread over the sky.
  constexpr int cloud_image_size = 513;
  const double cover = looked.render.sky.cloud_cover.value_or(0.0);
  if (cover <= 0.0) return {};
  const terrain::MidpointParams image{looked.render.sky.seed, looked.render.sky.cloud_fineness.value_or(0.6), 1.0, true};
  return look::cloud_density(terrain::generate_midpoint(image, cloud_image_size, context), cover);
}

}  // namespace sansui::scene
