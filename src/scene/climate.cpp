// Climate, season and weather to a look (seed 003, Oka et al. 1997, Sec. 4.2 "information
// compression"; SPEC 3.2). The numbers live in data/climate.toml, embedded at configure time
// (climate_table_text() is defined in the generated climate_embedded.cpp); this file reads that
// table strictly, once, and applies it: climate row (Table 4 and palette), then the season's
// snow-line drop and tints, then the weather's.
#include "scene/climate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

namespace sansui::scene {
namespace {

constexpr std::array<std::string_view, 14> climate_names{"Af",  "Am",  "Aw",  "BW", "BS", "Cs", "Cw",
                                                         "Cfa", "Cfb", "Cfc", "Df", "Dw", "ET", "EF"};
constexpr std::array<std::string_view, 4> season_names{"spring", "summer", "autumn", "winter"};
constexpr std::array<std::string_view, 6> weather_names{"clear", "cloudy", "overcast", "rain", "snow", "fog"};

/// The palette keys of the table, the scene-file keys they fill (for explain()), and Look's
/// members, in Look's order.
constexpr std::array<std::string_view, 9> colour_keys{"beach", "forest_low", "forest_high",   "cliff",     "snow",
                                                      "earth", "seabed",     "water_shallow", "water_deep"};
constexpr std::array<std::string_view, 9> colour_scene_keys{"land.beach", "land.forest_low", "land.forest_high", "land.cliff", "land.snow",
                                                            "land.earth", "sea.seabed",      "sea.shallow",      "sea.deep"};
constexpr std::array<Derived<look::Rgb> Look::*, 9> colour_members{&Look::beach,  &Look::forest_low,    &Look::forest_high,
                                                                   &Look::cliff,  &Look::snow,          &Look::earth,
                                                                   &Look::seabed, &Look::water_shallow, &Look::water_deep};
using Colours = std::array<look::Rgb, colour_keys.size()>;

constexpr std::string_view table_file = "data/climate.toml";

// ---- the table, as read ----------------------------------------------------------------------

struct ClimateRow {
  std::string title;
  double tree_density_pct = 0.0, tree_line_pct = 0.0;
  std::vector<double> snow_line_pct;  ///< one value, or spring, summer, autumn, winter
  double deciduous = 0.0;             ///< share of deciduous trees, 0..1
  double haze = 0.0;                  ///< turbidity, 2..10
  double cover_slope_deg = 0.0;       ///< pictures: plant cover up to this slope
  Colours palette{};
  // The lines in metres (land.lines = "climate").
  double snow_line_shift_m = 0.0;
  std::optional<double> winter_snow_line_m;  ///< unset: no seasonal snow below the climatic line
  std::optional<double> tree_line_max_m, snow_line_max_m;
};

/// The climatic snow and tree lines by latitude ([lines]).
struct LinesByLatitude {
  std::vector<double> latitude_deg, snow_line_m, tree_line_m;
};

/// Moves some palette colours of some climates part of the way toward one colour.
struct Tint {
  std::string what;
  std::array<bool, colour_keys.size()> colours{};
  look::Rgb toward;
  double amount = 0.0;
  std::array<bool, climate_names.size()> climates{};
  bool by_deciduous = false;
};

struct SeasonRow {
  double snow_line_drop = 0.0;
  double winter_share = 0.0;  ///< 0: the climatic snow line, 1: the climate's winter snow line
  std::vector<Tint> tints;
};

struct WeatherRow {
  double cloud_cover = 0.0, cloud_hurst = 0.0, fog_density = 0.0, sun_strength = 0.0, turbidity_change = 0.0, snow_line_drop = 0.0;
  double snow_line_drop_m = 0.0;
  std::vector<Tint> tints;
};

struct ClimateTable {
  std::array<ClimateRow, climate_names.size()> climates;
  std::array<SeasonRow, season_names.size()> seasons;
  std::array<WeatherRow, weather_names.size()> weathers;
  LinesByLatitude lines;
};

// ---- reading ---------------------------------------------------------------------------------

template <std::size_t N>
std::optional<std::size_t> index_of(const std::array<std::string_view, N>& names, std::string_view name) {
  const auto found = std::find(names.begin(), names.end(), name);
  return found == names.end() ? std::nullopt : std::optional<std::size_t>(static_cast<std::size_t>(found - names.begin()));
}

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

/// One TOML table being read. Keys other than `keys` are rejected up front, so a misspelt key in
/// the data is named as such (not reported as the correct key missing) and never silently unused.
class Section {
 public:
  Section(const toml::table& table, std::string context, const std::vector<std::string_view>& keys)
      : table_(table), context_(std::move(context)) {
    for (const auto& [key, node] : table_)
      if (std::find(keys.begin(), keys.end(), key.str()) == keys.end())
        fail(node, key.str(), fmt::format("unknown key; allowed: {}", fmt::join(keys, ", ")));
  }

