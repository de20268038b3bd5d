# Compiler settings shared by every Sansui target, as one interface target. Its compile options
# are for Sansui's own build only ($<BUILD_INTERFACE>): an installed library passes no warning or
# CPU flags to its users (cmake/SansuiInstall.cmake); the sanitizers' link options do pass on.
add_library(sansui_options INTERFACE)
set(sansui_compile_options
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  # Determinism: never fuse a*b+c into an FMA, so scalar, SSE, AVX2 and AVX-512 code
  # paths (and other compilers) round exactly alike and the same seed gives the same bytes.
  -ffp-contract=off -fno-fast-math
  # sqrt without errno: lets loops with sqrt vectorise; the values are the same.
  -fno-math-errno)
if(SANSUI_NATIVE AND NOT SANSUI_SANITIZE)
  list(APPEND sansui_compile_options -march=native)
endif()
# Sanitizer reports need file and line, not variables: line tables only (after the build type's
# -g, so they win) take an eighth off the sanitizer build's compile time and more off its links.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(sansui_line_tables -gline-tables-only)
else()
  set(sansui_line_tables -g1)
endif()
if(SANSUI_FUZZ)
  # Coverage feedback for libFuzzer in every library, with the sanitizers that make bugs loud.
  list(APPEND sansui_compile_options -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer ${sansui_line_tables})
  target_link_options(sansui_options INTERFACE -fsanitize=address,undefined)
endif()
if(SANSUI_SANITIZE)
  list(APPEND sansui_compile_options -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
       ${sansui_line_tables})
  target_link_options(sansui_options INTERFACE -fsanitize=address,undefined)
endif()
target_compile_options(sansui_options INTERFACE "$<BUILD_INTERFACE:${sansui_compile_options}>")
