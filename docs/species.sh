#!/usr/bin/env bash
# Makes docs/species.png: every species of data/species.toml (in file order, three to a row) in
# spring, summer, autumn and winter, drawn by `sansui tree`. Plants of snowless climates (tropics,
# deserts, steppe, Mediterranean) are drawn without winter snow. Usage: docs/species.sh
# (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mapfile -t species < <(grep -E '^name = "' data/species.toml | sed -E 's/name = "(.*)"/\1/')
snowless=" coconut_palm banana mangrove kapok baobab acacia saguaro date_palm short_grass savanna_grass fern olive cork_oak laurel cypress "
pictures=()
for name in "${species[@]}"; do
  snow=true
  [[ "$snowless" == *" $name "* ]] && snow=false
  for season in spring summer autumn winter; do
    flag=--winter-snow; [[ "$snow" == false ]] && flag=--no-winter-snow
    build/sansui tree --species "$name" --season "$season" "$flag" --width 140 --height 180 \
      -o "$work/$name-$season.png" >/dev/null
    pictures+=("$work/$name-$season.png")
  done
done
build/bench/contact_sheet docs/species.png 12 1 "${pictures[@]}"