  [[noreturn]] void fail(const toml::node& node, std::string_view key, std::string_view problem) const {
    const auto line = node.source().begin.line;
    throw std::logic_error(fmt::format("{}:{}: [{}] {}: {}", table_file, line, context_, key, problem));
  }

  const toml::node* find(std::string_view key) const { return table_.get(key); }

  const toml::node& get(std::string_view key) const {
    const toml::node* node = find(key);
    if (node == nullptr) fail(table_, key, "missing");
    return *node;
  }

  const toml::table& table(std::string_view key) const {
    const toml::node& node = get(key);
    if (!node.is_table()) fail(node, key, "must be a table");
    return *node.as_table();
  }

  double number(std::string_view key, double low, double high) const { return number_in(get(key), key, low, high); }

  double number_in(const toml::node& node, std::string_view key, double low, double high) const {
    const std::optional<double> value = node.is_boolean() ? std::nullopt : node.value<double>();
    if (!value || !std::isfinite(*value) || *value < low || *value > high)
      fail(node, key, fmt::format("must be a number in {}..{}", low, high));
    return *value;
  }

  std::string text(std::string_view key) const {
    const toml::node& node = get(key);
    if (!node.is_string() || node.as_string()->get().empty()) fail(node, key, "must be a non-empty string");
    return node.as_string()->get();
  }

  look::Rgb colour(std::string_view key) const {
    const toml::node& node = get(key);
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 3) fail(node, key, "must be [R, G, B], each 0..1 (sRGB)");
    const auto channel = [&](std::size_t i) { return static_cast<float>(number_in(*array->get(i), key, 0.0, 1.0)); };
    return {channel(0), channel(1), channel(2)};
  }

  bool flag(std::string_view key, bool fallback) const {
    const toml::node* node = find(key);
    if (node == nullptr) return fallback;
    if (!node->is_boolean()) fail(*node, key, "must be true or false");
    return node->as_boolean()->get();
  }

  /// A list of names from `names`, or the word "all".
  template <std::size_t N>
  std::array<bool, N> names_in(std::string_view key, const std::array<std::string_view, N>& names) const {
    const toml::node& node = get(key);
    std::array<bool, N> chosen{};
    if (node.is_string() && node.as_string()->get() == "all") {
      chosen.fill(true);
      return chosen;
    }
    const toml::array* array = node.as_array();
    if (array == nullptr || array->empty()) fail(node, key, fmt::format("must be \"all\" or a list of: {}", joined(names)));
    for (const toml::node& element : *array) {
      const std::optional<std::string_view> name = element.value<std::string_view>();
      const auto index = name ? index_of(names, *name) : std::nullopt;
      if (!index) fail(element, key, fmt::format("unknown name {}; allowed: {}", name ? *name : "(not a string)", joined(names)));
      chosen[*index] = true;
    }
    return chosen;
  }

  const std::string& context() const { return context_; }

  std::optional<double> optional_number(std::string_view key, double low, double high) const {
    const toml::node* node = find(key);
    if (node == nullptr) return std::nullopt;
    return number_in(*node, key, low, high);
  }

