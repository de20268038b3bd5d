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
cache=${SANSUI_TEST_ROOT_CACHE:-/var/cache/sansui-test-root}
mirror=${SANSUI_DEBIAN_MIRROR:-http://deb.debian.org/debian}
security=${SANSUI_DEBIAN_SECURITY:-http://deb.debian.org/debian-security}
base=$cache/bookworm
started=$SECONDS
say() { echo "clean-root: [$((SECONDS - started)) s] $*"; }

# Runs a command in a root with /proc and /dev mounted and the host's resolver; unmounts after.
in_root() {  # ROOT COMMAND...
  local root=$1
  shift
  mount -t proc proc "$root/proc"
  mount --rbind /dev "$root/dev"
  mount --make-rslave "$root/dev"
  cp /etc/resolv.conf "$root/etc/resolv.conf"
  local status=0
  chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive \
    "$@" || status=$?
  unmount_all "$root"
  return "$status"
}
unmount_all() {  # ROOT: unmounts everything under it, deepest first
  local root=$1 target
  while read -r target; do
    umount -l "$target" 2>/dev/null || true
  done < <(findmnt -rn -o TARGET | grep -F "$root/" | sort -r)
}
# Removes a root only when nothing is mounted under it any more (a bound /dev must never be
# deleted through), and never across file systems.
remove_root() {  # DIR
  local dir=$1
  [[ -d "$dir" ]] || return 0
  unmount_all "$dir"
  if findmnt -rn -o TARGET | grep -qF "$dir/"; then
    echo "clean-root: $dir still has mounts; left in place" >&2
    return 1
  fi
  rm -rf --one-file-system "$dir"
}

# 1. The base root, once: debootstrap's minbase of bookworm with the updates and security
# suites (the build's libraries are the host's, at their point releases), and apt's lists.
# Another run making it at the same time waits for it (flock).
mkdir -p "$cache"
exec 9>"$cache/.lock"
flock 9
if [[ ! -x "$base/usr/bin/apt-get" ]]; then
  say "making the base root $base (debootstrap, once)"
  remove_root "$base.new"
  debootstrap --variant=minbase bookworm "$base.new" "$mirror" >"$cache/debootstrap.log" 2>&1 ||
    { tail -30 "$cache/debootstrap.log"; exit 1; }
  cat >"$base.new/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb $security bookworm-security main
EOF
  # No service starts inside the root (policy-rc.d), and apt keeps no downloaded .debs.
  printf '#!/bin/sh\nexit 101\n' >"$base.new/usr/sbin/policy-rc.d"
  chmod 755 "$base.new/usr/sbin/policy-rc.d"
  echo 'Binary::apt::APT::Keep-Downloaded-Packages "false";' >"$base.new/etc/apt/apt.conf.d/01sansui-test"
  in_root "$base.new" apt-get update -qq
  in_root "$base.new" apt-get clean
  mv "$base.new" "$base"
  say "base root made ($(du -sh "$base" | cut -f1))"
fi
flock -u 9
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
