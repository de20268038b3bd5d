#!/usr/bin/env python3
"""Hostile inputs, one class per run: files and recipes an attacker hands a Sansui user.

Usage: hostile_inputs.py SANSUI WORKDIR CLASS

Each case lays out a folder (the attacker's files) beside a folder of bait (a user's files the
attacker must not reach), runs `sansui` on it under strace (every connect() and every file
opened is recorded), and checks the contract for bad input: exit 2 with one line on stderr, no
file written, no connect() to anything but a local socket, no bait opened or changed, and an end
within a time limit (no hang). Cases that are good input run to exit 0 with the same audit.
"""

import json
import os
import re
import shutil
import stat
import subprocess
import sys
import time

SANSUI, WORK, CLASS = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
failures = []
STRACE = shutil.which("strace")


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAIL: {what}", flush=True)


def fresh(name):
    """A case's root: ROOT/case (the attacker's folder), ROOT/bait (the user's files)."""
    root = os.path.join(WORK, CLASS, name)
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "case", "out"))
    os.makedirs(os.path.join(root, "bait"))
    with open(os.path.join(root, "bait", "secret.asc"), "w") as f:
        f.write(ascii_grid(4, 4, 1234.0))
    return root


def ascii_grid(width, height, value, step=1.0):
    rows = "\n".join(" ".join(f"{value + step * (x + y):g}" for x in range(width)) for y in range(height))
    return f"ncols {width}\nnrows {height}\nxllcorner 0\nyllcorner 0\ncellsize 10\n{rows}\n"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def vrt(width, height, sources, band_attributes=""):
    """A VRT of one band over the given source elements."""
    return (f'<VRTDataset rasterXSize="{width}" rasterYSize="{height}">\n'
            f'  <GeoTransform>0, 10, 0, 40, 0, -10</GeoTransform>\n'
            f'  <VRTRasterBand dataType="Float32" band="1"{band_attributes}>\n{sources}\n  </VRTRasterBand>\n</VRTDataset>\n')


def simple_source(name, relative=1, width=4, height=4):
    return (f'    <SimpleSource><SourceFilename relativeToVRT="{relative}">{name}</SourceFilename><SourceBand>1</SourceBand>'
            f'<SrcRect xOff="0" yOff="0" xSize="{width}" ySize="{height}"/><DstRect xOff="0" yOff="0" xSize="{width}" ySize="{height}"/>'
            f'</SimpleSource>')


def snapshot(folder):
    found = {}
    for base, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(base, name)
            try:
                info = os.lstat(path)
            except FileNotFoundError:
                continue
            found[path] = (info.st_size, info.st_mtime_ns)
    return found


def run(root, args, expect, message=None, timeout=60, cwd=None, env=None, written=None):
    """Runs sansui ARGS in ROOT/case; checks the exit code, the one-line message, the files in
    ROOT/case/out, the bait, and the audit."""
    case = os.path.join(root, "case")
    out = os.path.join(case, "out")
    bait_before = snapshot(os.path.join(root, "bait"))
    out_before = set(os.listdir(out))
    log = os.path.join(root, "strace.log")
    command = [SANSUI, "--progress", "none"] + args
    if STRACE:
        command = [STRACE, "-f", "-qq", "-e", "trace=connect,open,openat,creat,rename,unlink", "-o", log] + command
    label = f"{CLASS}/{os.path.basename(root)}: sansui {' '.join(args)}"
    start = time.monotonic()
    try:
        result = subprocess.run(command, cwd=cwd or case, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=timeout,
                                env=dict(os.environ, **(env or {})))
    except subprocess.TimeoutExpired:
        check(False, f"{label}: still running after {timeout} s (a hang)")
        return None
    seconds = time.monotonic() - start
    print(f"{label}: exit {result.returncode} in {seconds:.1f} s: {result.stderr.strip()[:300]}", flush=True)
    allowed = expect if isinstance(expect, tuple) else (expect,)
    check(result.returncode in allowed, f"{label}: exit {result.returncode}, expected {expect}; stderr: {result.stderr[:500]}")
    if result.returncode == 2:
        lines = result.stderr.strip("\n").split("\n")
        check(len(lines) == 1, f"{label}: {len(lines)} lines on stderr, expected one: {result.stderr[:800]}")
        check("internal error" not in result.stderr, f"{label}: an internal error: {result.stderr[:300]}")
        if message:
            check(message in result.stderr, f"{label}: the message lacks '{message}': {result.stderr[:300]}")
        check(set(os.listdir(out)) == out_before, f"{label}: files left in the output folder: {sorted(set(os.listdir(out)) - out_before)}")
    elif written and result.returncode == 0:
        for name in written:
            check(os.path.exists(os.path.join(out, name)), f"{label}: {name} was not written")
    check(snapshot(os.path.join(root, "bait")) == bait_before, f"{label}: the bait folder changed")
    if STRACE:
        audit(label, root, log)
    return result


