// Parameter tables (SPEC 3.7): one table per params struct, the only place an option is
// declared. A row names one field and says its key, the kind of value, its unit, the allowed
// range, one line of help and a group; its default is the struct's own default member value, so
// the default is never written twice. From the tables come the CLI options (bound straight into
// the library structs), the per-value checks of validate(), the provenance and scene-file keys,
// docs/params.md, and later the viewer's widgets and Python keyword arguments.
//
// The idea is FastNoise2's node metadata and Recast's documented rcConfig, with pbrt-v4's habit of
// naming the file, line and key of a bad value (scene/recipe_file.cpp does the file part).
//
//   const params::Table<MidpointParams>& parameter_table(const MidpointParams*) {
//     static const auto table = params::Table<MidpointParams>("midpoint", "Fractal terrain ...")
//         .add(params::field("hurst", &MidpointParams::hurst).above(0).at_most(1).doc("..."));
//     return table;
//   }
//
// params::table_of<S>() finds a struct's table by argument-dependent lookup of that function.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace sansui::params {

/// What a value is, as a user writes it.
enum class Kind {
  flag,     ///< true or false
  integer,  ///< a whole number (stored as int64)
  real,     ///< a finite number
  text,     ///< free text
  choice,   ///< one of a few names
  path,     ///< a file name, relative to the recipe file (or the working directory on the CLI)
  reals,    ///< a fixed or bounded number of finite numbers: a pair, a colour, a list
};

/// The kind's name as tables are shown to programs (Python's parameter_tables(), the page's
/// controls): "flag", "integer", "real", "text", "choice", "path", "reals".
std::string_view kind_name(Kind kind);

/// A value as a user writes it. monostate: an optional field left unset.
using Value = std::variant<std::monostate, bool, std::int64_t, double, std::string, std::vector<double>>;

/// What values a row allows, beyond its kind.
struct Limits {
  std::optional<double> min, max;            ///< bounds of numbers (each number of `reals`)
  std::optional<double> type_min, type_max;  ///< what the member's type holds (not shown in help)
  bool min_exclusive = false, max_exclusive = false;
  std::size_t min_count = 1, max_count = 1;  ///< `reals`: how many numbers
  bool whole = false;                        ///< `reals`: whole numbers only
  std::vector<std::string> choices;          ///< `choice`: the allowed names
  /// An extra rule (e.g. "2^k+1"): returns what is allowed if `value` breaks it, else "".
  std::function<std::string(const Value& value)> rule;
  std::string rule_text;  ///< the rule in words, for help and docs
};

/// Everything about a row except how it reaches the struct.
struct ParamInfo {
  std::string key;                   ///< key in its section, dotted for nested tables: "camera.azimuth"
  std::string flag;                  ///< CLI long option without "--" and section prefix: "camera-azimuth"
  std::vector<std::string> aliases;  ///< extra CLI names, with dashes: "-R", "--fov"
  Kind kind = Kind::real;
  std::string unit;       ///< "m", "deg", "px", ...; empty when the value has none
  bool unitless = false;  ///< a number that has no unit on purpose (a ratio, a fraction, an exponent)
  Limits limits;
  std::string help;         ///< one line
  std::string group;        ///< for help and docs: "shape", "camera", ...
  bool optional = false;    ///< may be left unset
  std::string unset_means;  ///< what unset stands for, e.g. "1.4; revised 3"
  bool exposed = true;      ///< false: filled by the pipeline, never by users
  /// A key kept to read older files: files of layout version `superseded_in` or later give it
  /// as `superseded_by` instead ("[world] sea_level") and may not set it. 0: a current key.
  int superseded_in = 0;
  std::string superseded_by;
  /// A key new in layout version `introduced_in`: older files neither read nor write it (their
  /// value is the one the older layout implied). 0: a key of every version.
  int introduced_in = 0;

  /// Whether files of layout `version` read and write this key.
  bool current_in(int version) const {
    return (superseded_in == 0 || version < superseded_in) && (introduced_in == 0 || version >= introduced_in);
  }
};

