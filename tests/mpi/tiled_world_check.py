#!/usr/bin/python3
"""A tiled world gives the untiled world's bytes, in one process and on 1, 2 and 4 MPI ranks.

Usage: tiled_world_check.py SANSUI WORK_DIR SIZE TILE_SIZE[,TILE_SIZE...] [RANKS...]

Writes the same eroded midpoint world untiled (one GeoTIFF per output) and tiled (GeoTIFF tiles
under a VRT) without MPI and under `mpirun -np N` for each N; with more tile sizes, the untiled
world is made once and each further tiling runs on the most ranks only. Every VRT must read back, through
GDAL, as the untiled GeoTIFF's very values, the rivers and lakes GeoJSON must be the untiled files
byte for byte, each splat-map tile the untiled splat map's pixels there, and the tiles of every
run must be the same files.
"""
import filecmp
import pathlib
import shutil
import subprocess
import sys

import numpy as np
from osgeo import gdal

gdal.UseExceptions()
sansui, work, size = sys.argv[1], pathlib.Path(sys.argv[2]), int(sys.argv[3])
tile_sizes = [int(t) for t in sys.argv[4].split(",")]
ranks = [int(r) for r in sys.argv[5:]]
OUTPUTS = {"heights": "heightmap", "flow": "flow_map", "eroded": "erosion_map", "deposited": "deposition_map"}
JOINED = ["rivers", "lakes"]  # one GeoJSON each, joined across tiles


def recipe(tiled, tile_size):
    lines = ['source = "midpoint"', "", "[world]", f"size = {size}", f"tile_size = {tile_size}"]
    lines += ["tiled = true"] if tiled else []
    lines += ["", "[[shape]]", 'step = "erode"']
    for name, kind in OUTPUTS.items():
        lines += ["", "[[output]]", f'file = "{name}.{"vrt" if tiled else "tif"}"', f'kind = "{kind}"']
    for name in JOINED:
        lines += ["", "[[output]]", f'file = "{name}.geojson"', f'kind = "{name}"']
    lines += ["", "[[output]]", 'file = "splat.png"', 'kind = "splat_map"']
    return "\n".join(lines) + "\n"


def run(command, out):
    result = subprocess.run(command + ["--out-dir", str(out)], capture_output=True, text=True)
    assert result.returncode == 0, f"{' '.join(command)} failed:\n{result.stdout}\n{result.stderr}"


def rgba(path):
    dataset = gdal.Open(str(path))
    return np.stack([dataset.GetRasterBand(b + 1).ReadAsArray() for b in range(dataset.RasterCount)])


def values(path):
    dataset = gdal.Open(str(path))  # kept while its band is read: GDAL frees the band with it
    return dataset.GetRasterBand(1).ReadAsArray()


def check_tiling(tile_size, ranks):
    (work / "tiled.toml").write_text(recipe(True, tile_size))
    runs = {"one process": [sansui, "run", str(work / "tiled.toml")]} if len(ranks) > 1 else {}
    for n in ranks:
        runs[f"{n} ranks"] = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(n), sansui, "run", str(work / "tiled.toml")]
    first = None
    for label, command in runs.items():
        out = work / f"tiles_of_{tile_size}_{label.replace(' ', '_')}"
        run(command, out)
        label = f"tiles of {tile_size}, {label}"
        for name in OUTPUTS:
            whole, tiled = values(work / "whole" / f"{name}.tif"), values(out / f"{name}.vrt")
            assert whole.shape == tiled.shape == (size, size), (label, name, whole.shape, tiled.shape)
            differing = int(np.count_nonzero(whole.view(np.uint32) != tiled.view(np.uint32)))
            assert differing == 0, f"{label}: {name}: {differing} samples differ from the untiled world's"
        for name in JOINED:
            assert filecmp.cmp(work / "whole" / f"{name}.geojson", out / f"{name}.geojson", shallow=False), f"{label}: {name} differ"
        # Splat maps: a PNG per tile, the whole world's splat map cut up.
        whole_splat, cells = rgba(work / "whole" / "splat.png"), tile_size - 1
        for tile in out.glob("splat_*_*.png"):
            tx, ty = (int(v) for v in tile.stem.split("_")[1:])
            part = rgba(tile)
            expected = whole_splat[:, ty * cells:ty * cells + part.shape[1], tx * cells:tx * cells + part.shape[2]]
            assert np.array_equal(part, expected), f"{label}: {tile.name} differs from the whole world's splat map there"
        tiles = sorted(p.name for p in out.glob("*.tif"))
        if first is None:
            first = (out, tiles)
        else:
            assert tiles == first[1], (label, "writes other tiles")
            _, mismatch, errors = filecmp.cmpfiles(first[0], out, tiles, shallow=False)
            assert not mismatch and not errors, f"{label}: tiles differ from the first run's: {mismatch + errors}"
        print(f"{label}: {len(tiles)} tiles, every sample the untiled world's; rivers and lakes byte for byte its GeoJSON")


shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
(work / "whole.toml").write_text(recipe(False, tile_sizes[0]))
run([sansui, "run", str(work / "whole.toml")], work / "whole")
for k, tile_size in enumerate(tile_sizes):
    check_tiling(tile_size, ranks if k == 0 else ranks[-1:])
