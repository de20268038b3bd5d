#!/usr/bin/env bash
# The README's two commands on a brand-new Debian 12 machine: a copy of the debootstrap root
# (debian_root.sh) gets a clone of the repository's HEAD, then, as root and in that order,
# `scripts/main-job` (apt, build, the scene into out/) and `scripts/test` (apt for the tests,
# build, the whole CTest suite). Both must pass; the main job's three pictures and models must
# be in out/; the suite's Python, MPI, Blender and browser tests must have run and passed (a build
# folder configured before `scripts/setup --test` installed their packages would hold none).
# Each command is timed, apt included. `--test-first` runs them in the other order; `--main-job`
# runs the main job alone (to time it on a brand-new machine).
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

# A machine behind this one's TLS-inspecting proxy trusts its CAs (the browser test's npm ci
# fetches from the npm registry): the host's local CAs, given to node.
extra_ca=()
if compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null; then
  cat /usr/local/share/ca-certificates/*.crt >"$root/root/host-ca.crt"
  extra_ca=(NODE_EXTRA_CA_CERTS=/root/host-ca.crt)
fi
for command in "${order[@]}"; do
  begun=$SECONDS
  in_root "$root" env "${extra_ca[@]}" sh -c "cd /root/sansui && scripts/$command" >"$work/$command.log" 2>&1 ||
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
# The whole suite ran, the optional parts' tests too: each has tests that passed, none skipped.
total=$(grep -oE 'tests failed out of [0-9]+' "$work/test.log" | tail -1 | grep -oE '[0-9]+$')
say "the suite ran $total tests"
for part in Python Mpi Blender Web; do
  grep -qE "Test +#[0-9]+: $part\.[^ ]* \.+ +Passed" "$work/test.log" || { echo "$name: no $part test passed" >&2; exit 1; }
done
if grep -E '(Python|Mpi|Blender|Web)\.[^ ]* \.+\*+Skipped' "$work/test.log"; then
  echo "$name: Python, MPI, Blender or browser tests were skipped" >&2
  exit 1
fi
say "done"