def audit(label, root, log):
    bait = os.path.join(root, "bait")
    # /etc/passwd is not among them: Mesa looks up the home folder (getpwuid) for its shader cache.
    forbidden_reads = ("/etc/shadow", "/proc/self/environ")
    with open(log, errors="replace") as f:
        for line in f:
            if " connect(" in line and "AF_UNIX" not in line:
                check(False, f"{label}: a network connection: {line.strip()[:200]}")
            match = re.search(r'(?:open|openat|creat|rename|unlink)\((?:AT_FDCWD, )?"([^"]*)"', line)
            if not match or "ENOENT" in line:
                continue
            path = match.group(1)
            if path.startswith(bait) or path in forbidden_reads or re.match(r"/proc/\d+/environ", path):
                check(False, f"{label}: opened a file it was not given: {line.strip()[:200]}")


def fifo(path):
    if os.path.exists(path):
        os.unlink(path)
    os.mkfifo(path)


# ---- the classes -------------------------------------------------------------------------------


def network():
    """A DEM whose sources are on the network: refused before GDAL sees them, no connect()."""
    for name, source in [("vsicurl", "/vsicurl/http://127.0.0.1:9/dem.tif"), ("http", "http://127.0.0.1:9/dem.tif"),
                         ("vsis3", "/vsis3/bucket/dem.tif"), ("vsigs", "/vsigs/bucket/dem.tif"), ("vsiaz", "/vsiaz/c/dem.tif"),
                         ("wms", "WMS:http://127.0.0.1:9/wms?"), ("vrtconnection", "vrt://dem.asc?bands=1")]:
        root = fresh(name)
        write(os.path.join(root, "case", "dem.vrt"), vrt(4, 4, simple_source(source, relative=0)))
        run(root, ["render", "dem.vrt", "-o", "out/p.png", "--width", "64", "--height", "48"], 2, "dem.vrt")
    # The DEM's own name, given in a recipe and on the command line.
    root = fresh("recipe-url")
    write(os.path.join(root, "case", "r.toml"),
          'sansui_recipe = 4\nsource = "file"\n[file]\npath = "/vsicurl/http://127.0.0.1:9/dem.asc"\n[[output]]\nfile = "out/h.r32"\n')
    run(root, ["run", "r.toml"], 2)
    root = fresh("argument-url")
    run(root, ["render", "/vsis3/bucket/dem.asc", "-o", "out/p.png"], 2)
    # A WMS service description saved as a file with a DEM's extension.
    root = fresh("wms-file")
    write(os.path.join(root, "case", "dem.img"),
          '<GDAL_WMS><Service name="WMS"><ServerUrl>http://127.0.0.1:9/wms?</ServerUrl><Layers>x</Layers></Service>'
          '<DataWindow><UpperLeftX>0</UpperLeftX><UpperLeftY>1</UpperLeftY><LowerRightX>1</LowerRightX><LowerRightY>0</LowerRightY>'
          '<SizeX>64</SizeX><SizeY>64</SizeY></DataWindow></GDAL_WMS>\n')
    run(root, ["render", "dem.img", "-o", "out/p.png", "--width", "64", "--height", "48"], 2)


