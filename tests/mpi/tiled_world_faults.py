#!/usr/bin/python3
"""A tiled world over MPI ranks: a killed rank, a memory cap per rank, and bad input.

Usage: tiled_world_faults.py SANSUI WORK_DIR

1. A rank killed partway fails the whole run, leaves no VRT, and a rerun gives the untiled bytes.
2. A world whose untiled run takes more memory than a cap builds on 4 ranks under that cap each
   (peak resident memory measured per process), with --max-memory set to the cap.
3. Bad input ends every rank with one line naming what is allowed, and no VRT.
"""
import os
import pathlib
import pty
import resource
import shutil
import signal
import subprocess
import sys
import time

import numpy as np
from osgeo import gdal

gdal.UseExceptions()
sansui, work = sys.argv[1], pathlib.Path(sys.argv[2])
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe"]


def recipe(size, tile_size, tiled, extra=""):
    ext = "vrt" if tiled else "tif"
    return (f'sansui_recipe = 4\nsource = "midpoint"\n\n[world]\nsize = {size}\ntile_size = {tile_size}\n'
            f'{"tiled = true" if tiled else ""}\n{extra}\n[[shape]]\nstep = "erode"\n\n'
            f'[[output]]\nfile = "heights.{ext}"\nkind = "heightmap"\n\n[[output]]\nfile = "flow.{ext}"\nkind = "flow_map"\n')


def values(path):
    dataset = gdal.Open(str(path))
    return dataset.GetRasterBand(1).ReadAsArray()


def same_as_untiled(tiled_dir, whole_dir):
    for name in ("heights", "flow"):
        a, b = values(whole_dir / f"{name}.tif"), values(tiled_dir / f"{name}.vrt")
        assert np.array_equal(a.view(np.uint32), b.view(np.uint32)), f"{tiled_dir}: {name} differs from the untiled world"


