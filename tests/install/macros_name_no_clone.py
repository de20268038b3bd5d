#!/usr/bin/env python3
"""Only tests/test_paths.cpp and bench/bench_paths.cpp are compiled with a macro that holds the
clone's or the build's path (compile_commands.json).

ccache's base directory makes a compile in one clone hit the cache of another by rewriting the
paths that start an argument (-I/clone/src); a path inside a macro's value (-DX="/clone/...")
stays, so every object compiled with one misses the cache in each fresh clone. CI builds fresh
clones: one such macro on every test object cost about 7 minutes of each run.

Usage: macros_name_no_clone.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import shlex
import sys

ALLOWED = {"tests/test_paths.cpp", "bench/bench_paths.cpp"}


def macros(command):
    words = shlex.split(command)
    for i, word in enumerate(words):
        if word == "-D" and i + 1 < len(words):
            yield words[i + 1]
        elif word.startswith("-D"):
            yield word[2:]


def main():
    build, source = (os.path.realpath(p) for p in sys.argv[1:3])
    with open(os.path.join(build, "compile_commands.json")) as f:
        entries = json.load(f)
    found = []
    for entry in entries:
        file = os.path.realpath(entry["file"])
        relative = os.path.relpath(file, source)
        if relative in ALLOWED:
            continue
        command = entry.get("command") or shlex.join(entry["arguments"])
        for macro in macros(command):
            if source in macro or build in macro:
                found.append(f"{relative}: -D{macro}")
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} compiles name the clone in a macro: ccache misses them in every fresh clone; "
              "give the path through tests/test_paths.hpp or bench/bench_paths.hpp")
        return 1
    print(f"{len(entries)} compiles: only the path files name the clone in a macro")
    return 0


if __name__ == "__main__":
    sys.exit(main())