  /// A non-empty list of numbers, each in low..high.
  std::vector<double> numbers(std::string_view key, double low, double high) const {
    const toml::node& node = get(key);
    const toml::array* array = node.as_array();
    if (array == nullptr || array->empty()) fail(node, key, fmt::format("must be a list of numbers in {}..{}", low, high));
    std::vector<double> values;
    for (const toml::node& element : *array) values.push_back(number_in(element, key, low, high));
    return values;
  }

 private:
  const toml::table& table_;
  std::string context_;
};

/// The sub-tables of `section.key`, one per name, all present and no others.
template <std::size_t N>
std::array<const toml::table*, N> named_tables(const Section& section, std::string_view key, const std::array<std::string_view, N>& names) {
  const toml::table& parent = section.table(key);
  std::array<const toml::table*, N> tables{};
  for (const auto& [name, node] : parent) {
    const auto index = index_of(names, name.str());
    if (!index) section.fail(node, key, fmt::format("unknown name {}; allowed: {}", name.str(), joined(names)));
    if (!node.is_table()) section.fail(node, name.str(), "must be a table");
    tables[*index] = node.as_table();
  }
  for (std::size_t i = 0; i < N; ++i)
    if (tables[i] == nullptr) section.fail(parent, key, fmt::format("{} is missing", names[i]));
  return tables;
}

ClimateRow read_climate(const toml::table& table, std::string_view name) {
  std::vector<std::string_view> keys{"title", "cover_slope",       "tree_density_pct",   "tree_line_pct",   "snow_line_pct",  "deciduous",
                                     "haze",  "snow_line_shift_m", "winter_snow_line_m", "tree_line_max_m", "snow_line_max_m"};
  keys.insert(keys.end(), colour_keys.begin(), colour_keys.end());
  Section section(table, fmt::format("climate.{}", name), keys);
  ClimateRow row;
  row.title = section.text("title");
  row.tree_density_pct = section.number("tree_density_pct", 0, 100);
  row.tree_line_pct = section.number("tree_line_pct", 0, 100);
  const toml::node& snow = section.get("snow_line_pct");
  if (const toml::array* seasons = snow.as_array()) {
    if (seasons->size() != season_names.size())
      section.fail(snow, "snow_line_pct", "must be one number or four (spring, summer, autumn, winter)");
    for (const toml::node& value : *seasons) row.snow_line_pct.push_back(section.number_in(value, "snow_line_pct", 0, 100));
  } else {
    row.snow_line_pct.push_back(section.number_in(snow, "snow_line_pct", 0, 100));
  }
  row.deciduous = section.number("deciduous", 0, 1);
  row.haze = section.number("haze", 2, 10);
  row.cover_slope_deg = section.number("cover_slope", 0, 90);
  row.snow_line_shift_m = section.optional_number("snow_line_shift_m", -3000, 3000).value_or(0.0);
  row.winter_snow_line_m = section.optional_number("winter_snow_line_m", 0, 9000);
  row.tree_line_max_m = section.optional_number("tree_line_max_m", 0, 9000);
  row.snow_line_max_m = section.optional_number("snow_line_max_m", 0, 9000);
  for (std::size_t i = 0; i < colour_keys.size(); ++i) row.palette[i] = section.colour(colour_keys[i]);
  return row;
}

Tint read_tint(const toml::table& table, const std::string& context, const std::array<ClimateRow, climate_names.size()>& climates) {
  Section section(table, context + ".tint", {"what", "colours", "toward", "amount", "climates", "by_deciduous"});
  Tint tint;
  tint.what = section.text("what");
  tint.colours = section.names_in("colours", colour_keys);
  tint.toward = section.colour("toward");
  tint.amount = section.number("amount", 0, 1);
  tint.climates = section.names_in("climates", climate_names);
  tint.by_deciduous = section.flag("by_deciduous", false);
  // A deciduous tint listed for a climate without deciduous trees would silently do nothing.
  for (std::size_t i = 0; i < climate_names.size(); ++i)
    if (tint.by_deciduous && tint.climates[i] && climates[i].deciduous == 0.0)
      section.fail(table, "climates", fmt::format("{} has deciduous = 0, so by_deciduous tints cannot apply to it", climate_names[i]));
  return tint;
}

std::vector<Tint> read_tints(const Section& section, const std::array<ClimateRow, climate_names.size()>& climates) {
  std::vector<Tint> tints;
  const toml::node* node = section.find("tint");
  if (node == nullptr) return tints;
  const toml::array* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) section.fail(*node, "tint", "must be [[...tint]] tables");
  for (const toml::node& element : *array) tints.push_back(read_tint(*element.as_table(), section.context(), climates));
  return tints;
}