/// One row: a ParamInfo plus the way to read and write its field(s) of S.
template <class S>
struct Param : ParamInfo {
  std::function<Value(const S&)> get;
  std::function<void(S&, const Value&)> set;
  std::vector<std::ptrdiff_t> fields;  ///< byte offsets of the members of S the row covers

  // Builders: each returns *this, so rows read as one expression.
  Param& doc(std::string text) {
    help = std::move(text);
    return *this;
  }
  Param& units(std::string text) {
    unit = std::move(text);
    return *this;
  }
  /// A ratio, fraction, exponent or index: a number with no unit, on purpose.
  Param& no_unit() {
    unitless = true;
    return *this;
  }
  Param& grouped(std::string text) {
    group = std::move(text);
    return *this;
  }
  Param& alias(std::string name) {
    aliases.push_back(std::move(name));
    return *this;
  }
  Param& flag_name(std::string name) {
    flag = std::move(name);
    return *this;
  }
  Param& unset(std::string meaning) {
    unset_means = std::move(meaning);
    return *this;
  }
  Param& internal() {
    exposed = false;
    return *this;
  }
  /// Read only from files older than layout `version`; from then on the value is given as `by`.
  Param& superseded(int version, std::string by) {
    superseded_in = version;
    superseded_by = std::move(by);
    return *this;
  }
  /// Read and written by files of layout `version` on only.
  Param& introduced(int version) {
    introduced_in = version;
    return *this;
  }
  Param& at_least(double v) {
    limits.min = v;
    limits.min_exclusive = false;
    return *this;
  }
  Param& above(double v) {
    limits.min = v;
    limits.min_exclusive = true;
    return *this;
  }
  Param& at_most(double v) {
    limits.max = v;
    limits.max_exclusive = false;
    return *this;
  }
  Param& below(double v) {
    limits.max = v;
    limits.max_exclusive = true;
    return *this;
  }
  Param& in(double low, double high) { return at_least(low).at_most(high); }
  Param& count(std::size_t low, std::size_t high) {
    limits.min_count = low;
    limits.max_count = high;
    return *this;
  }
  Param& whole() {
    limits.whole = true;
    return *this;
  }
  Param& rule(std::function<std::string(const Value&)> check, std::string text) {
    limits.rule = std::move(check);
    limits.rule_text = std::move(text);
    return *this;
  }
};

/// The rows of one params struct, and the name of its section in scene files.
template <class S>
struct Table {
  std::string section;  ///< "midpoint": [midpoint] in a scene file
  std::string title;    ///< one line, for docs
  std::vector<Param<S>> rows;

  Table(std::string section_name, std::string title_text) : section(std::move(section_name)), title(std::move(title_text)) {}
  Table&& add(Param<S> row) && {
    rows.push_back(std::move(row));
    return std::move(*this);
  }
  Table& add(Param<S> row) & {
    rows.push_back(std::move(row));
    return *this;
  }
  /// The rows of `inner` (the table of S's member `member`), keys prefixed by `key_prefix`
  /// ("camera." for a nested table, "loop_" for one flattened into this section) and CLI flags
  /// by `flag_prefix`. `exposed_only`: without the rows the pipeline fills (a node kind that
  /// takes a section's user keys, beside keys of its own of the same names).
  template <class Inner>
  Table& nest(std::string key_prefix, std::string flag_prefix, Inner S::*member, const Table<Inner>& inner, bool exposed_only = false) &;
  template <class Inner>
  Table&& nest(std::string key_prefix, std::string flag_prefix, Inner S::*member, const Table<Inner>& inner, bool exposed_only = false) && {
    nest(std::move(key_prefix), std::move(flag_prefix), member, inner, exposed_only);
    return std::move(*this);
  }

  const Param<S>* find(std::string_view key) const {
    for (const auto& row : rows)
      if (row.key == key) return &row;
    return nullptr;
  }
};

/// The table of S, found by argument-dependent lookup of `parameter_table(const S*)`, which the
/// struct's own header declares.
template <class S>
const Table<S>& table_of() {
  return parameter_table(static_cast<const S*>(nullptr));
}

// ---- how a C++ member type maps to a Value ---------------------------------------------------

