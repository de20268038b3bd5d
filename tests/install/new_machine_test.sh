#!/usr/bin/env bash
# The README's two commands on a brand-new Debian 12 machine: a copy of the debootstrap root
# (debian_root.sh) gets a clone of the repository's HEAD, then, as root and in that order,
# `scripts/main-job` (apt, build, the scene into out/) and `scripts/test` (apt for the tests,
# build, the whole CTest suite). Both must pass; the main job's three pictures and models must
# be in out/; the suite must hold as many tests as this machine's build/ (a build folder
# configured before `scripts/setup --test` installed pybind11, MPI and Blender would hold fewer)
# and none of its Python, MPI or Blender tests may be skipped. Each command is timed, apt
# included. `--test-first` runs them in the other order; `--main-job` runs the main job alone (to
# time it on a brand-new machine).
#
# Needs root (chroot, mount) and Debian's archive over the network; it compiles everything from
# nothing (no ccache of this machine's) and runs the suite, so it takes most of an hour on two
# cores: run by hand, not by CTest. Usage: tests/install/new_machine_test.sh [--test-first | --main-job]
set -euo pipefail
order=(main-job test)
case "${1:-}" in
  --test-first) order=(test main-job) ;;
  --main-job) order=(main-job) ;;
esac
name=new-machine
[[ $(id -u) -eq 0 ]] || { echo "$name: needs root (debootstrap, chroot, mount)" >&2; exit 77; }
for tool in debootstrap chroot git; do
  command -v "$tool" >/dev/null || { echo "$name: $tool is missing" >&2; exit 77; }
done
repo=$(cd "$(dirname "$0")/../.." && pwd)
source "$repo/tests/install/debian_root.sh"
make_base_root

work=$(mktemp -d "${TMPDIR:-/var/tmp}/sansui-new-machine-XXXXXX")
root=$work/root
trap 'remove_root "$root"; rm -rf "$work"' EXIT
cp -a "$base" "$root"
git clone -q "$repo" "$root/root/sansui"
say "a clean root with a clone of $(git -C "$repo" rev-parse --short HEAD)"

for command in "${order[@]}"; do
  begun=$SECONDS
  in_root "$root" sh -c "cd /root/sansui && scripts/$command" >"$work/$command.log" 2>&1 ||
    { tail -60 "$work/$command.log"; [[ -z "${SANSUI_NEW_MACHINE_LOGS:-}" ]] || cp "$work/$command.log" "$SANSUI_NEW_MACHINE_LOGS/"; echo "$name: scripts/$command failed" >&2; exit 1; }
  say "scripts/$command passed in $((SECONDS - begun)) s"
  [[ -z "${SANSUI_NEW_MACHINE_LOGS:-}" ]] || cp "$work/$command.log" "$SANSUI_NEW_MACHINE_LOGS/"
done

# The main job's outputs.
for file in tropical-coast.png tropical-coast-heightmap.png tropical-coast.glb; do
  [[ -s "$root/root/sansui/out/$file" ]] || { echo "$name: the main job wrote no out/$file" >&2; exit 1; }
done
grep -h "^main-job: " "$work/main-job.log" || true
[[ -f "$work/test.log" ]] || { say "done"; exit 0; }
# The whole suite ran: as many tests as this machine's build, none of the optional parts skipped.
total=$(grep -oE 'tests failed out of [0-9]+' "$work/test.log" | tail -1 | grep -oE '[0-9]+$')
say "the suite ran $total tests"
if [[ -f "$repo/build/CTestTestfile.cmake" ]]; then
  expected=$(cd "$repo/build" && ctest -N | grep -oE 'Total Tests: [0-9]+' | grep -oE '[0-9]+')
  [[ "$total" == "$expected" ]] || { echo "$name: the suite ran $total tests; this machine's build/ has $expected" >&2; exit 1; }
fi
if grep -E '(Python|Mpi|Blender)\.[^ ]* \.+\*+Skipped' "$work/test.log"; then
  echo "$name: Python, MPI or Blender tests were skipped" >&2
  exit 1
fi
say "done"