SeasonRow read_season(const toml::table& table, std::string_view name, const std::array<ClimateRow, climate_names.size()>& climates) {
  Section section(table, fmt::format("season.{}", name), {"snow_line_drop", "winter_share", "tint"});
  SeasonRow row;
  row.snow_line_drop = section.number("snow_line_drop", 0, 1);
  row.winter_share = section.number("winter_share", 0, 1);
  row.tints = read_tints(section, climates);
  return row;
}

WeatherRow read_weather(const toml::table& table, std::string_view name, const std::array<ClimateRow, climate_names.size()>& climates) {
  Section section(
      table, fmt::format("weather.{}", name),
      {"cloud_cover", "cloud_hurst", "fog_density", "sun_strength", "turbidity_change", "snow_line_drop", "snow_line_drop_m", "tint"});
  WeatherRow row;
  row.cloud_cover = section.number("cloud_cover", 0, 1);
  row.cloud_hurst = section.number("cloud_hurst", 0.05, 1);
  row.fog_density = section.number("fog_density", 0, 10);
  row.sun_strength = section.number("sun_strength", 0, 1);
  row.turbidity_change = section.number("turbidity_change", -8, 8);
  row.snow_line_drop = section.number("snow_line_drop", 0, 1);
  row.snow_line_drop_m = section.number("snow_line_drop_m", 0, 9000);
  row.tints = read_tints(section, climates);
  return row;
}

LinesByLatitude read_lines(const toml::table& table) {
  Section section(table, "lines", {"latitude_deg", "snow_line_m", "tree_line_m"});
  LinesByLatitude lines;
  lines.latitude_deg = section.numbers("latitude_deg", 0, 90);
  lines.snow_line_m = section.numbers("snow_line_m", 0, 9000);
  lines.tree_line_m = section.numbers("tree_line_m", 0, 9000);
  const auto& latitudes = lines.latitude_deg;
  if (latitudes.front() != 0.0 || latitudes.back() != 90.0 ||
      std::adjacent_find(latitudes.begin(), latitudes.end(), std::greater_equal<>()) != latitudes.end())
    section.fail(section.get("latitude_deg"), "latitude_deg", "must rise strictly from 0 to 90");
  if (lines.snow_line_m.size() != latitudes.size() || lines.tree_line_m.size() != latitudes.size())
    section.fail(table, "snow_line_m", "snow_line_m and tree_line_m must have one value per latitude_deg");
  return lines;
}

ClimateTable parse_table(std::string_view text) {
  toml::table root;
  try {
    root = toml::parse(text, table_file);
  } catch (const toml::parse_error& e) {
    throw std::logic_error(fmt::format("{}:{}: not valid TOML: {}", table_file, e.source().begin.line, e.description()));
  }
  Section top(root, "top level", {"schema", "climate", "lines", "season", "weather"});
  if (top.get("schema").value<std::int64_t>() != 1) top.fail(top.get("schema"), "schema", "must be 1 (the version this reader knows)");
  ClimateTable table;
  const auto climates = named_tables(top, "climate", climate_names);
  for (std::size_t i = 0; i < climate_names.size(); ++i) table.climates[i] = read_climate(*climates[i], climate_names[i]);
  const auto seasons = named_tables(top, "season", season_names);
  for (std::size_t i = 0; i < season_names.size(); ++i) table.seasons[i] = read_season(*seasons[i], season_names[i], table.climates);
  const auto weathers = named_tables(top, "weather", weather_names);
  for (std::size_t i = 0; i < weather_names.size(); ++i) table.weathers[i] = read_weather(*weathers[i], weather_names[i], table.climates);
  table.lines = read_lines(top.table("lines"));
  return table;
}

