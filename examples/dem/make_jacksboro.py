#!/usr/bin/env python3
"""Cuts the example real DEM out of matplotlib's sample data (Debian: python-matplotlib-data).

Source: /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz, a 3-arc-second
USGS elevation model around the Jacksboro fault, Tennessee (public domain USGS data, shipped by
matplotlib under its PSF-based licence). This script takes the dissected Cumberland Plateau
massif west of the fault (columns 90..199, rows 80..169 of the 403 x 344 grid), whose 800 m
contour encloses one branching ridge, resamples rows from 92.5 m to the 74.5 m column spacing
(linear), and writes an ESRI ASCII grid with square 74.5 m cells. Standard library only.
Usage: make_jacksboro.py OUT.asc
"""
import struct
import sys
import zipfile

NPZ = "/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz"
COLUMNS, ROWS = (90, 200), (80, 170)
DX, DY = 74.5, 92.5  # metres per column and per row at 36.6 degrees north


def read_npy(data):
    header_length = struct.unpack("<H", data[8:10])[0]
    header = eval(data[10:10 + header_length].decode("latin1"))  # numpy's own dict literal
    assert header["descr"] == "<i2" and not header["fortran_order"]
    rows, columns = header["shape"]
    values = struct.unpack("<%dh" % (rows * columns), data[10 + header_length:])
    return rows, columns, values


def main():
    with zipfile.ZipFile(NPZ) as archive:
        rows, columns, values = read_npy(archive.read("elevation.npy"))
    x0, x1 = COLUMNS
    y0, y1 = ROWS
    out_rows = int((y1 - 1 - y0) * DY / DX) + 1
    lines = []
    for r in range(out_rows):
        y = y0 + r * DX / DY
        j = min(int(y), y1 - 2)
        t = y - j
        row = []
        for i in range(x0, x1):
            a, b = values[j * columns + i], values[(j + 1) * columns + i]
            row.append("%.1f" % (a + t * (b - a)))
        lines.append(" ".join(row))
    with open(sys.argv[1], "w") as f:
        f.write("ncols %d\nnrows %d\nxllcorner 0\nyllcorner 0\ncellsize %.1f\nNODATA_value -9999\n"
                % (x1 - x0, out_rows, DX))
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
