// The parts of C++20's standard library that Sansui uses and that Debian's Emscripten (3.1.6,
// whose libc++ is LLVM 13's) does not have yet: std::bit_cast, the std::ranges algorithms that
// src/ calls, std::atomic_ref, and std::from_chars for floating-point numbers. The browser build
// includes this file before every C++ file (cmake/SansuiWeb.cmake); the native build never sees
// it. Each is what the standard specifies for the calls src/ makes, no more; a newer Emscripten
// (libc++ 15+) has them all and then this file is skipped.
#pragma once

#include <version>

#if defined(__EMSCRIPTEN__) && defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 14000

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace std {

template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> && is_trivially_copyable_v<From>) constexpr To
    bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}

/// The browser build is serial (core/parallel.hpp), and one wasm thread sees its own stores:
/// plain loads and stores through the reference are what std::atomic_ref would do there.
template <class T>
class atomic_ref {
 public:
  explicit atomic_ref(T& value) noexcept : value_(addressof(value)) {}
  T load(memory_order = memory_order_seq_cst) const noexcept { return __atomic_load_n(value_, __ATOMIC_SEQ_CST); }
  void store(T desired, memory_order = memory_order_seq_cst) const noexcept { __atomic_store_n(value_, desired, __ATOMIC_SEQ_CST); }

 private:
  T* value_;
};

/// Floating-point from_chars as the standard has it (chars_format::general): no leading
/// whitespace or '+', no hexadecimal; rounded correctly (musl's strtod, in the C locale that a
/// wasm module always has); result_out_of_range when the value overflows.
namespace sansui_compat {
template <class T>
from_chars_result float_from_chars(const char* first, const char* last, T& value) {
  const char* p = first;
  if (p != last && *p == '-') ++p;
  if (p == last || *p == '+' || *p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == '\f' || *p == '\v')
    return {first, errc::invalid_argument};
  if (last - p >= 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
    value = T(0);  // "0x..." reads as the number 0 followed by "x...", as from_chars does
    return {p + 1, errc{}};
  }
  const string text(first, last);
  char* end = nullptr;
  errno = 0;
  const T parsed = is_same_v<T, float> ? T(strtof(text.c_str(), &end)) : T(strtod(text.c_str(), &end));
  if (end == text.c_str()) return {first, errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE && (parsed == T(HUGE_VAL) || parsed == -T(HUGE_VAL) || parsed == numeric_limits<T>::infinity() ||
                          parsed == -numeric_limits<T>::infinity()))
    return {stop, errc::result_out_of_range};
  value = parsed;
  return {stop, errc{}};
}
}  // namespace sansui_compat

inline from_chars_result from_chars(const char* first, const char* last, double& value, chars_format = chars_format::general) {
  return sansui_compat::float_from_chars(first, last, value);
}
inline from_chars_result from_chars(const char* first, const char* last, float& value, chars_format = chars_format::general) {
  return sansui_compat::float_from_chars(first, last, value);
}

namespace ranges {

template <class T>
struct min_max_result {
  T min;
  T max;
};

template <class R, class Out>
auto copy(R&& range, Out out) {
  return std::copy(std::begin(range), std::end(range), out);
}
template <class R, class T>
void fill(R&& range, const T& value) {
  std::fill(std::begin(range), std::end(range), value);
}
template <class R, class T>
void replace(R&& range, const T& old_value, const T& new_value) {
  std::replace(std::begin(range), std::end(range), old_value, new_value);
}
template <class R, class Out, class Op>
auto transform(R&& range, Out out, Op op) {
  return std::transform(std::begin(range), std::end(range), out, op);
}
template <class R, class T>
auto find(R&& range, const T& value) {
  return std::find(std::begin(range), std::end(range), value);
}
template <class R, class P>
auto find_if(R&& range, P predicate) {
  return std::find_if(std::begin(range), std::end(range), predicate);
}
template <class R, class P>
bool any_of(R&& range, P predicate) {
  return std::any_of(std::begin(range), std::end(range), predicate);
}
template <class R, class P>
bool all_of(R&& range, P predicate) {
  return std::all_of(std::begin(range), std::end(range), predicate);
}
template <class R, class P>
bool none_of(R&& range, P predicate) {
  return std::none_of(std::begin(range), std::end(range), predicate);
}
template <class R, class T>
auto count(R&& range, const T& value) {
  return std::count(std::begin(range), std::end(range), value);
}
template <class R, class C>
void sort(R&& range, C compare) {
  std::sort(std::begin(range), std::end(range), compare);
}
template <class R>
auto max_element(R&& range) {
  return std::max_element(std::begin(range), std::end(range));
}
template <class R>
auto max(R&& range) {
  return *std::max_element(std::begin(range), std::end(range));
}
template <class R>
auto minmax(R&& range) {
  using T = std::remove_cvref_t<decltype(*std::begin(range))>;
  const auto [low, high] = std::minmax_element(std::begin(range), std::end(range));
  return min_max_result<T>{*low, *high};
}

}  // namespace ranges
}  // namespace std

#endif