/// The embedded table, parsed on first use (the library's only static state).
const ClimateTable& climate_table() {
  static const ClimateTable table = parse_table(climate_table_text());
  return table;
}

// ---- deriving --------------------------------------------------------------------------------

template <class E>
std::size_t index(E value) {
  return static_cast<std::size_t>(value);
}

void add_step(std::string& source, std::string_view step) {
  source += fmt::format("; {}", step);
}

look::Rgb mix(const look::Rgb& from, const look::Rgb& to, double amount) {
  const auto t = static_cast<float>(amount);
  return {from.r + (to.r - from.r) * t, from.g + (to.g - from.g) * t, from.b + (to.b - from.b) * t};
}

/// Applies the tints of one season or weather (`label`, e.g. "season autumn") for `climate`.
void apply_tints(Look& look, const std::vector<Tint>& tints, const ClimateRow& row, Climate climate, std::string_view label) {
  for (const Tint& tint : tints) {
    if (!tint.climates[index(climate)]) continue;
    const double amount = tint.amount * (tint.by_deciduous ? row.deciduous : 1.0);
    if (amount <= 0.0) continue;
    for (std::size_t i = 0; i < colour_keys.size(); ++i) {
      if (!tint.colours[i]) continue;
      Derived<look::Rgb>& colour = look.*colour_members[i];
      colour.value = mix(colour.value, tint.toward, amount);
      add_step(colour.source, fmt::format("{}: {} (x{:.2f})", label, tint.what, amount));
    }
  }
}

Derived<double> percent(double pct, std::string_view what) {
  return {pct / 100.0, fmt::format("Table 4 ({}): {:g} %", what, pct)};
}

/// Lowers a snow line by `drop` (a fraction of the maximum elevation), never below 0.
void lower_snow_line(Derived<double>& snow_line, double drop, std::string_view label) {
  if (drop <= 0.0) return;
  const bool stopped = snow_line.value - drop < 0.0;
  snow_line.value = std::max(0.0, snow_line.value - drop);
  add_step(snow_line.source, fmt::format("{}: snow line -{:g}{}", label, drop, stopped ? " (stopped at 0)" : ""));
}

Derived<double> snow_line(const ClimateRow& row, Climate climate, Season season, Weather weather) {
  const ClimateTable& table = climate_table();
  const std::string_view name = name_of(climate);
  // Table 4 gives Df, Dw and ET a snow line per season, which already holds winter's fall; the
  // others get one value, lowered by the season's drop.
  Derived<double> line;
  if (row.snow_line_pct.size() == season_names.size()) {
    line = percent(row.snow_line_pct[index(season)], fmt::format("{}, {}", name, name_of(season)));
  } else {
    line = percent(row.snow_line_pct.front(), name);
    lower_snow_line(line, table.seasons[index(season)].snow_line_drop, fmt::format("season {}", name_of(season)));
  }
  lower_snow_line(line, table.weathers[index(weather)].snow_line_drop, fmt::format("weather {}", name_of(weather)));
  return line;
}

/// `values` at `latitude_deg` (north or south), linearly between the table's latitudes.
double at_latitude(const LinesByLatitude& lines, const std::vector<double>& values, double latitude_deg) {
  const double lat = std::clamp(std::abs(latitude_deg), 0.0, 90.0);
  const auto& lats = lines.latitude_deg;
  const std::size_t i = std::min<std::size_t>(std::upper_bound(lats.begin(), lats.end(), lat) - lats.begin(), lats.size() - 1);
  if (i == 0) return values.front();
  const double t = (lat - lats[i - 1]) / (lats[i] - lats[i - 1]);
  return values[i - 1] + (values[i] - values[i - 1]) * std::min(t, 1.0);
}