template <class T>
struct Codec;  // specialisations below: kind, limits, to, from

template <>
struct Codec<bool> {
  static constexpr Kind kind = Kind::flag;
  static void limit(Limits&) {}
  static Value to(bool v) { return v; }
  static bool from(const Value& v) { return std::get<bool>(v); }
};

template <class T>
requires(std::is_integral_v<T> && !std::is_same_v<T, bool>) struct Codec<T> {
  static constexpr Kind kind = Kind::integer;
  static void limit(Limits& limits) {
    // Values are int64 in files; unsigned 64-bit fields (seeds) stop at 2^63 - 1.
    limits.type_min = static_cast<double>(std::numeric_limits<T>::min());
    limits.type_max =
        static_cast<double>(std::min<std::uintmax_t>(std::numeric_limits<T>::max(), std::numeric_limits<std::int64_t>::max()));
  }
  static Value to(T v) { return static_cast<std::int64_t>(v); }
  static T from(const Value& v) { return static_cast<T>(std::get<std::int64_t>(v)); }
};

/// A float as the double of its shortest decimal form (0.95f as 0.95, not 0.949999988...), so
/// files and messages show what a user wrote; converting back gives the same float.
double float_as_written(float v);
inline double as_written(double v) {
  return v;
}
inline double as_written(float v) {
  return float_as_written(v);
}

template <class T>
requires std::is_floating_point_v<T>
struct Codec<T> {
  static constexpr Kind kind = Kind::real;
  static void limit(Limits&) {}
  static Value to(T v) { return as_written(v); }
  static T from(const Value& v) { return static_cast<T>(std::get<double>(v)); }
};

template <>
struct Codec<std::string> {
  static constexpr Kind kind = Kind::text;
  static void limit(Limits&) {}
  static Value to(const std::string& v) { return v; }
  static std::string from(const Value& v) { return std::get<std::string>(v); }
};

template <class T>
requires std::is_floating_point_v<T>
struct Codec<std::vector<T>> {
  static constexpr Kind kind = Kind::reals;
  static void limit(Limits& limits) { limits.min_count = 0, limits.max_count = 1u << 20; }
  static Value to(const std::vector<T>& v) {
    std::vector<double> numbers;
    numbers.reserve(v.size());
    for (T x : v) numbers.push_back(as_written(x));
    return numbers;
  }
  static std::vector<T> from(const Value& v) {
    const auto& numbers = std::get<std::vector<double>>(v);
    return std::vector<T>(numbers.begin(), numbers.end());
  }
};

template <class T, std::size_t N>
requires std::is_arithmetic_v<T>
struct Codec<std::array<T, N>> {
  static constexpr Kind kind = Kind::reals;
  static void limit(Limits& limits) {
    limits.min_count = limits.max_count = N;
    limits.whole = std::is_integral_v<T>;
    if constexpr (std::is_integral_v<T>) {
      // Each number must fit the element (a tile index of 2^63 - 1 is no int: the recipe fuzz
      // target's finding under UBSan).
      limits.type_min = static_cast<double>(std::numeric_limits<T>::min());
      limits.type_max = static_cast<double>(std::numeric_limits<T>::max());
    }
  }
  static Value to(const std::array<T, N>& v) {
    std::vector<double> numbers;
    for (T x : v) {
      if constexpr (std::is_floating_point_v<T>)
        numbers.push_back(as_written(x));
      else
        numbers.push_back(static_cast<double>(x));
    }
    return numbers;
  }
  static std::array<T, N> from(const Value& v) {
    const auto& numbers = std::get<std::vector<double>>(v);
    std::array<T, N> out{};
    for (std::size_t i = 0; i < N && i < numbers.size(); ++i) out[i] = static_cast<T>(numbers[i]);
    return out;
  }
};

/// Colours: any struct with float r, g, b (sRGB, 0..1).
template <class T>
concept RgbColour = requires(T c) {
  { c.r } -> std::convertible_to<float>;
  { c.g } -> std::convertible_to<float>;
  { c.b } -> std::convertible_to<float>;
}
&&!requires(T c) {
  c.a;
}
&&std::is_floating_point_v<decltype(T::r)>;

