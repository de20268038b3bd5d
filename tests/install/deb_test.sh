#!/usr/bin/env bash
# Packages a built tree as Debian packages (cpack -G DEB: one per component, see
# cmake/SansuiInstall.cmake), checks them with lintian (no error, and no warning but those the
# packages override, each with its reason), and installs them all with dpkg into an empty root,
# as on a fresh machine (the root has no package database of dependencies: the host's libraries
# serve, hence --force-depends). Then: the files are where Debian wants them (multiarch
# libraries, /usr/share/doc/PACKAGE with copyright and changelog), the Depends name what the
# programs load at run time and nothing the command line does not need, the installed sansui
# makes a terrain and renders it (headless, Mesa's EGL), the installed MPI plugin runs a tiled
# world under mpirun (and its absence is said), the Python module imports, and Blender enables
# the installed add-on. lintian runs alongside. About a minute on two busy cores (54-72 s
# measured, half of it CPack). The same packages installed by apt into a clean Debian 12, with a
# picture rendered there: clean_root_test.sh (root, network, minutes).
# Usage: tests/install/deb_test.sh BUILD_DIR
# Skips (exit 77) when a tool it needs is missing: scripts/setup --test installs them.
set -euo pipefail
for tool in cpack dpkg dpkg-deb dpkg-shlibdeps file lintian gcc; do
  command -v "$tool" >/dev/null || { echo "deb: $tool is missing (scripts/setup --test installs it): skipped" >&2; exit 77; }
done
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/sansui-deb-XXXXXX")
lintian_pids=()
trap 'for pid in "${lintian_pids[@]}"; do kill "$pid" 2>/dev/null; done; wait; rm -rf "$work"' EXIT
fail() {
  echo "deb: $*" >&2
  exit 1
}
started=$SECONDS