def local_files():
    """A DEM that reads files it does not hold: raw bands, ../, links, FIFOs, spill files."""
    for name, target in [("passwd", "/etc/passwd"), ("environ", "/proc/self/environ")]:
        root = fresh("raw-" + name)
        band = (f'<VRTDataset rasterXSize="8" rasterYSize="8"><VRTRasterBand dataType="Byte" band="1" subClass="VRTRawRasterBand">'
                f'<SourceFilename relativetoVRT="0">{target}</SourceFilename><ImageOffset>0</ImageOffset><PixelOffset>1</PixelOffset>'
                f'<LineOffset>8</LineOffset></VRTRasterBand></VRTDataset>\n')
        write(os.path.join(root, "case", "dem.vrt"), band)
        write(os.path.join(root, "case", "r.toml"),
              'sansui_recipe = 4\nsource = "file"\n[file]\npath = "dem.vrt"\ncell = 10\n[[output]]\nfile = "out/h.r32"\n')
        run(root, ["run", "r.toml"], 2, "raw band")
    # A source in the folder above the VRT's, relative and absolute.
    root = fresh("parent")
    write(os.path.join(root, "case", "sub", "dem.vrt"), vrt(4, 4, simple_source("../../bait/secret.asc")))
    run(root, ["render", "sub/dem.vrt", "-o", "out/p.png", "--width", "64", "--height", "48"], 2, "outside the VRT's folder")
    root = fresh("absolute")
    write(os.path.join(root, "case", "dem.vrt"), vrt(4, 4, simple_source(os.path.join(root, "bait", "secret.asc"), relative=0)))
    run(root, ["render", "dem.vrt", "-o", "out/p.png", "--width", "64", "--height", "48"], 2, "outside the VRT's folder")
    # A link in the folder to the bait.
    root = fresh("link")
    os.symlink(os.path.join(root, "bait", "secret.asc"), os.path.join(root, "case", "tile.asc"))
    write(os.path.join(root, "case", "dem.vrt"), vrt(4, 4, simple_source("tile.asc")))
    run(root, ["render", "dem.vrt", "-o", "out/p.png", "--width", "64", "--height", "48"], 2, "outside the VRT's folder")
    # A raw band over a FIFO, and a FIFO as a VRT's source: refused at once, no hang.
    root = fresh("fifo-raw")
    fifo(os.path.join(root, "case", "pipe.raw"))
    write(os.path.join(root, "case", "dem.vrt"),
          '<VRTDataset rasterXSize="8" rasterYSize="8"><VRTRasterBand dataType="Byte" band="1" subClass="VRTRawRasterBand">'
          '<SourceFilename relativetoVRT="1">pipe.raw</SourceFilename></VRTRasterBand></VRTDataset>\n')
    run(root, ["render", "dem.vrt", "-o", "out/p.png"], 2, timeout=30)
    root = fresh("fifo-source")
    fifo(os.path.join(root, "case", "pipe.asc"))
    write(os.path.join(root, "case", "dem.vrt"), vrt(4, 4, simple_source("pipe.asc")))
    run(root, ["render", "dem.vrt", "-o", "out/p.png"], 2, timeout=30)
    # A FIFO beside a DEM under a name GDAL reads with it (its .prj), and a DEM that is a FIFO.
    root = fresh("fifo-companion")
    write(os.path.join(root, "case", "dem.asc"), ascii_grid(8, 8, 100.0))
    fifo(os.path.join(root, "case", "dem.prj"))
    run(root, ["render", "dem.asc", "-o", "out/p.png", "--width", "64", "--height", "48"], 2, "dem.prj", timeout=30)
    root = fresh("fifo-dem")
    fifo(os.path.join(root, "case", "dem.asc"))
    run(root, ["render", "dem.asc", "-o", "out/p.png"], 2, timeout=30)
    # Pixel-function code.
    root = fresh("python")
    write(os.path.join(root, "case", "dem.asc"), ascii_grid(4, 4, 100.0))
    write(os.path.join(root, "case", "dem.vrt"),
          vrt(4, 4, simple_source("dem.asc") + "<PixelFunctionLanguage>Python</PixelFunctionLanguage><PixelFunctionType>f</PixelFunctionType>"
              "<PixelFunctionCode><![CDATA[\nimport os\ndef f(*a, **k): os.system('touch /tmp/owned')\n]]></PixelFunctionCode>",
              ' subClass="VRTDerivedRasterBand"'))
    run(root, ["render", "dem.vrt", "-o", "out/p.png"], 2, "pixel-function code")
    # A VRT that names itself.
    root = fresh("cycle")
    write(os.path.join(root, "case", "dem.vrt"), vrt(4, 4, simple_source("dem.vrt")))
    run(root, ["render", "dem.vrt", "-o", "out/p.png"], 2, "cycle")
    # Good input goes on working: a VRT over a tile beside it.
    root = fresh("good")
    write(os.path.join(root, "case", "sub", "tile.asc"), ascii_grid(8, 8, 100.0, 3.0))
    write(os.path.join(root, "case", "dem.vrt"), vrt(8, 8, simple_source("sub/tile.asc", width=8, height=8)))
    run(root, ["render", "dem.vrt", "-o", "out/p.png", "--width", "64", "--height", "48"], 0, written=["p.png"])