Derived<double> tree_line_m(const ClimateRow& row, Climate climate, double latitude_deg) {
  const ClimateTable& table = climate_table();
  Derived<double> line{at_latitude(table.lines, table.lines.tree_line_m, latitude_deg),
                       fmt::format("climatic tree line at {:g} deg (Koerner 1998)", std::abs(latitude_deg))};
  line.value = std::round(line.value);
  if (row.tree_line_max_m && line.value > *row.tree_line_max_m) {
    line.value = *row.tree_line_max_m;
    add_step(line.source, fmt::format("{}: at most {:g} m", name_of(climate), *row.tree_line_max_m));
  }
  return line;
}

Derived<double> snow_line_m(const ClimateRow& row, Climate climate, Season season, Weather weather, double latitude_deg) {
  const ClimateTable& table = climate_table();
  const std::string_view name = name_of(climate);
  Derived<double> line{at_latitude(table.lines, table.lines.snow_line_m, latitude_deg),
                       fmt::format("climatic snow line at {:g} deg (Wilhelm 1975)", std::abs(latitude_deg))};
  line.value = std::round(line.value);
  if (row.snow_line_shift_m != 0.0) {
    line.value = std::max(0.0, line.value + row.snow_line_shift_m);
    add_step(line.source, fmt::format("{}: {:+g} m", name, row.snow_line_shift_m));
  }
  if (row.snow_line_max_m && line.value > *row.snow_line_max_m) {
    line.value = *row.snow_line_max_m;
    add_step(line.source, fmt::format("{}: at most {:g} m", name, *row.snow_line_max_m));
  }
  const double share = table.seasons[index(season)].winter_share;
  if (row.winter_snow_line_m && share > 0.0 && *row.winter_snow_line_m < line.value) {
    line.value = std::round(line.value + (*row.winter_snow_line_m - line.value) * share);
    add_step(line.source, fmt::format("season {}: {:g} of the way to {}'s winter snow line {:g} m", name_of(season), share, name,
                                      *row.winter_snow_line_m));
  }
  const double drop = table.weathers[index(weather)].snow_line_drop_m;
  if (drop > 0.0 && line.value > 0.0) {
    line.value = std::max(0.0, line.value - drop);
    add_step(line.source, fmt::format("weather {}: -{:g} m", name_of(weather), drop));
  }
  return line;
}

Derived<double> turbidity(const ClimateRow& row, Climate climate, Weather weather) {
  const double change = climate_table().weathers[index(weather)].turbidity_change;
  Derived<double> haze{row.haze, fmt::format("climate table: {} haze {:g}", name_of(climate), row.haze)};
  if (change == 0.0) return haze;
  const double sum = haze.value + change;
  haze.value = std::clamp(sum, 2.0, 10.0);
  add_step(haze.source,
           fmt::format("weather {}: turbidity {:+g}{}", name_of(weather), change, sum == haze.value ? "" : " (kept within 2..10)"));
  return haze;
}

template <class E, std::size_t N>
std::vector<std::pair<std::string, E>> choices_of(const std::array<std::string_view, N>& names) {
  std::vector<std::pair<std::string, E>> choices;
  for (std::size_t i = 0; i < N; ++i) choices.emplace_back(std::string(names[i]), static_cast<E>(i));
  return choices;
}

std::string colour_text(const look::Rgb& colour) {
  return fmt::format("{:.3f},{:.3f},{:.3f}", colour.r, colour.g, colour.b);
}

}  // namespace

std::string_view name_of(Climate climate) {
  return climate_names.at(index(climate));
}
std::string_view name_of(Season season) {
  return season_names.at(index(season));
}
std::string_view name_of(Weather weather) {
  return weather_names.at(index(weather));
}

std::optional<Climate> climate_from_name(std::string_view name) {
  const auto i = index_of(climate_names, name);
  return i ? std::optional<Climate>(static_cast<Climate>(*i)) : std::nullopt;
}