def peak_kb(command):
    """Runs `command`; its exit code and the peak resident memory of its process (kB)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    code = subprocess.call(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return code, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, before


shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)

# 1. Kill a rank partway, then rerun.
(work / "whole.toml").write_text(recipe(1025, 257, False))
(work / "tiled.toml").write_text(recipe(1025, 257, True))
subprocess.run([sansui, "run", str(work / "whole.toml"), "--out-dir", str(work / "whole")], check=True, capture_output=True)
out = work / "killed"
run = subprocess.Popen(MPIRUN + ["-np", "4", sansui, "run", str(work / "tiled.toml"), "--out-dir", str(out)],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
victim = None
for _ in range(200):  # the ranks start within a few seconds
    found = subprocess.run(["pgrep", "-f", f"{sansui} run {work / 'tiled.toml'}"], capture_output=True, text=True).stdout.split()
    ranks = [int(p) for p in found if int(p) != run.pid]
    if len(ranks) >= 4:
        victim = ranks[1]
        break
    time.sleep(0.05)
assert victim is not None, "the ranks did not start"
time.sleep(1.0)
os.kill(victim, signal.SIGKILL)
code = run.wait(timeout=120)
assert code != 0, "a run with a killed rank must fail"
assert not list(out.glob("*.vrt")), "a failed run must leave no VRT"
subprocess.run(MPIRUN + ["-np", "4", sansui, "run", str(work / "tiled.toml"), "--out-dir", str(out)], check=True, capture_output=True)
same_as_untiled(out, work / "whole")
print("a killed rank fails the run without a VRT; the rerun gives the untiled bytes")

# 2. A memory cap the untiled run cannot meet, met by each of 4 ranks.
(work / "whole2049.toml").write_text(recipe(2049, 513, False))
(work / "tiled2049.toml").write_text(recipe(2049, 513, True))
code, whole_peak, _ = peak_kb([sansui, "run", str(work / "whole2049.toml"), "--out-dir", str(work / "whole2049")])
assert code == 0
cap_kb = 250_000
assert whole_peak > cap_kb, f"the untiled run's peak {whole_peak} kB should exceed the cap {cap_kb} kB"
# Each rank writes its peak to its own file: the ranks' standard outputs interleave.
peaks_dir = work / "peaks"
peaks_dir.mkdir()
wrapper = ("import resource,subprocess,sys,os;c=subprocess.call(sys.argv[1:]);"
           f"open('{peaks_dir}/'+os.environ['OMPI_COMM_WORLD_RANK'],'w').write(str(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss));"
           "sys.exit(c)")
result = subprocess.run(MPIRUN + ["-np", "4", "/usr/bin/python3", "-c", wrapper, sansui, "--max-memory", str(cap_kb / 1e6), "run",
                                  str(work / "tiled2049.toml"), "--out-dir", str(work / "capped")], capture_output=True, text=True)
assert result.returncode == 0, result.stdout + result.stderr
peaks = [int(p.read_text()) for p in sorted(peaks_dir.iterdir())]
assert len(peaks) == 4 and max(peaks) < cap_kb, f"rank peaks {peaks} kB against the cap {cap_kb} kB"
same_as_untiled(work / "capped", work / "whole2049")
print(f"untiled peak {whole_peak} kB > cap {cap_kb} kB; 4 ranks peak {peaks} kB, each under it")

# 3. Bad input: one line for the whole run (rank 0's), exit 2, no MPI_ABORT, no VRT; with
# mpirun -q (docs/worlds.md), nothing else on stderr. Caught when the recipe is read (a key that
# is not there, a tile size no 2^m+1), or by checks every rank makes together.
cases = {
    "unknown key": (recipe(257, 65, True).replace("[world]", "colour = 1\n[world]"), [], "unknown key"),
    "tile size that is no 2^m+1": (recipe(1025, 505, True), [], "must be 2^m+1"),
    "tile larger than the world": (recipe(257, 513, True), [], "between 3 and the world size"),
    "share over the memory cap": (recipe(1025, 513, True), ["--max-memory", "0.001"], "more than the memory limit"),
    "unwritable output folder": (recipe(257, 65, True), [], "not writable by every rank"),
    "a VRT without its kind": (recipe(257, 65, True).replace('kind = "flow_map"\n', ""), [], "flow.vrt: give its kind"),
}
for label, (text, options, expected) in cases.items():
    path = work / "bad.toml"
    path.write_text(text)
    out = pathlib.Path("/proc/version/out") if "unwritable" in label else work / "bad"
    result = subprocess.run(MPIRUN + ["-q", "-np", "2", sansui] + options + ["run", str(path), "--out-dir", str(out)], capture_output=True,
                            text=True)
    assert result.returncode == 2, f"{label}: exit {result.returncode}: {result.stderr}"
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("sansui:") and expected in lines[0], f"{label}: {result.stderr}"
    assert "MPI_ABORT" not in result.stderr, f"{label}: bad input found by every rank must end them cleanly: {result.stderr}"
    assert not list(work.glob("bad/*.vrt")), label
    print(f"{label}: {lines[0]}")

# More ranks than tiles: a warning, idle ranks, and the same world.
(work / "small.toml").write_text(recipe(257, 129, True))
result = subprocess.run(MPIRUN + ["-np", "5", sansui, "run", str(work / "small.toml"), "--out-dir", str(work / "idle")], capture_output=True,
                        text=True)
assert result.returncode == 0, result.stderr
assert "5 ranks for 4 tiles: 1 ranks stay idle" in result.stderr, result.stderr
print("more ranks than tiles: a warning, and the world is built")

# Progress: rank 0 alone shows the whole world's, as a bar when mpirun runs on a terminal (a
# pseudo-terminal here; each rank's stderr to a file of its own, so that who drew what shows), and
# as plain lines in a log.

(work / "progress.toml").write_text(recipe(1025, 257, True))
logs = work / "progress-logs"
command = MPIRUN + ["-np", "2", "--output-filename", str(logs), sansui, "run", str(work / "progress.toml"), "--out-dir",
                    str(work / "progress")]
status = pty.spawn(command, lambda fd: os.read(fd, 1 << 16))
assert os.waitstatus_to_exitcode(status) == 0, status
streams = {rank: (next(logs.glob(f"*/rank.{rank}/stderr")).read_bytes() if list(logs.glob(f"*/rank.{rank}/stderr")) else b"")
           for rank in (0, 1)}
assert b"\rworld" in streams[0] and b"[" in streams[0], f"rank 0 drew no bar: {streams[0][:300]!r}"
assert b"world" not in streams[1], f"rank 1 reported progress too: {streams[1][:300]!r}"
piped = subprocess.run(MPIRUN + ["-np", "2", sansui, "run", str(work / "progress.toml"), "--out-dir", str(work / "progress-piped")],
                       capture_output=True, text=True)
assert piped.returncode == 0, piped.stderr
world_lines = [line for line in piped.stderr.splitlines() if line.startswith("sansui: world")]
assert world_lines and all("\r" not in line for line in world_lines), piped.stderr
assert len([line for line in piped.stdout.splitlines() if "MB sent" in line]) == 1, piped.stdout
print(f"progress: one bar on a terminal (rank 0's), {len(world_lines)} plain lines in a log")