def tiled_links():
    """A tiled world never writes through a link planted in its folder, nor over its own files."""
    world = ('sansui_recipe = 4\nsource = "midpoint"\n[world]\nsize = 129\ntiled = true\ntile_size = 65\n'
             '[[output]]\nfile = "out/h.vrt"\nkind = "heightmap"\n')
    root = fresh("probe")
    target = os.path.join(root, "bait", "secret.asc")
    for rank in range(4):
        os.symlink(target, os.path.join(root, "case", "out", f".sansui-probe-{rank}"))
    write(os.path.join(root, "case", "w.toml"), world)
    run(root, ["run", "w.toml"], 0, written=["h.vrt", "h_0_0.tif", "h_1_1.tif"])
    root = fresh("tile-link")
    os.symlink(target, os.path.join(root, "case", "out", "h_1_0.tif"))
    write(os.path.join(root, "case", "w.toml"), world)
    run(root, ["run", "w.toml"], 2, "symbolic link")
    root = fresh("tile-device")
    os.mkfifo(os.path.join(root, "case", "out", "h_0_1.tif"))
    write(os.path.join(root, "case", "w.toml"), world)
    run(root, ["run", "w.toml"], 2, "FIFO")
    os.unlink(os.path.join(root, "case", "out", "h_0_1.tif"))
    root = fresh("tile-sidecar")
    write(os.path.join(root, "case", "w.toml"), world + '[[output]]\nfile = "out/h_0_0.tif.json"\nkind = "rivers"\n')
    run(root, ["run", "w.toml"], 2, "h_0_0.tif.json")
    root = fresh("vrt-twice")
    write(os.path.join(root, "case", "w.toml"), world + '[[output]]\nfile = "out/sub/../h.vrt"\nkind = "flow_map"\n')
    run(root, ["run", "w.toml"], 2, "same file")
    root = fresh("tiles-twice")
    write(os.path.join(root, "case", "w.toml"), world + '[[output]]\nfile = "out/h.vrt"\nkind = "flow_map"\n')
    run(root, ["run", "w.toml"], 2)
    root = fresh("overflow")
    write(os.path.join(root, "case", "w.toml"), world.replace("size = 129", "world_size = 1048577").replace("tile_size = 65", "tile_size = 3"))
    run(root, ["run", "w.toml"], 2, "tiles")
    root = fresh("two-to-the-thirty")
    write(os.path.join(root, "case", "w.toml"), world.replace("size = 129", "world_size = 1048577").replace("tile_size = 65", "tile_size = 33"))
    run(root, ["run", "w.toml"], 2, "tiles", timeout=30)
    # A finished tile copied from another position is made again, not kept.
    root = fresh("moved-tile")
    write(os.path.join(root, "case", "w.toml"), world)
    run(root, ["run", "w.toml"], 0)
    out = os.path.join(root, "case", "out")
    whole = open(os.path.join(out, "h_1_1.tif"), "rb").read()
    shutil.copy(os.path.join(out, "h_0_0.tif"), os.path.join(out, "h_1_1.tif"))
    shutil.copy(os.path.join(out, "h_0_0.tif.json"), os.path.join(out, "h_1_1.tif.json"))
    run(root, ["run", "w.toml"], 0)
    check(open(os.path.join(out, "h_1_1.tif"), "rb").read() == whole, "moved-tile: the tile copied from (0, 0) was kept at (1, 1)")


def graph_files():
    """A graph node's file that never ends or blocks: refused at once, before its hash."""
    for name, path in [("dev-zero", "/dev/zero"), ("fifo", "x.r32"), ("link", "z.r32")]:
        root = fresh(name)
        case = os.path.join(root, "case")
        if name == "fifo":
            fifo(os.path.join(case, "x.r32"))
        if name == "link":
            os.symlink("/dev/zero", os.path.join(case, "z.r32"))
        for kind, key in [("file", "path"), ("contour", "file"), ("contour_map", "file"), ("mask_polygon", "file")]:
            extra = '\n[[node]]\nid = "m"\nkind = "midpoint"\n[[node]]\nid = "b"\nkind = "blend"\ninputs = ["m", "m", "n"]' if kind == "mask_polygon" else ""
            target = "b" if kind == "mask_polygon" else "n"
            write(os.path.join(case, "g.toml"),
                  f'sansui_recipe = 4\n[world]\nsize = 65\n[[node]]\nid = "n"\nkind = "{kind}"\n{key} = "{path}"{extra}\n'
                  f'[[output]]\nfile = "out/h.r32"\nnode = "{target}"\n')
            run(root, ["run", "g.toml"], 2, timeout=30)
            run(root, ["run", "g.toml", "--cache", "cache"], 2, timeout=30)