std::optional<Season> season_from_name(std::string_view name) {
  const auto i = index_of(season_names, name);
  return i ? std::optional<Season>(static_cast<Season>(*i)) : std::nullopt;
}

std::optional<Weather> weather_from_name(std::string_view name) {
  const auto i = index_of(weather_names, name);
  return i ? std::optional<Weather>(static_cast<Weather>(*i)) : std::nullopt;
}

const std::vector<std::pair<std::string, Climate>>& climate_choices() {
  static const auto choices = choices_of<Climate>(climate_names);
  return choices;
}

const std::vector<std::pair<std::string, Season>>& season_choices() {
  static const auto choices = choices_of<Season>(season_names);
  return choices;
}

const std::vector<std::pair<std::string, Weather>>& weather_choices() {
  static const auto choices = choices_of<Weather>(weather_names);
  return choices;
}

std::string climate_title(Climate climate) {
  return climate_table().climates[index(climate)].title;
}

void check_climate_table(std::string_view toml_text) {
  parse_table(toml_text);
}

Look derive_look(Climate climate, Season season, Weather weather, double latitude_deg) {
  const ClimateTable& table = climate_table();
  const ClimateRow& row = table.climates[index(climate)];
  const WeatherRow& sky = table.weathers[index(weather)];
  const std::string_view name = name_of(climate);
  const std::string weather_source = fmt::format("weather {}", name_of(weather));
  Look look;
  // The climate's (summer) palette, then the season's tints, then the weather's.
  for (std::size_t i = 0; i < colour_keys.size(); ++i)
    look.*colour_members[i] = {row.palette[i], fmt::format("climate table: {} palette", name)};
  apply_tints(look, table.seasons[index(season)].tints, row, climate, fmt::format("season {}", name_of(season)));
  apply_tints(look, sky.tints, row, climate, weather_source);
  look.tree_density = percent(row.tree_density_pct, name);
  look.cover_slope = {row.cover_slope_deg, fmt::format("climate table: {} cover slope", name)};
  look.tree_line = percent(row.tree_line_pct, name);
  look.snow_line = snow_line(row, climate, season, weather);
  look.tree_line_m = tree_line_m(row, climate, latitude_deg);
  look.snow_line_m = snow_line_m(row, climate, season, weather, latitude_deg);
  look.cloud_cover = {sky.cloud_cover, weather_source};
  look.cloud_hurst = {sky.cloud_hurst, weather_source};
  look.fog_density = {sky.fog_density, weather_source};
  look.sun_strength = {sky.sun_strength, weather_source};
  look.turbidity = turbidity(row, climate, weather);
  return look;
}

std::vector<ExplainedValue> explain(const Look& look) {
  std::vector<ExplainedValue> values;
  for (std::size_t i = 0; i < colour_keys.size(); ++i) {
    const Derived<look::Rgb>& colour = look.*colour_members[i];
    values.push_back({std::string(colour_scene_keys[i]), colour_text(colour.value), colour.source});
  }
  const std::array<std::pair<std::string_view, const Derived<double>*>, 11> numbers{{{"land.tree_line_m", &look.tree_line_m},
                                                                                     {"land.cover_slope", &look.cover_slope},
                                                                                     {"land.snow_line_m", &look.snow_line_m},
                                                                                     {"land.tree_line", &look.tree_line},
                                                                                     {"land.snow_line", &look.snow_line},
                                                                                     {"vegetation.density", &look.tree_density},
                                                                                     {"sky.cloud_cover", &look.cloud_cover},
                                                                                     {"sky.cloud_fineness", &look.cloud_hurst},
                                                                                     {"atmosphere.fog", &look.fog_density},
                                                                                     {"sky.sun_strength", &look.sun_strength},
                                                                                     {"sky.turbidity", &look.turbidity}}};
  for (const auto& [key, number] : numbers) values.push_back({std::string(key), fmt::format("{:.4g}", number->value), number->source});
  return values;
}

}  // namespace sansui::scene