template <RgbColour T>
struct Codec<T> {
  static constexpr Kind kind = Kind::reals;
  static void limit(Limits& limits) {
    limits.min_count = limits.max_count = 3;
    limits.min = 0.0, limits.max = 1.0;
  }
  static constexpr bool unitless = true;
  static Value to(const T& c) { return std::vector<double>{as_written(c.r), as_written(c.g), as_written(c.b)}; }
  static T from(const Value& v) {
    const auto& n = std::get<std::vector<double>>(v);
    T c;
    c.r = static_cast<float>(n[0]), c.g = static_cast<float>(n[1]), c.b = static_cast<float>(n[2]);
    return c;
  }
};

/// 8-bit colours with alpha: any struct with integral r, g, b, a (0..255).
template <class T>
concept Rgba8Colour = requires(T c) {
  c.r;
  c.g;
  c.b;
  c.a;
}
&&std::is_integral_v<decltype(T::r)>;

template <Rgba8Colour T>
struct Codec<T> {
  static constexpr Kind kind = Kind::reals;
  static void limit(Limits& limits) {
    limits.min_count = limits.max_count = 4;
    limits.min = 0.0, limits.max = 255.0;
    limits.whole = true;
  }
  static constexpr bool unitless = true;
  static Value to(const T& c) { return std::vector<double>{double(c.r), double(c.g), double(c.b), double(c.a)}; }
  static T from(const Value& v) {
    const auto& n = std::get<std::vector<double>>(v);
    T c;
    c.r = static_cast<decltype(c.r)>(n[0]), c.g = static_cast<decltype(c.g)>(n[1]);
    c.b = static_cast<decltype(c.b)>(n[2]), c.a = static_cast<decltype(c.a)>(n[3]);
    return c;
  }
};

template <class T>
struct Codec<std::optional<T>> {
  static constexpr Kind kind = Codec<T>::kind;
  static void limit(Limits& limits) { Codec<T>::limit(limits); }
  static Value to(const std::optional<T>& v) { return v ? Codec<T>::to(*v) : Value{}; }
  static std::optional<T> from(const Value& v) {
    if (std::holds_alternative<std::monostate>(v)) return std::nullopt;
    return Codec<T>::from(v);
  }
};

template <class T>
inline constexpr bool is_optional_v = false;
template <class T>
inline constexpr bool is_optional_v<std::optional<T>> = true;

namespace detail {

template <class T>
struct value_type_of {
  using type = T;
};
template <class T>
struct value_type_of<std::optional<T>> {
  using type = T;
};

/// Byte offset of a member in S (S must be default-constructible).
template <class S, class M>
std::ptrdiff_t offset_of(M S::*member) {
  static const S probe{};
  return reinterpret_cast<const char*>(&(probe.*member)) - reinterpret_cast<const char*>(&probe);
}

/// "sea_level" -> "sea-level": the CLI spelling of a key.
std::string flag_of(std::string_view key);

template <class M>
void describe(ParamInfo& info, std::string key) {
  info.flag = flag_of(key);
  info.key = std::move(key);
  info.kind = Codec<M>::kind;
  info.optional = is_optional_v<M>;
  Codec<M>::limit(info.limits);
  if constexpr (requires { Codec<typename value_type_of<M>::type>::unitless; })
    info.unitless = Codec<typename value_type_of<M>::type>::unitless;
}

}  // namespace detail

// ---- row builders ----------------------------------------------------------------------------

/// A row for one member; the kind follows the member's type (bool, whole number, real, text,
/// numbers, colour, or an optional of one of those).
template <class S, class M>
Param<S> field(std::string key, M S::*member) {
  Param<S> row;
  detail::describe<M>(row, std::move(key));
  row.get = [member](const S& s) { return Codec<M>::to(s.*member); };
  row.set = [member](S& s, const Value& v) { s.*member = Codec<M>::from(v); };
  row.fields = {detail::offset_of(member)};
  return row;
}