def graph_budget():
    """A graph is held to one budget over all its nodes, before any node runs."""
    root = fresh("wide")
    nodes = "".join(f'[[node]]\nid = "s{k}"\nkind = "scale"\ninputs = ["m"]\ngain = {1 + k / 1000}\n' for k in range(512))
    blends = 's0'
    for k in range(1, 512):
        nodes += f'[[node]]\nid = "a{k}"\nkind = "max"\ninputs = ["{blends}", "s{k}"]\n'
        blends = f"a{k}"
    write(os.path.join(root, "case", "g.toml"),
          f'sansui_recipe = 4\n[world]\nsize = 1025\n[[node]]\nid = "m"\nkind = "midpoint"\n{nodes}[[output]]\nfile = "out/h.r32"\nnode = "{blends}"\n')
    run(root, ["--max-memory", "1", "run", "g.toml"], 2, "memory limit", timeout=30)
    root = fresh("erode-chain")
    nodes, last = "", "m"
    for k in range(199):
        nodes += f'[[node]]\nid = "e{k}"\nkind = "erode"\ninputs = ["{last}"]\n'
        last = f"e{k}"
    write(os.path.join(root, "case", "g.toml"),
          f'sansui_recipe = 4\n[world]\nsize = 4097\n[[node]]\nid = "m"\nkind = "midpoint"\n{nodes}[[output]]\nfile = "out/h.r32"\nnode = "{last}"\n')
    run(root, ["run", "g.toml"], 2, "work limit", timeout=60)


def cache_entries():
    """Cache entries are read as inputs: of the world's size, never a FIFO."""
    root = fresh("cache")
    case = os.path.join(root, "case")
    write(os.path.join(case, "g.toml"),
          'sansui_recipe = 4\n[world]\nsize = 65\n[[node]]\nid = "m"\nkind = "midpoint"\n[[output]]\nfile = "out/h.r32"\nnode = "m"\n')
    run(root, ["run", "g.toml", "--cache", "cache"], 0)
    reference = open(os.path.join(case, "out", "h.r32"), "rb").read()
    entries = [name for name in os.listdir(os.path.join(case, "cache")) if name.endswith(".node")]
    check(len(entries) == 1, f"cache: {entries}")
    for entry in entries:
        os.unlink(os.path.join(case, "cache", entry))
        fifo(os.path.join(case, "cache", entry))
    os.unlink(os.path.join(case, "out", "h.r32"))
    result = run(root, ["run", "g.toml", "--cache", "cache"], 0, timeout=30)
    check(open(os.path.join(case, "out", "h.r32"), "rb").read() == reference, "cache: the rerun past a FIFO entry changed the bytes")
    check(result is not None and "ignored and rebuilt" in result.stderr, "cache: no warning about the FIFO entry")


def render_shapes():
    """Elongated DEMs render, or are refused with one line, and never crash."""
    for width, height in [(130, 2), (1000, 2), (2, 100000), (2, 2)]:
        root = fresh(f"dem-{width}x{height}")
        write(os.path.join(root, "case", "dem.asc"), ascii_grid(width, height, 100.0, 0.5))
        run(root, ["render", "dem.asc", "-o", "out/p.png", "--width", "64", "--height", "48"], (0, 2), timeout=300)


CLASSES = {"network": network, "local_files": local_files, "tiled_links": tiled_links, "graph_files": graph_files,
           "graph_budget": graph_budget, "cache_entries": cache_entries, "render_shapes": render_shapes}

if __name__ == "__main__":
    if not STRACE:
        print("note: strace is not installed (scripts/setup --test installs it): files and connections are not audited")
    CLASSES[CLASS]()
    if failures:
        print(f"{len(failures)} failures in {CLASS}")
        sys.exit(1)
    print(f"{CLASS}: every case held")
