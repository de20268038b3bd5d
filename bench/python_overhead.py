#!/usr/bin/python3
"""The Python module's cost over the library (issue 33: under 2 % of the in-process time).

Times sansui.midpoint(size=1025) from Python and the same node run in C++ (bench_evaluator's
NodeMidpoint1025), in one session, each as the median of REPETITIONS runs, and prints both and
the overhead. Also the peak memory of making a 4097² terrain from Python, in grids.

Usage: PYTHONPATH=build/python bench/python_overhead.py [BUILD_DIR] [REPETITIONS]
"""
import json
import pathlib
import resource
import statistics
import subprocess
import sys
import time

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build")
repetitions = int(sys.argv[2]) if len(sys.argv) > 2 else 9

import sansui  # noqa: E402


def python_seconds():
    for _ in range(5):  # warm: the thread pool, the allocator, the caches
        sansui.midpoint(size=1025)
    times = []
    for _ in range(10 * repetitions):  # as many calls as Google Benchmark makes of the reference
        start = time.perf_counter()
        sansui.midpoint(size=1025)
        times.append(time.perf_counter() - start)
    return times


def library_seconds():
    done = subprocess.run(
        [str(build / "bench" / "bench_evaluator"), "--benchmark_filter=NodeMidpoint1025", f"--benchmark_repetitions={repetitions}",
         "--benchmark_format=json"], capture_output=True, text=True, check=True)
    runs = json.loads(done.stdout)["benchmarks"]
    return [r["real_time"] / 1000.0 for r in runs if r.get("run_type") == "iteration"]


def fixed_cost_seconds():
    """A call that does almost nothing (a 3x3 constant): what the binding itself costs per call."""
    times = []
    for _ in range(200):
        start = time.perf_counter()
        sansui.constant(size=3)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def peak_grids():
    statm = lambda: int(open("/proc/self/statm").read().split()[1]) * resource.getpagesize()  # noqa: E731
    before = statm()
    sansui.midpoint(size=4097, seed=1)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    return (peak - before) / (4097 * 4097 * 4)


library, python = [], []
for _ in range(2):  # interleaved, so that both see the same load
    library += library_seconds()
    python += python_seconds()
lib, py = statistics.median(library), statistics.median(python)
print(f"library  NodeMidpoint1025  median {lib * 1e3:7.2f} ms  (spread {min(library) * 1e3:.2f}-{max(library) * 1e3:.2f})")
print(f"python   sansui.midpoint   median {py * 1e3:7.2f} ms  (spread {min(python) * 1e3:.2f}-{max(python) * 1e3:.2f})")
print(f"overhead {(py - lib) * 1e3:+.3f} ms = {100 * (py - lib) / lib:+.2f} % of the library's time (goal under 2 %)")
fixed = fixed_cost_seconds()
print(f"the binding's own cost per call (sansui.constant(size=3)): {fixed * 1e6:.1f} us = {100 * fixed / lib:.2f} % of the 1025² midpoint")
print(f"peak memory of making a 4097² terrain: {peak_grids():.3f} grids over the process before it (goal at most 1.10)")
