#!/usr/bin/env bash
# Packages a built tree as a .deb (cpack -G DEB) and installs it with dpkg into an empty root,
# as on a fresh machine: the package's files land under /usr, its Depends name the shared
# libraries the programs need, and the installed sansui runs.
# Usage: tests/install/deb_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/sansui-deb-XXXXXX")
trap 'rm -rf "$work"' EXIT

(cd "$build" && cpack -G DEB -B "$work/package" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb=$(find "$work/package" -maxdepth 1 -name 'sansui_*.deb')
[[ -n "$deb" ]] || { echo "deb: cpack wrote no sansui_*.deb" >&2; cat "$work/cpack.log"; exit 1; }
depends=$(dpkg-deb -f "$deb" Depends)
for library in libc6 libgdal32 libproj25 libtbb12; do
  [[ "$depends" == *"$library"* ]] || { echo "deb: Depends lacks $library: $depends" >&2; exit 1; }
done

# An empty root with an empty package database; dpkg installs the package there (its
# dependencies are the host's, hence --force-depends).
root=$work/root
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates"
touch "$root/var/lib/dpkg/status"
dpkg --root="$root" --force-depends --force-not-root -i "$deb" >"$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; exit 1; }
for file in usr/bin/sansui usr/share/man/man1/sansui.1 usr/share/bash-completion/completions/sansui usr/share/sansui/data/climate.toml; do
  [[ -f "$root/$file" ]] || { echo "deb: $file is not installed" >&2; exit 1; }
done
dpkg --root="$root" -s sansui | grep -q '^Status: install ok installed' || { echo "deb: dpkg does not list sansui as installed" >&2; exit 1; }
"$root/usr/bin/sansui" --version
# The Python module, when the build has it: in Debian's dist-packages, importable from there.
if [[ -d "$build/python/sansui" ]]; then
  site=usr/lib/python3/dist-packages/sansui
  for file in __init__.py __init__.pyi py.typed; do
    [[ -f "$root/$site/$file" ]] || { echo "deb: $site/$file is not installed" >&2; exit 1; }
  done
  PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import sansui, numpy; h = sansui.midpoint(size=33, seed=1); assert h.shape == (33, 33) and h.dtype == numpy.float32; print('deb: import sansui', sansui.__version__)"
fi
echo "deb: $(basename "$deb") ($(du -h "$deb" | cut -f1)) installs into an empty root and runs"
