#!/usr/bin/env bash
# The .deb packages on a clean Debian 12: a root made by debootstrap (minbase) from Debian's
# archive, where apt installs ./sansui_*.deb with --no-install-recommends and resolves its Depends
# from the archive (nothing from this machine), and the installed sansui makes a heightmap and
# renders it to a PNG (Mesa's EGL, headless, no GPU). Then the other packages: python3-sansui
# imports and makes a grid, sansui-viewer prints its version, sansui-mpi runs a tiled world over
# two ranks, and apt resolves sansui-dev's Depends (simulated: they are the -dev packages of the
# whole tool chain). Needs root (chroot, mount) and Debian's archive over the network; minutes.
#
# The base root is made once and kept in $SANSUI_TEST_ROOT_CACHE (default
# /var/cache/sansui-test-root/bookworm, outside the repository); each run copies it and throws
# the copy away. `--prepare` only makes the base root.
# Usage: tests/install/clean_root_test.sh [--prepare] BUILD_DIR
set -euo pipefail
prepare=false
if [[ "${1:-}" == "--prepare" ]]; then
  prepare=true
  shift
fi
[[ $(id -u) -eq 0 ]] || { echo "clean-root: needs root (debootstrap, chroot, mount)" >&2; exit 77; }
for tool in debootstrap chroot cpack; do
  command -v "$tool" >/dev/null || { echo "clean-root: $tool is missing (scripts/setup --test installs debootstrap)" >&2; exit 77; }
done
name=clean-root
source "$(dirname "$0")/debian_root.sh"
make_base_root
$prepare && exit 0

build=$(cd "$1" && pwd)
work=$(mktemp -d "${TMPDIR:-/var/tmp}/sansui-clean-root-XXXXXX")
root=$work/root
trap 'remove_root "$root"; rm -rf "$work"' EXIT

# 2. The packages, made from the build as deb_test.sh makes them.
(cd "$build" && cpack -G DEB -B "$work/package" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
say "packages: $(cd "$work/package" && echo *.deb)"

# 3. A copy of the base root, brought up to date, with the packages in /tmp.
cp -a "$base" "$root"
mkdir -p "$root/tmp/debs"
cp "$work/package"/*.deb "$root/tmp/debs/"
in_root "$root" apt-get update -qq
say "root ready"

# 4. sansui alone, with only its Depends (no Recommends): a heightmap, then its picture.
sansui_deb=$(cd "$root/tmp/debs" && echo sansui_*.deb)  # the name on this side: the root's shell is not used
in_root "$root" apt-get install -y -qq --no-install-recommends "/tmp/debs/$sansui_deb" >"$work/apt-sansui.log" 2>&1 ||
  { cat "$work/apt-sansui.log"; exit 1; }
say "apt installed sansui and $(grep -c '^Setting up' "$work/apt-sansui.log") packages"
# Neither Open MPI nor GLFW came with it (they are sansui-mpi's and sansui-viewer's).
for name in libopenmpi3 openmpi-bin libglfw3; do
  [[ ! -e "$root/var/lib/dpkg/info/$name.list" && ! -e "$root/var/lib/dpkg/info/$name:$(dpkg --print-architecture).list" ]] ||
    { echo "clean-root: installing sansui installed $name" >&2; exit 1; }
done
in_root "$root" sh -c 'cd /tmp && sansui --version && sansui terrain --size 129 --seed 7 -o /tmp/h.png --quiet &&
  sansui render /tmp/h.png -o /tmp/picture.png --quiet'
picture=$root/tmp/picture.png
[[ -s "$picture" && "$(head -c 8 "$picture" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
  { echo "clean-root: sansui render wrote no PNG" >&2; exit 1; }
if command -v identify >/dev/null; then
  # A picture, not a blank: its pixels differ (ImageMagick's standard deviation of the values).
  spread=$(identify -format '%[fx:standard_deviation]' "$picture")
  say "picture: $(identify -format '%wx%h' "$picture"), standard deviation $spread"
  awk -v spread="$spread" 'BEGIN { exit !(spread > 0.01) }' || { echo "clean-root: the picture is blank" >&2; exit 1; }
fi
cp "$picture" "${SANSUI_CLEAN_ROOT_PICTURE:-$work/picture.png}"
say "sansui render drew $(du -h "$picture" | cut -f1) in the clean root"

# 5. The other packages: each installs with its Depends and runs.
others=()
for name in python3-sansui sansui-viewer sansui-mpi; do
  deb=$(find "$root/tmp/debs" -name "${name}_*.deb")
  [[ -n "$deb" ]] && others+=("/tmp/debs/$(basename "$deb")")
done
in_root "$root" apt-get install -y -qq --no-install-recommends "${others[@]}" >"$work/apt-others.log" 2>&1 ||
  { cat "$work/apt-others.log"; exit 1; }
say "apt installed ${others[*]##*/}"
if [[ -x "$root/usr/bin/python3" && -d "$root/usr/lib/python3/dist-packages/sansui" ]]; then
  in_root "$root" python3 -c "import sansui; h = sansui.midpoint(size=33, seed=1); print('python3-sansui:', sansui.__version__, h.shape)"
fi
if [[ -x "$root/usr/bin/sansui-viewer" ]]; then
  in_root "$root" sansui-viewer --version
fi
if [[ -x "$root/usr/bin/mpirun" ]]; then
  cat >"$root/tmp/world.toml" <<'EOF'
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
  in_root "$root" sh -c 'cd /tmp && mpirun --allow-run-as-root --oversubscribe -q -np 2 sansui run world.toml --out-dir mpi-out --quiet &&
    ls mpi-out'
  say "sansui-mpi: a tiled world over two ranks"
fi
dev=$(find "$root/tmp/debs" -name 'sansui-dev_*.deb')
if [[ -n "$dev" ]]; then
  in_root "$root" apt-get install -s --no-install-recommends "/tmp/debs/$(basename "$dev")" >"$work/apt-dev.log" 2>&1 ||
    { cat "$work/apt-dev.log"; exit 1; }
  say "sansui-dev: apt resolves its Depends ($(grep -c '^Inst ' "$work/apt-dev.log") packages)"
fi
say "done"
