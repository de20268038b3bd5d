#!/usr/bin/env bash
# Installs a built tree into a temporary prefix and builds a tiny user of it twice: with CMake's
# find_package(Sansui) and with pkg-config and the compiler directly; runs both, and the installed
# sansui. Only the consumer is compiled, never the project.
# Usage: tests/install/install_test.sh BUILD_DIR CXX_COMPILER
set -euo pipefail
build=$1 cxx=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/sansui-install-XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for file in bin/sansui share/man/man1/sansui.1.gz share/bash-completion/completions/sansui include/sansui/core/grid.hpp \
  include/sansui/terrain/midpoint.hpp share/sansui/data/climate.toml share/sansui/data/species.toml; do
  [[ -f "$prefix/$file" ]] || { echo "install: $file is missing" >&2; exit 1; }
done
pc=$(find "$prefix" -name sansui.pc)
config=$(find "$prefix" -name SansuiConfig.cmake)
[[ -n "$pc" && -n "$config" ]] || { echo "install: sansui.pc or SansuiConfig.cmake is missing" >&2; exit 1; }
"$prefix/bin/sansui" --version
zgrep -q '^\.TH SANSUI 1 ' "$prefix/share/man/man1/sansui.1.gz" || { echo "install: sansui.1.gz is not a manual page" >&2; exit 1; }
bash -n "$prefix/share/bash-completion/completions/sansui"

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$here/consumer" -B "$work/cmake" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/cmake" >"$work/build.log" || { cat "$work/build.log"; exit 1; }
echo "find_package(Sansui): $("$work/cmake/consumer")"

export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
# shellcheck disable=SC2046  # pkg-config's flags are words
"$cxx" -std=c++20 -O1 "$here/consumer/main.cpp" -o "$work/pkgconfig-consumer" $(pkg-config --cflags --libs sansui)
echo "pkg-config sansui: $("$work/pkgconfig-consumer")"
