# Helpers of the tests that run in a clean Debian 12 root (sourced, not run): a base root made
# once by debootstrap (minbase) from Debian's archive and kept in $SANSUI_TEST_ROOT_CACHE
# (default /var/cache/sansui-test-root, outside the repository), commands run inside a root with
# /proc, /sys and /dev mounted, and roots removed without deleting through a mount.
# The sourcing script sets `name` (its prefix in messages) first.
cache=${SANSUI_TEST_ROOT_CACHE:-/var/cache/sansui-test-root}
mirror=${SANSUI_DEBIAN_MIRROR:-http://deb.debian.org/debian}
security=${SANSUI_DEBIAN_SECURITY:-http://deb.debian.org/debian-security}
base=$cache/bookworm
started=$SECONDS
say() { echo "$name: [$((SECONDS - started)) s] $*"; }

# Runs a command in a root with /proc, /sys and /dev mounted and the host's resolver; unmounts after.
in_root() {  # ROOT COMMAND...
  local root=$1
  shift
  mount -t proc proc "$root/proc"
  mount -t sysfs sysfs "$root/sys"
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
    echo "$name: $dir still has mounts; left in place" >&2
    return 1
  fi
  rm -rf --one-file-system "$dir"
}

# The base root, once: debootstrap's minbase of bookworm with the updates and security
# suites (the build's libraries are the host's, at their point releases), and apt's lists.
# Another run making it at the same time waits for it (flock).
make_base_root() {
  mkdir -p "$cache"
  exec 9>"$cache/.lock"
  flock 9
  if [[ ! -x "$base/usr/bin/apt-get" ]]; then
    say "making the base root $base (debootstrap, once)"
    remove_root "$base.new"
    debootstrap --variant=minbase bookworm "$base.new" "$mirror" >"$cache/debootstrap.log" 2>&1 ||
      { tail -30 "$cache/debootstrap.log"; exit 1; }
    printf 'deb %s bookworm main\ndeb %s bookworm-updates main\ndeb %s bookworm-security main\n' \
      "$mirror" "$mirror" "$security" >"$base.new/etc/apt/sources.list"
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
}
