#!/usr/bin/env python3
"""Every file the build's configure found comes from a package scripts/setup installs.

A development machine holds packages that a brand-new Debian 12 does not, so a library the build
finds there only through an unrelated package (libOpenGL.so came with libglvnd-dev) configures
here and fails on a new machine. This reads the paths CMake found (CMakeCache.txt: libraries,
headers, config folders and programs under /usr), asks dpkg which package owns each, and checks
that the owner is one scripts/setup installs or one apt brings with them: their Depends and
Pre-Depends, with apt's choice among alternatives (scripts/setup installs without Recommends), or a package of debootstrap's minimal base (Essential or Priority
required). The whole install on a clean root is tests/install/new_machine_test.sh, by hand.

Usage: setup_covers_build.py BUILD_DIR [PACKAGE ...]   (default: `scripts/setup --list`)
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path


# Cache entries of things CMake looks for whether or not the build needs them: GLU (FindOpenGL
# always looks for it; Sansui does not link it), and the archiver, linker and binary tools, which
# CMake takes from the compiler's family when they are there (llvm-ar beside clang) and from
# binutils, which build-essential brings, when not.
UNUSED = re.compile(r"^(OPENGL_glu_LIBRARY|CMAKE_(ADDR2LINE|AR|DLLTOOL|LINKER|NM|OBJCOPY|OBJDUMP|RANLIB|READELF|STRIP))$")


def found_paths(cache: Path, ignore: list[Path]) -> list[str]:
    """Paths under /usr that CMake found and cached (FILEPATH and PATH entries)."""
    paths = set()
    for line in cache.read_text(errors="replace").splitlines():
        match = re.match(r"^([A-Za-z0-9_.+-]+):(FILEPATH|PATH)=(/usr/.+)$", line)
        if not match or UNUSED.match(match.group(1)):
            continue
        for value in match.group(3).split(";"):
            path = Path(value)
            if path.exists() and not any(path.is_relative_to(folder) for folder in ignore):
                paths.add(str(path))
    return sorted(paths)


def owners(paths: list[str]) -> dict[str, set[str]]:
    """The packages dpkg says own each path (or the file it links to); unowned paths are left out."""
    found: dict[str, set[str]] = {}
    queries = {path: [path, os.path.realpath(path)] for path in paths}
    names = sorted({name for both in queries.values() for name in both})
    out = subprocess.run(["dpkg", "-S", *names], capture_output=True, text=True).stdout
    by_name: dict[str, set[str]] = {}
    for line in out.splitlines():
        if line.startswith("diversion "):
            continue
        packages, _, name = line.partition(": ")
        by_name.setdefault(name, set()).update(p.strip().split(":")[0] for p in packages.split(","))
    for path, both in queries.items():
        packages = by_name.get(both[0]) or by_name.get(both[1])
        if packages:
            found[path] = packages
    return found


def clauses(field: str) -> list[list[str]]:
    """A Depends-like field as its clauses, each the list of its alternatives (versions and archs
    stripped)."""
    result = []
    for clause in filter(None, (c.strip() for c in field.split(","))):
        names = [a.strip().split(" ")[0].split(":")[0] for a in clause.split("|")]
        result.append([name for name in names if name])
    return result


def installed_closure(roots: list[str]) -> set[str]:
    """The installed packages apt brings with `roots`, plus debootstrap's minimal base.

    As apt does, a clause with alternatives is met by one already coming, else by its first
    alternative (a virtual package by its installed provider). Clauses without alternatives are
    followed first, so an alternative that comes anyway is seen before one is chosen."""
    out = subprocess.run(
        ["dpkg-query", "-W", "-f=${Package}\t${Status}\t${Essential}\t${Priority}\t${Depends}\t${Pre-Depends}\t${Provides}\n"],
        capture_output=True, text=True, check=True).stdout
    depends: dict[str, list[list[str]]] = {}
    providers: dict[str, list[str]] = {}
    base = []
    for line in out.splitlines():
        package, status, essential, priority, deps, pre, provides = (line.split("\t") + [""] * 7)[:7]
        if not status.endswith(" installed"):
            continue
        depends[package] = clauses(deps) + clauses(pre)
        for virtual in clauses(provides):
            providers.setdefault(virtual[0], []).append(package)
        if essential == "yes" or priority == "required":
            base.append(package)

    def real(name: str) -> list[str]:
        return [name] if name in depends else sorted(providers.get(name, ()))

    seen: set[str] = set()

    def follow(names: list[str]) -> None:  # adds these and every clause without alternatives
        stack = list(names)
        while stack:
            for package in real(stack.pop())[:1]:
                if package not in seen:
                    seen.add(package)
                    stack.extend(clause[0] for clause in depends[package] if len(clause) == 1)

    follow([*roots, *base])
    while True:
        unmet = [clause for package in sorted(seen) for clause in depends[package]
                 if len(clause) > 1 and not any(set(real(name)) & seen for name in clause)]
        if not unmet:
            return seen
        follow([next((name for name in unmet[0] if real(name)), unmet[0][0])])


def main() -> int:
    if not shutil.which("dpkg-query"):
        print("setup-covers-build: not a Debian system (no dpkg-query): skipped", file=sys.stderr)
        return 77
    build = Path(sys.argv[1]).resolve()
    source = Path(__file__).resolve().parents[2]
    roots = sys.argv[2:] or subprocess.run([str(source / "scripts/setup"), "--list"], capture_output=True, text=True,
                                           check=True).stdout.split()
    paths = found_paths(build / "CMakeCache.txt", [build, source])
    owned = owners(paths)
    allowed = installed_closure(roots)
    strays = {path: packages for path, packages in owned.items() if not packages & allowed}
    print(f"setup-covers-build: {len(paths)} paths found by CMake, {len(owned)} owned by packages, "
          f"{len(allowed)} packages come with scripts/setup's {len(roots)}")
    for path, packages in sorted(strays.items()):
        print(f"setup-covers-build: {path} comes from {', '.join(sorted(packages))}, which scripts/setup does not install "
              "(a brand-new machine lacks it): add it to scripts/setup", file=sys.stderr)
    return 1 if strays else 0


if __name__ == "__main__":
    sys.exit(main())
