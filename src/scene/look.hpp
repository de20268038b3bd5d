// A scene's look, resolved: every low-level value the recipe leaves unset (tree and snow lines,
// palette, sea colours, haze, sunlight, clouds, fog) is derived from the climate, season and
// weather (scene/climate.hpp), and the sun's position from the date, time and place (NOAA's
// formula, look/sky_model.hpp) — the paper's "information compression" (seeds/003, Sec. 4.2).
// Values the recipe sets are overrides and stay as they are. Every value is reported with
// where it came from, for `sansui run --explain`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/sky_model.hpp"
#include "scene/climate.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {

/// "" when `text` is a date YYYY-MM-DD that exists (1583..3000), else what is allowed.
std::string date_problem(std::string_view text);
/// "" when `text` is a clock time HH:MM or HH:MM:SS, else what is allowed.
std::string time_problem(std::string_view text);

/// The recipe's [time] as the solar position formula takes it. Throws InputError naming the key.
look::SolarTime solar_time_of(const TimeParams& time);

/// The meteorological season of time.date at time.latitude: March to May is spring in the north
/// and autumn in the south, and so on. Throws InputError for a bad date.
Season season_of_date(const TimeParams& time);

/// The recipe's season: season.season when set, else season_of_date().
Season season_of(const Recipe& recipe);

/// "" when the season is unset or agrees with the date and latitude; else a warning in one line
/// ("season.season winter contradicts time.date 2026-07-15 at 45 deg N, which is summer").
std::string season_contradiction(const Recipe& recipe);

/// Fills the unset look values of recipe.render (see above) and returns every value with its
/// key ("land.tree_line", "sky.turbidity", "time.sun", ...) and source; the season too, when it
/// is unset (from the date). Throws InputError for a bad date or time, and for tree or snow
/// lines of the kind land.lines does not read.
std::vector<ExplainedValue> resolve_look(Recipe& recipe);

/// The cloud layer of a resolved recipe: the paper's 2-D midpoint-displacement image (its
/// fineness the Hurst exponent) turned into density for its cloud cover; empty when the cover is 0.
Grid<float> scene_clouds(const Recipe& looked, const Context& context = quiet_context());

/// Everything scene_clouds() and the sky dome (look::bake_sky_dome of the resolved render
/// params) read from a resolved recipe, as text: the sky section and the sun's position.
std::string sky_key(const Recipe& looked);

}  // namespace sansui::scene
