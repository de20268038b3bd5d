#!/usr/bin/env bash
# Makes the seed corpus of every fuzz target (tests/fuzz/corpus/NAME) from the examples and from
# small outputs of the built `sansui`: mostly valid files, so that fuzzing starts deep in each
# reader. Usage: tests/fuzz/make_corpus.sh [BUILD_DIR]   (default build; needs BUILD_DIR/sansui)
set -euo pipefail
cd "$(dirname "$0")/../.."
sansui="$PWD/${1:-build}/sansui"
corpus=tests/fuzz/corpus
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -rf "$corpus"
for name in $(scripts/fuzz --list); do mkdir -p "$corpus/$name"; done
separator=$'\n--sansui-fuzz-file--\n'  # tests/fuzz/fuzz_readers.hpp: sidecar, separator, file

# A heightmap file alone and with its sidecar.
with_sidecar() {  # FILE TARGET NAME
  cp "$1" "$corpus/$2/$3"
  { cat "$1.json"; printf '%s' "$separator"; cat "$1"; } > "$corpus/$2/$3-sidecar"
}
# Relative names, so that the sidecars' recipes (the sidecar target's corpus) name no folder.
cp examples/contours/c_shape.csv "$work/"
(cd "$work" && "$sansui" -q terrain --size 9 --seed 3 -o t.png -o t.raw -o t.r32 -o t.tif)
"$sansui" -q terrain --size 17 --seed 4 --compression none -o "$work/u.png" -o "$work/u.tif"
with_sidecar "$work/t.png" png16 t9; with_sidecar "$work/u.png" png16 u17
with_sidecar "$work/t.raw" raw16 t9
with_sidecar "$work/t.r32" r32 t9
with_sidecar "$work/t.tif" geotiff t9; with_sidecar "$work/u.tif" geotiff u17
convert -size 8x6 gradient:red-blue "$work/rgb.png" && cp "$work/rgb.png" "$corpus/image_png/rgb8x6.png"
convert -size 5x5 xc:gray50 -depth 16 "$work/grey16.png" && cp "$work/grey16.png" "$corpus/image_png/grey16.png"
cp "$work/t.png" "$corpus/image_png/t9.png"

cp "$work/t.r32.json" "$corpus/sidecar/terrain.r32.json"
(cd "$work" && "$sansui" -q contour c_shape.csv --offset 40 --dem-size 33 --dem c.r32 --contours c.geojson)
cp "$work/c.r32.json" "$corpus/sidecar/contour.r32.json"
cp "$work/c.geojson" "$corpus/contours_geojson/c_shape.geojson"

for scene in examples/scenes/*.toml; do cp "$scene" "$corpus/scene_toml/"; done
cp examples/contours/*.csv "$corpus/seed_csv/"; rm "$corpus/seed_csv/hypsometry_dome.csv"
cp examples/contours/*.geojson "$corpus/seed_geojson/"
cp examples/contours/*.svg "$corpus/seed_svg/"
cp examples/contours/hypsometry_dome.csv "$corpus/hypsometry/"
cp examples/meshes/mountain80.obj "$corpus/obj/"
"$sansui" -q subdivide --pyramid 100,50 --steps 1 -o "$work/p.glb" -o "$work/p.obj"
cp "$work/p.glb" "$corpus/glb/pyramid.glb"; cp "$work/p.obj" "$corpus/obj/pyramid.obj"
cp examples/sketches/mountain80.geojson "$corpus/sketch/"
# Text glTF and vertex locks: hand-made files (buffers as data: URIs), the pyramid's .glb.
python3 tests/fuzz/make_gltf_corpus.py "$corpus/gltf" "$corpus/vertex_locks"
cp "$work/p.glb" "$corpus/vertex_locks/pyramid.glb"
# contour-dem's contour maps: the first 12 lines of the Jacksboro map, and generated contours.
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d["features"]=d["features"][:12]; json.dump(d,open(sys.argv[2],"w"))' \
  examples/contours/jacksboro_40m.geojson "$corpus/contour_map/jacksboro_12.geojson"
cp "$work/c.geojson" "$corpus/contour_map/c_shape.geojson"
# Species files: the example, and the first two species of data/species.toml.
cp examples/species/weeping-willow.toml "$corpus/species/"
python3 -c 'import re,sys; b=re.split(r"(?m)^\[\[species\]\]\s*$", open(sys.argv[1]).read()); t="".join("[[species]]"+x for x in b[1:3]); open(sys.argv[2],"w").write(re.split(r"(?m)^\[(?!\[species\]\])", t)[0])' \
  data/species.toml "$corpus/species/two.toml"
"$sansui" -q contour examples/contours/c_shape.csv --offset 40 --dem-size 33 --plants "$work/plants.csv"
"$sansui" -q contour examples/contours/c_shape.csv --offset 40 --dem-size 33 --plants "$work/plants.json"
head -c 4000 "$work/plants.csv" | sed '$d' > "$corpus/plants_csv/plants.csv"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d["instances"]=d["instances"][:30]; json.dump(d,open(sys.argv[2],"w"))' \
  "$work/plants.json" "$corpus/plants_json/plants.json"
# argv: NUL-separated arguments after `sansui`.
args() { local name=$1; shift; printf '%s\0' "$@" | head -c -1 > "$corpus/argv/$name"; }
args terrain terrain --size 9 --hurst 0.7 -o out.png
args terrain-tiles terrain --world-size 33 --tile-size 17 -o out.r32
args contour contour examples/contours/c_shape.csv --offset 40 --dem out.r32
args solid solid --texture oak --levels 5 --slice out.png
args subdivide subdivide --pyramid 100,50 --steps 2 -o out.glb
args render render t.r32 -o out.png --view top
args erode terrain --size 65 --erode --stage mature -o out.r32
echo "corpus: $(find "$corpus" -type f | wc -l) files, $(du -sh "$corpus" | cut -f1)"
