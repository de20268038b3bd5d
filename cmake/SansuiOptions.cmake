# Compiler settings shared by every Sansui target, as one interface target.
add_library(sansui_options INTERFACE)
target_compile_options(sansui_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  # Determinism: never fuse a*b+c into an FMA, so scalar, SSE, AVX2 and AVX-512 code
  # paths (and other compilers) round exactly alike and the same seed gives the same bytes.
  -ffp-contract=off -fno-fast-math
  # sqrt without errno: lets loops with sqrt vectorise; the values are the same.
  -fno-math-errno)
if(SANSUI_NATIVE AND NOT SANSUI_SANITIZE)
  target_compile_options(sansui_options INTERFACE -march=native)
endif()
if(SANSUI_FUZZ)
  # Coverage feedback for libFuzzer in every library, with the sanitizers that make bugs loud.
  target_compile_options(sansui_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -g)
  target_link_options(sansui_options INTERFACE -fsanitize=address,undefined)
endif()
if(SANSUI_SANITIZE)
  target_compile_options(sansui_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  target_link_options(sansui_options INTERFACE -fsanitize=address,undefined)
endif()