# lintian takes as long as the rest of the test, sansui-dev (static libraries) half of it: that
# package is made first and lintian checks it while CPack makes the others; lintian checks those
# while they install and run. Its verdict is read at the end: errors and warnings fail, the
# overridden ones are listed (O:) with the packages' reasons. (--fail-on would count the
# overridden tags too once --show-overrides lists them: the verdict is read from the listing.)
lint() {  # LOG DEB...
  local log=$1
  shift
  lintian --fail-on none --show-overrides --tag-display-limit 0 "$@" >"$log" 2>&1 &
  lintian_pids+=("$!")
}
components=$(sed -n 's/^set(CPACK_COMPONENTS_ALL "\(.*\)")$/\1/p' "$build/CPackConfig.cmake")
[[ ";$components;" == *";dev;"* ]] || fail "CPackConfig.cmake has no component dev: $components"
others=$(echo "$components" | tr ';' '\n' | grep -vx dev | paste -sd';')
(cd "$build" && cpack -G DEB -B "$work/package" -D CPACK_COMPONENTS_ALL=dev >"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; exit 1; }
lint "$work/lintian-dev.log" "$work/package"/sansui-dev_*.deb
(cd "$build" && cpack -G DEB -B "$work/package" -D "CPACK_COMPONENTS_ALL=$others" >>"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; exit 1; }
packages=(sansui sansui-viewer sansui-dev sansui-doc)
[[ -f "$build/sansui-mpi.so" ]] && packages+=(sansui-mpi)
[[ -d "$build/python/sansui" ]] && packages+=(python3-sansui sansui-blender)
declare -A deb
for package in "${packages[@]}"; do
  deb[$package]=$(find "$work/package" -maxdepth 1 -name "${package}_*.deb")
  [[ -n "${deb[$package]}" ]] || { cat "$work/cpack.log"; fail "cpack wrote no ${package}_*.deb"; }
done
made=$(find "$work/package" -maxdepth 1 -name '*.deb' | wc -l)
((made == ${#packages[@]})) || fail "cpack wrote $made packages, not the ${#packages[@]} expected: $(cd "$work/package" && echo *.deb)"
echo "deb: cpack wrote $made packages in $((SECONDS - started)) s: $(cd "$work/package" && du -h ./*.deb | sed 's#\./##' | tr '\t\n' '  ')"

# The control fields: the maintainers, one version, the Depends.
field() { dpkg-deb -f "${deb[$1]}" "$2"; }
version=$(field sansui Version)
for package in "${packages[@]}"; do
  [[ "$(field "$package" Maintainer)" == "Sansui maintainers <maintainers@users.noreply.h-seed-33883018.example>" ]] ||
    fail "$package: Maintainer is $(field "$package" Maintainer)"
  [[ "$(field "$package" Version)" == "$version" ]] || fail "$package: version $(field "$package" Version), sansui's $version"
done
depends() {  # PACKAGE MUST... -- MUST-NOT...
  local package=$1 list
  list=$(field "$package" Depends)
  shift
  local must=true
  for name in "$@"; do
    if [[ "$name" == -- ]]; then must=false; continue; fi
    if $must; then
      [[ ", $list," =~ ,\ $name[\ ,] ]] || fail "$package: Depends lacks $name: $list"
    else
      [[ ", $list," =~ ,\ $name[\ ,] ]] && fail "$package: Depends has $name: $list"
    fi
  done
  return 0
}
# The command line: what dpkg-shlibdeps sees, plus what the renderer loads at run time (Mesa's
# EGL and its software driver, glvnd's desktop OpenGL) and GDAL (dlopen); never MPI or GLFW.
depends sansui libc6 libgdal32 libproj25 libtbb12 libepoxy0 libegl1 libegl-mesa0 libgl1-mesa-dri libopengl0 \
  -- libopenmpi3 openmpi-bin libglfw3 python3
depends sansui-viewer libglfw3 libegl1 libgl1-mesa-dri -- libopenmpi3
depends sansui-dev libgdal-dev libcgal-dev libtbb-dev libepoxy-dev
if [[ -n "${deb[sansui-mpi]:-}" ]]; then depends sansui-mpi libopenmpi3 openmpi-bin sansui; fi
if [[ -n "${deb[python3-sansui]:-}" ]]; then depends python3-sansui python3 python3-numpy libegl-mesa0 -- libopenmpi3; fi
if [[ -n "${deb[sansui-blender]:-}" ]]; then depends sansui-blender python3-sansui; fi

lint "$work/lintian-others.log" $(find "$work/package" -maxdepth 1 -name '*.deb' ! -name 'sansui-dev_*')

# An empty root with an empty package database; dpkg installs every package there.
root=$work/root
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates"
touch "$root/var/lib/dpkg/status"
dpkg --root="$root" --force-depends --force-not-root -i "$work/package"/*.deb >"$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; exit 1; }
multiarch=$(gcc -print-multiarch)
files=(usr/bin/sansui usr/bin/sansui-viewer usr/share/man/man1/sansui.1.gz usr/share/man/man1/sansui-viewer.1.gz
  usr/share/bash-completion/completions/sansui usr/share/sansui/data/climate.toml usr/share/sansui/examples/scenes/island.toml
  usr/share/doc/sansui/README.md usr/share/doc/sansui/changelog.gz usr/share/doc/sansui/docs/render.md
  usr/share/doc/sansui/docs/images/scene-main-job.png
  usr/include/sansui/core/grid.hpp "usr/lib/$multiarch/libsansui_core.a" "usr/lib/$multiarch/cmake/Sansui/SansuiConfig.cmake"
  "usr/lib/$multiarch/pkgconfig/sansui.pc")
for file in "${files[@]}"; do
  [[ -f "$root/$file" ]] || fail "$file is not installed"
done
for package in "${packages[@]}"; do
  dpkg --root="$root" -s "$package" | grep -q '^Status: install ok installed' || fail "dpkg does not list $package as installed"
  for file in copyright changelog.Debian.gz; do
    [[ -f "$root/usr/share/doc/$package/$file" ]] || fail "$package has no /usr/share/doc/$package/$file"
  done
  first=$(zcat "$root/usr/share/doc/$package/changelog.Debian.gz" | head -1)
  [[ "$first" == "sansui ($version) "* ]] ||
    fail "cmake/debian/changelog's first entry is not version $version: $first (add an entry for the new version)"
done
leftovers=$(cd "$root" && find usr/lib -maxdepth 1 \( -type f -o -name pkgconfig -o -name cmake \))
[[ -z "$leftovers" ]] || fail "outside the multiarch folder usr/lib/$multiarch: $leftovers"

"$root/usr/bin/sansui" --version
"$root/usr/bin/sansui-viewer" --version
zgrep -q '^\.TH SANSUI 1 ' "$root/usr/share/man/man1/sansui.1.gz" || fail "sansui.1.gz is not a manual page"
zgrep -q '^\.TH SANSUI\\-VIEWER 1 ' "$root/usr/share/man/man1/sansui-viewer.1.gz" || fail "sansui-viewer.1.gz is not a manual page"
! ldd "$root/usr/bin/sansui" | grep -E 'libmpi|libglfw' || fail "the installed sansui links MPI or GLFW"

# The installed program makes a heightmap and draws it, headless (Mesa's EGL, no display): a PNG
# whose pixels differ.
mkdir "$work/run"
(cd "$work/run" && "$root/usr/bin/sansui" terrain --size 129 --seed 7 -o h.png --quiet >"$work/run.log" 2>&1 &&
  "$root/usr/bin/sansui" render h.png -o picture.png --width 320 --height 180 --quiet >>"$work/run.log" 2>&1) ||
  { cat "$work/run.log"; fail "the installed sansui does not make and render a terrain"; }
picture=$work/run/picture.png
[[ "$(head -c 8 "$picture" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] || fail "sansui render wrote no PNG"
python3 - "$picture" <<'PY' || fail "the rendered picture is blank"
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat = 8, b""
while pos < len(data):
    size, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + size]
    pos += 12 + size
pixels = zlib.decompress(idat)
sys.exit(0 if len(set(pixels)) > 16 else 1)
PY
echo "deb: the installed sansui made a 129x129 terrain and rendered it ($(du -h "$picture" | cut -f1) PNG)"

# The MPI plugin, as installed: found from /usr/bin/sansui under mpirun, a tiled world over two
# ranks; without it, one line naming the package to install, and exit code 2.
if [[ -n "${deb[sansui-mpi]:-}" ]] && command -v mpirun >/dev/null; then
  plugin=$root/usr/lib/$multiarch/sansui/sansui-mpi.so
  [[ -f "$plugin" ]] || fail "the MPI plugin is not installed at usr/lib/$multiarch/sansui/sansui-mpi.so"
  cat >"$work/world.toml" <<'EOF'
sansui_recipe = 4
source = "midpoint"
[world]
size = 129
tile_size = 65
tiled = true
[[output]]
file = "heights.vrt"
kind = "heightmap"
EOF
  mpirun -q --allow-run-as-root --oversubscribe -np 2 "$root/usr/bin/sansui" run "$work/world.toml" --out-dir "$work/world" >"$work/mpi.log" 2>&1 ||
    { cat "$work/mpi.log"; fail "the installed sansui does not run a tiled world over two ranks"; }
  grep -q "^2 ranks, 4 tiles" "$work/mpi.log" || { cat "$work/mpi.log"; fail "the tiled world did not run over two ranks"; }
  mv "$plugin" "$work/plugin.so"
  status=0
  mpirun -q --allow-run-as-root --oversubscribe -np 2 "$root/usr/bin/sansui" run "$work/world.toml" --out-dir "$work/world2" >"$work/mpi.log" 2>&1 || status=$?
  mv "$work/plugin.so" "$plugin"
  ((status != 0)) && grep -q "install the package sansui-mpi" "$work/mpi.log" && [[ ! -e "$work/world2" ]] ||
    { cat "$work/mpi.log"; fail "without the plugin, mpirun sansui should fail saying what to install (status $status)"; }
  echo "deb: the installed MPI plugin runs a tiled world over two ranks; without it: $(grep -m1 sansui-mpi "$work/mpi.log")"
fi

# The Python module, in Debian's dist-packages, importable from there.
if [[ -n "${deb[python3-sansui]:-}" ]]; then
  site=usr/lib/python3/dist-packages/sansui
  for file in __init__.py __init__.pyi py.typed; do
    [[ -f "$root/$site/$file" ]] || fail "$site/$file is not installed"
  done
  PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import sansui, numpy; h = sansui.midpoint(size=33, seed=1); assert h.shape == (33, 33) and h.dtype == numpy.float32; print('deb: import sansui', sansui.__version__)"
fi
# The Blender add-on, among Blender's system add-ons.
if [[ -n "${deb[sansui-blender]:-}" ]]; then
  [[ -f "$root/usr/share/blender/scripts/addons/sansui_terrain/__init__.py" ]] || fail "the Blender add-on is not installed"
  if command -v blender >/dev/null; then
    blender -b --factory-startup --python-exit-code 1 --python "$here/blender_addon_check.py" -- "$root" >"$work/blender.log" 2>&1 ||
      { cat "$work/blender.log"; fail "Blender does not enable the installed add-on"; }
    grep '^deb: ' "$work/blender.log"
  fi
fi
for pid in "${lintian_pids[@]}"; do
  status=0
  wait "$pid" || status=$?
  ((status == 0)) || { cat "$work"/lintian-*.log; fail "lintian did not run (status $status)"; }
done
lintian_pids=()
cat "$work/lintian-dev.log" "$work/lintian-others.log" >"$work/lintian.log"
grep -v -e '^running with root privileges' -e '^N: ' "$work/lintian.log" | sed 's/^/deb: lintian: /' || true
! grep -q '^[EW]: ' "$work/lintian.log" || fail "lintian reports errors or warnings (above)"
echo "deb: lintian passes the $made packages: no error, no warning not overridden"
echo "deb: ${#packages[@]} packages install into an empty root and run ($((SECONDS - started)) s)"
