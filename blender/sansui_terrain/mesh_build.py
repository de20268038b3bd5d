"""Blender meshes from numpy arrays through the bulk paths (foreach_set): a 1025² terrain is a
million vertices, which per-vertex Python would take minutes over.

Coordinates: x east, y north, z up, metres, the object's origin at the world's centre; grid row 0
is the north edge, column 0 the west edge."""
import bpy
import numpy as np


def grid_offsets(rows, cols, cell):
    """Half the world's extent east and north: sample (row, col) lies at
    (col * cell - east, north - row * cell)."""
    return (cols - 1) * cell / 2.0, (rows - 1) * cell / 2.0


def grid_vertices(surface, cell):
    """(rows * cols, 3) float32 vertices of a grid of heights; z is the heights' own float32."""
    rows, cols = surface.shape
    east, north = grid_offsets(rows, cols, cell)
    vertices = np.empty((rows, cols, 3), np.float32)
    vertices[..., 0] = (np.arange(cols) * cell - east)[None, :]
    vertices[..., 1] = (north - np.arange(rows) * cell)[:, None]
    vertices[..., 2] = surface
    return vertices.reshape(-1, 3)


def grid_quads(rows, cols):
    """(F, 4) int32 corners of every grid cell, counter-clockwise seen from above (NW, SW, SE, NE)."""
    index = np.arange(rows * cols, dtype=np.int32).reshape(rows, cols)
    corners = (index[:-1, :-1], index[1:, :-1], index[1:, 1:], index[:-1, 1:])
    return np.stack([c.ravel() for c in corners], axis=1)


def grid_uvs(rows, cols):
    """(rows * cols, 2) float32 texture coordinates: each sample at its pixel's centre of a
    rows x cols image (images are stored bottom row first, hence v from the south)."""
    u = (np.arange(cols, dtype=np.float64) + 0.5) / cols
    v = 1.0 - (np.arange(rows, dtype=np.float64) + 0.5) / rows
    uvs = np.empty((rows, cols, 2), np.float32)
    uvs[..., 0] = u[None, :]
    uvs[..., 1] = v[:, None]
    return uvs.reshape(-1, 2)


def mesh_from_polygons(name, vertices, polygons, vertex_uvs=None, smooth=True):
    """A mesh of equal-sided polygons ((F, k) int vertex indices), with per-vertex UVs spread to
    the loops when given."""
    mesh = bpy.data.meshes.new(name)
    count, sides = polygons.shape
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", np.ascontiguousarray(vertices, np.float32).ravel())
    mesh.loops.add(count * sides)
    mesh.loops.foreach_set("vertex_index", np.ascontiguousarray(polygons, np.int32).ravel())
    mesh.polygons.add(count)
    mesh.polygons.foreach_set("loop_start", np.arange(0, count * sides, sides, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(count, sides, np.int32))
    if smooth:
        mesh.polygons.foreach_set("use_smooth", np.ones(count, bool))
    if vertex_uvs is not None:
        layer = mesh.uv_layers.new(name="UVMap")
        layer.data.foreach_set("uv", vertex_uvs[polygons.ravel()].ravel())
    mesh.update(calc_edges=True)
    return mesh


def terrain_mesh(name, heights, cell):
    """The terrain: one vertex per sample, one quad per cell, UVs onto the sample-sized images."""
    rows, cols = heights.shape
    return mesh_from_polygons(name, grid_vertices(heights, cell), grid_quads(rows, cols), grid_uvs(rows, cols))


def _neighbourhood_max(levels):
    """The highest of each sample's 3x3 neighbours (-inf outside the grid)."""
    padded = np.pad(levels, 1, constant_values=-np.inf)
    rows, cols = levels.shape
    best = np.full(levels.shape, -np.inf, levels.dtype)
    for dy in range(3):
        for dx in range(3):
            np.maximum(best, padded[dy:dy + rows, dx:dx + cols], out=best)
    return best


def water_levels(heights, depth):
    """The water surface's height at every sample it covers, NaN elsewhere. Wet samples lie at
    ground + depth; the dry ring around them takes their neighbours' level, so the flat surface
    runs under the shore and the ground cuts a clean water line (no gap of half a cell)."""
    wet = depth > 0
    levels = np.where(wet, heights + depth, -np.inf).astype(np.float32)
    ring = _neighbourhood_max(levels)
    levels = np.where(wet, levels, ring)
    return np.where(np.isfinite(levels), levels, np.nan).astype(np.float32)


def water_mesh(name, heights, depth, cell):
    """The water surface (sea and lakes) as one mesh over the cells whose four corners it covers,
    or None when the world is dry."""
    levels = water_levels(heights, depth)
    rows, cols = levels.shape
    quads = grid_quads(rows, cols)
    covered = ~np.isnan(levels.ravel())
    quads = quads[covered[quads].all(axis=1)]
    if len(quads) == 0:
        return None
    used = np.unique(quads)
    renumber = np.zeros(rows * cols, np.int32)
    renumber[used] = np.arange(len(used), dtype=np.int32)
    vertices = grid_vertices(np.nan_to_num(levels), cell)[used]
    return mesh_from_polygons(name, vertices, renumber[quads], smooth=False)


def point_mesh(name, points, attributes):
    """A mesh of loose vertices (the plants), with named per-point attributes:
    {name: (type 'INT'|'FLOAT', array)}."""
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(points))
    mesh.vertices.foreach_set("co", np.ascontiguousarray(points, np.float32).ravel())
    for attribute, (kind, values) in attributes.items():
        layer = mesh.attributes.new(attribute, kind, "POINT")
        dtype = np.int32 if kind == "INT" else np.float32
        layer.data.foreach_set("value", np.ascontiguousarray(values, dtype))
    mesh.update()
    return mesh


def triangle_mesh(name, vertices, faces):
    """A mesh of triangles (a plant)."""
    return mesh_from_polygons(name, vertices, np.asarray(faces, np.int32).reshape(-1, 3), smooth=False)
