// One kernel body compiled for each vector level of core/simd.hpp, and a call that picks the
// level's. Write the body as an always-inline function template, then:
//
//   SANSUI_SIMD_KERNEL(name, body_function, (parameters), (arguments))
//
// defines name(parameters), which calls body_function(arguments) compiled for AVX-512
// (F, DQ, BW, VL, as Skylake-SP has), AVX2 or the baseline, as simd::level() says. Loops the
// compiler vectorises on its own gain the wider vectors; the code is the same C++ for every level,
// with -ffp-contract=off, so every level gives the same bytes (tests/core/simd_test.cpp).
// Elsewhere than x86-64 with GCC or Clang (the browser build) only the baseline is compiled.
#pragma once

#include "core/simd.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__EMSCRIPTEN__)
#define SANSUI_SIMD_KERNEL(name, body, parameters, arguments)                                   \
  namespace {                                                                                   \
  __attribute__((target("avx512f,avx512dq,avx512bw,avx512vl"))) void name##_avx512 parameters { \
    body arguments;                                                                             \
  }                                                                                             \
  __attribute__((target("avx2"))) void name##_avx2 parameters {                                 \
    body arguments;                                                                             \
  }                                                                                             \
  void name##_sse2 parameters {                                                                 \
    body arguments;                                                                             \
  }                                                                                             \
  }                                                                                             \
  void name parameters {                                                                        \
    switch (::sansui::simd::level()) {                                                          \
      case ::sansui::simd::Level::avx512:                                                       \
        return name##_avx512 arguments;                                                         \
      case ::sansui::simd::Level::avx2:                                                         \
        return name##_avx2 arguments;                                                           \
      default:                                                                                  \
        return name##_sse2 arguments;                                                           \
    }                                                                                           \
  }
#else
#define SANSUI_SIMD_KERNEL(name, body, parameters, arguments) \
  void name parameters {                                      \
    body arguments;                                           \
  }
#endif