/// A row for a member that users never set (its type has no text form): the pipeline fills it.
/// It counts for the completeness check and reads as unset.
template <class S, class M>
Param<S> opaque(std::string key, M S::*member) {
  Param<S> row;
  row.flag = detail::flag_of(key);
  row.key = std::move(key);
  row.kind = Kind::text;
  row.optional = true;
  row.exposed = false;
  row.get = [](const S&) { return Value{}; };
  row.set = [](S&, const Value&) {};
  row.fields = {detail::offset_of(member)};
  return row;
}

/// A row for a file name held in a std::string member.
template <class S>
Param<S> path(std::string key, std::string S::*member) {
  Param<S> row = field(std::move(key), member);
  row.kind = Kind::path;
  return row;
}

/// A row for an enum member, written as one of `names`.
template <class S, class E>
requires std::is_enum_v<E> Param<S> choice(std::string key, E S::*member, std::vector<std::pair<std::string, E>> names) {
  Param<S> row;
  detail::describe<std::string>(row, std::move(key));
  row.kind = Kind::choice;
  for (const auto& [name, value] : names) row.limits.choices.push_back(name);
  row.get = [member, names](const S& s) -> Value {
    for (const auto& [name, value] : names)
      if (s.*member == value) return name;
    return std::string("?");
  };
  row.set = [member, names](S& s, const Value& v) {
    for (const auto& [name, value] : names)
      if (std::get<std::string>(v) == name) s.*member = value;
  };
  row.fields = {detail::offset_of(member)};
  return row;
}

/// The same for an optional enum (unset: the method's own default).
template <class S, class E>
Param<S> choice(std::string key, std::optional<E> S::*member, std::vector<std::pair<std::string, E>> names) {
  Param<S> row;
  detail::describe<std::string>(row, std::move(key));
  row.kind = Kind::choice;
  row.optional = true;
  for (const auto& [name, value] : names) row.limits.choices.push_back(name);
  row.get = [member, names](const S& s) -> Value {
    if (!(s.*member)) return {};
    for (const auto& [name, value] : names)
      if (*(s.*member) == value) return name;
    return std::string("?");
  };
  row.set = [member, names](S& s, const Value& v) {
    if (std::holds_alternative<std::monostate>(v)) {
      s.*member = std::nullopt;
      return;
    }
    for (const auto& [name, value] : names)
      if (std::get<std::string>(v) == name) s.*member = value;
  };
  row.fields = {detail::offset_of(member)};
  return row;
}

/// A text row whose value is one of `names` (a std::string member: presets, "none").
template <class S>
Param<S> choice(std::string key, std::string S::*member, std::vector<std::string> names) {
  Param<S> row = field(std::move(key), member);
  row.kind = Kind::choice;
  row.limits.choices = std::move(names);
  return row;
}

/// Two numeric members written as one pair "A,B" (both set or, for optionals, both unset).
template <class S, class M>
Param<S> pair(std::string key, M S::*first, M S::*second) {
  using Number = typename detail::value_type_of<M>::type;
  Param<S> row;
  detail::describe<std::array<double, 2>>(row, std::move(key));
  row.limits.whole = std::is_integral_v<Number>;
  row.optional = is_optional_v<M>;
  row.get = [first, second](const S& s) -> Value {
    if constexpr (is_optional_v<M>) {
      if (!(s.*first) || !(s.*second)) return {};
      return std::vector<double>{double(*(s.*first)), double(*(s.*second))};
    } else {
      return std::vector<double>{double(s.*first), double(s.*second)};
    }
  };
  row.set = [first, second](S& s, const Value& v) {
    if constexpr (is_optional_v<M>) {
      if (std::holds_alternative<std::monostate>(v)) {
        s.*first = std::nullopt, s.*second = std::nullopt;
        return;
      }
    }
    const auto& n = std::get<std::vector<double>>(v);
    s.*first = static_cast<Number>(n[0]);
    s.*second = static_cast<Number>(n[1]);
  };
  row.fields = {detail::offset_of(first), detail::offset_of(second)};
  return row;
}

