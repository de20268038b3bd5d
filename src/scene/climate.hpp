// Climate, season and weather: the high-level parameters of seed 003 (Oka et al. 1997, Sec. 4.2,
// "information compression"; SPEC 3.2) turned into the low-level values a picture needs: the
// terrain palette, tree line, snow line, tree density, clouds, fog, sunlight and haze.
//
// The mapping is data, data/climate.toml, compiled into the library (src/scene/CMakeLists.txt
// embeds it at configure time) and parsed once on first use. Table 4 of the paper gives tree
// density, tree line and snow line per Köppen climate (TABLES-003.md); everything else is
// Sansui's choice, explained in docs/climate.md. Every derived value carries its source, so
// `--explain` can say where each number came from.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/season.hpp"
#include "look/render_params.hpp"

namespace sansui::scene {

/// The 14 Köppen climates of Table 4 (Table 4 groups Cw with Cfa, Cfb and Cfc).
enum class Climate { Af, Am, Aw, BW, BS, Cs, Cw, Cfa, Cfb, Cfc, Df, Dw, ET, EF };
using sansui::Season;
enum class Weather { clear, cloudy, overcast, rain, snow, fog };

/// Köppen symbol: "Af", "Cfb", ... (case as Köppen writes it).
std::string_view name_of(Climate climate);
/// "spring", "summer", "autumn", "winter".
std::string_view name_of(Season season);
/// "clear", "cloudy", "overcast", "rain", "snow", "fog".
std::string_view name_of(Weather weather);

/// The value named `name` (exact spelling as name_of gives it); nullopt for anything else.
std::optional<Climate> climate_from_name(std::string_view name);
std::optional<Season> season_from_name(std::string_view name);
std::optional<Weather> weather_from_name(std::string_view name);

/// Every value with its name, in declaration order (for params::choice and help texts).
const std::vector<std::pair<std::string, Climate>>& climate_choices();
const std::vector<std::pair<std::string, Season>>& season_choices();
const std::vector<std::pair<std::string, Weather>>& weather_choices();

/// A climate's name in words, from the table: "marine west coast" for Cfb.
std::string climate_title(Climate climate);

/// A derived value and where it came from, e.g. {0.75, "Table 4 (Cfb): 75 %"} or a colour with
/// "climate table: Cfb palette; season autumn: deciduous colours (x0.65)". `source` is never
/// empty; steps are joined by "; " in the order they were applied.
template <class T>
struct Derived {
  T value{};
  std::string source;
};

/// The low-level look of a scene. Elevations are fractions of the terrain's maximum elevation
/// above sea level (Table 4's per cent / 100), as render::Bands takes them.
struct Look {
  // Palette, sRGB, each channel [Range: 0..1].
  Derived<look::Rgb> beach;        ///< low rock and sand just above the sea (the low ground)
  Derived<look::Rgb> forest_low;   ///< vegetation at the coast end of the forest band
  Derived<look::Rgb> forest_high;  ///< vegetation near the tree line
  Derived<look::Rgb> cliff;        ///< bare rock above the tree line and on steep slopes
  Derived<look::Rgb> snow;
  Derived<look::Rgb> earth;  ///< the cut sides of the terrain block
  Derived<look::Rgb> seabed;
  Derived<look::Rgb> water_shallow;
  Derived<look::Rgb> water_deep;
  /// Tree line: forest below, bare rock above. [Range: 0..1] (Table 4)
  Derived<double> tree_line;
  /// Snow line: snow above. [Range: 0..1] (Table 4, lowered in winter and by snowfall)
  Derived<double> snow_line;
  /// The tree line in metres above sea level at the latitude (land.lines = "climate").
  Derived<double> tree_line_m;
  /// The snow line in metres above sea level at the latitude, in the season and weather.
  Derived<double> snow_line_m;
  /// Pictures: slopes up to this hold a closed plant cover (look::Land::cover_slope_deg). [Units: degrees]
  Derived<double> cover_slope;
  /// Share of the forest band's ground covered by trees. [Range: 0..1] (Table 4)
  Derived<double> tree_density;
  /// Share of the sky covered by cloud. [Range: 0..1]
  Derived<double> cloud_cover;
  /// Hurst exponent H of the fractal cloud image (seed 003 Sec. 4.1.10: cloud "fineness" via the
  /// fractal dimension 3 - H; the scene key is sky.cloud_fineness): smaller is finer and more
  /// broken, larger smoother. [Range: 0.05..1]
  Derived<double> cloud_hurst;
  /// The renderer's distance fog: exp(-fog_density) of the light is kept over one terrain size.
  /// [Range: 0..10]
  Derived<double> fog_density;
  /// Share of direct sunlight reaching the ground (overcast skies dim it). [Range: 0..1]
  Derived<double> sun_strength;
  /// Atmospheric turbidity (haze) for the sky. [Range: 2..10]
  Derived<double> turbidity;
};

/// The look of `climate` in `season` under `weather` at `latitude_deg` (north positive; only the
/// metre lines depend on it). Pure and deterministic; the first call parses the embedded table (a
/// corrupt table throws std::logic_error: a programmer's error).
Look derive_look(Climate climate, Season season, Weather weather, double latitude_deg = 45.0);

/// One line of `--explain`: the scene-file key the value fills ("land.beach", "land.tree_line",
/// "sea.shallow", "sky.turbidity", "sky.cloud_fineness", "atmosphere.fog", "vegetation.density"),
/// the value as text, and its source.
struct ExplainedValue {
  std::string key;
  std::string value;
  std::string source;
};

/// Every value of `look` with its key and source, palette first, in Look's order.
std::vector<ExplainedValue> explain(const Look& look);

/// The text of data/climate.toml as compiled into the library.
std::string_view climate_table_text();

/// Parses and checks a climate table in data/climate.toml's form: throws std::logic_error naming
/// the line and key of the first problem (unknown or missing key, misspelt name, value out of
/// range). For tests and tools; derive_look checks the embedded table itself.
void check_climate_table(std::string_view toml_text);

}  // namespace sansui::scene
