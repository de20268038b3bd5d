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


def grid_edges(rows, cols):
    """The grid's edges ((E, 2) vertex indices: the east-west ones row by row, then the
    north-south ones) and, for each cell of grid_quads(), the edges its four sides are, in loop
    order (NW-SW, SW-SE, SE-NE, NE-NW). Blender would find the edges itself in update(), with a
    hash table: 2.3 s for a 1025² grid, against a few hundredths here."""
    index = np.arange(rows * cols, dtype=np.int32).reshape(rows, cols)
    east_west = np.stack([index[:, :-1].ravel(), index[:, 1:].ravel()], axis=1)
    north_south = np.stack([index[:-1, :].ravel(), index[1:, :].ravel()], axis=1)
    east_west_id = np.arange(rows * (cols - 1), dtype=np.int32).reshape(rows, cols - 1)
    north_south_id = (len(east_west) + np.arange((rows - 1) * cols, dtype=np.int32)).reshape(rows - 1, cols)
    sides = (north_south_id[:, :-1], east_west_id[1:, :], north_south_id[:, 1:], east_west_id[:-1, :])
    return np.concatenate([east_west, north_south]), np.stack([s.ravel() for s in sides], axis=1)


def grid_uvs(rows, cols):
    """(rows * cols, 2) float32 texture coordinates: each sample at its pixel's centre of a
    rows x cols image (images are stored bottom row first, hence v from the south)."""
    u = (np.arange(cols, dtype=np.float64) + 0.5) / cols
    v = 1.0 - (np.arange(rows, dtype=np.float64) + 0.5) / rows
    uvs = np.empty((rows, cols, 2), np.float32)
    uvs[..., 0] = u[None, :]
    uvs[..., 1] = v[:, None]
    return uvs.reshape(-1, 2)


def mesh_from_polygons(name, vertices, polygons, vertex_uvs=None, smooth=True, edges=None):
    """A mesh of equal-sided polygons ((F, k) int vertex indices), with per-vertex UVs spread to
    the loops when given. `edges`: (edge vertex pairs (E, 2), each loop's edge (F, k)), else
    Blender finds them."""
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
    if edges is not None:
        mesh.edges.add(len(edges[0]))
        mesh.edges.foreach_set("vertices", np.ascontiguousarray(edges[0], np.int32).ravel())
        mesh.loops.foreach_set("edge_index", np.ascontiguousarray(edges[1], np.int32).ravel())
    mesh.update(calc_edges=edges is None)
    return mesh


def terrain_mesh(name, heights, cell):
    """The terrain: one vertex per sample, one quad per cell, UVs onto the sample-sized images."""
    rows, cols = heights.shape
    return mesh_from_polygons(name, grid_vertices(heights, cell), grid_quads(rows, cols), grid_uvs(rows, cols),
                              edges=grid_edges(rows, cols))


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
    covered = ~np.isnan(levels.ravel())
    quads = grid_quads(rows, cols)
    kept = covered[quads].all(axis=1)
    if not kept.any():
        return None
    quads = quads[kept]
    edge_pairs, quad_edges = grid_edges(rows, cols)
    quad_edges = quad_edges[kept]
    used, used_edges = np.unique(quads), np.unique(quad_edges)
    renumber = np.zeros(rows * cols, np.int32)
    renumber[used] = np.arange(len(used), dtype=np.int32)
    renumber_edge = np.zeros(len(edge_pairs), np.int32)
    renumber_edge[used_edges] = np.arange(len(used_edges), dtype=np.int32)
    vertices = grid_vertices(np.nan_to_num(levels), cell)[used]
    edges = (renumber[edge_pairs[used_edges]], renumber_edge[quad_edges])
    return mesh_from_polygons(name, vertices, renumber[quads], smooth=False, edges=edges)


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