/// A row with its own accessors, for values spread over members in an unusual way. `fields`
/// are the members it covers (for the completeness check).
template <class S>
Param<S> custom(std::string key, Kind kind, std::function<Value(const S&)> get, std::function<void(S&, const Value&)> set,
                std::vector<std::ptrdiff_t> fields) {
  Param<S> row;
  row.flag = detail::flag_of(key);
  row.key = std::move(key);
  row.kind = kind;
  row.get = std::move(get);
  row.set = std::move(set);
  row.fields = std::move(fields);
  return row;
}

/// Byte offset of a member, for custom rows.
template <class S, class M>
std::ptrdiff_t offset(M S::*member) {
  return detail::offset_of(member);
}

template <class S>
template <class Inner>
Table<S>& Table<S>::nest(std::string key_prefix, std::string flag_prefix, Inner S::*member, const Table<Inner>& inner,
                         bool exposed_only) & {
  const std::ptrdiff_t where = detail::offset_of(member);
  for (const Param<Inner>& row : inner.rows) {
    if (exposed_only && !row.exposed) continue;
    Param<S> outer;
    static_cast<ParamInfo&>(outer) = row;
    outer.key = key_prefix + row.key;
    outer.flag = flag_prefix + row.flag;
    outer.get = [member, get = row.get](const S& s) { return get(s.*member); };
    outer.set = [member, set = row.set](S& s, const Value& v) { set(s.*member, v); };
    outer.fields = {where};
    rows.push_back(std::move(outer));
  }
  return *this;
}

// ---- values as text, checks ------------------------------------------------------------------

/// A value as a user would write it on the command line: 0.8, true, 300,32, revised. Numbers
/// are written in the fewest digits that read back to the same double.
std::string format_value(const Value& value);

/// A number in the fewest digits that read back to the same double ("0.1", "400", "1e-07").
std::string format_number(double value);

/// What the row allows, in words: "> 0 and <= 1", "one of simple, midpoint", "2 numbers, each
/// between 0 and 1", with the unit. Empty when anything of its kind goes.
std::string allowed_text(const ParamInfo& row);

/// The default shown in help and docs: the value, or what unset means.
std::string default_text(const ParamInfo& row, const Value& default_value);

/// "" if `value` is allowed, else what is allowed (for a message). Checks the kind too.
std::string check(const ParamInfo& row, const Value& value);

/// Parses command-line text into the row's kind. Throws InputError naming `name` (e.g. the
/// option "--hurst") and what is allowed.
Value parse_text(const ParamInfo& row, std::string_view text, std::string_view name);

/// Throws InputError "NAME VALUE is not allowed: it must be ..." unless check() passes.
void require_allowed(const ParamInfo& row, const Value& value, std::string_view name);

/// Checks every row of `table` on `object`; messages name "section.key".
template <class S>
void validate(const Table<S>& table, const S& object) {
  for (const auto& row : table.rows) require_allowed(row, row.get(object), table.section + "." + row.key);
}

template <class S>
void validate(const S& object) {
  validate(table_of<S>(), object);
}

// ---- completeness: every member of a params struct has a row ---------------------------------

namespace detail {

struct AnyMember {
  // Not for optionals: optional<T> is built from AnyMember through its converting constructor,
  // and a second path would make the initialisation ambiguous.
  template <class T>
  requires(!is_optional_v<T>) operator T() const noexcept;
};

template <class T, std::size_t... I>
constexpr bool brace_constructible(std::index_sequence<I...>) {
  return requires {
    T{(void(I), AnyMember{})...};
  };
}

}  // namespace detail

/// The number of members of the aggregate T (brace-initialisation probing, as Boost.PFR does).
template <class T, std::size_t N = 0>
constexpr std::size_t field_count() {
  if constexpr (detail::brace_constructible<T>(std::make_index_sequence<N + 1>()))
    return field_count<T, N + 1>();
  else
    return N;
}

/// How many distinct members of S the rows of `table` cover.
template <class S>
std::size_t covered_fields(const Table<S>& table) {
  std::vector<std::ptrdiff_t> seen;
  for (const auto& row : table.rows)
    for (std::ptrdiff_t f : row.fields)
      if (std::find(seen.begin(), seen.end(), f) == seen.end()) seen.push_back(f);
  return seen.size();
}

}  // namespace sansui::params
