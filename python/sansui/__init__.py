"""Sansui: deterministic natural terrain, water, plants and scenes, from Python.

    import sansui
    h = sansui.midpoint(size=1025, hurst=0.8, seed=7)   # sansui.Grid: numpy float32 (1025, 1025), metres
    e = sansui.erode(h, stage="mature")                 # on h's world: its cell size and sea level
    rivers = sansui.rivers(e)                           # GeoJSON, in the grid's coordinates and CRS
    sansui.run("scene.toml", out_dir="out")

Every node kind of a recipe graph is a function whose keyword arguments are its parameter
table's keys (help(sansui.midpoint), inspect.signature(sansui.midpoint)); results are
sansui.Grid arrays that know their world, or xarray DataArrays (sansui.set_arrays("xarray"),
or given one); sansui.Recipe and sansui.run run whole recipes. See docs/python.md.
"""
from ._sansui import *  # noqa: F401,F403  (the names are the library's own)
from ._sansui import __version__  # noqa: F401
from . import _sansui
from ._grids import Grid, WorldWarning, arrays, grid, set_arrays  # noqa: F401
from ._water import drainage_area, fill_depressions, flow_routing, lakes, rivers, slope, surface_water  # noqa: F401
from . import _grids, _nodes

globals().update(_nodes.node_functions())
for _public in (Grid, World, Recipe):  # noqa: F405
    _public.__module__ = "sansui"  # as users name them (help(), signatures, pickles)
del _nodes


def _recipe_heights(self, node=None, progress=None):
    """The terrain its outputs are made from (a sansui.Grid on the recipe's world: float32, rows x
    cols, metres), or the result of node `node` (one copy)."""
    values = _sansui.Recipe._heights(self, node, progress)
    return _grids.result(values, _grids.Facts(**_sansui._grid_facts(values)))


Recipe.heights = _recipe_heights  # noqa: F405


def terrain_mesh(heights, world=None, *, cell=None, progress=None):
    array, facts, _ = _grids.unwrap(heights, "heights")
    if world is None and cell is None and facts is not None:
        cell = facts.cell  # the cell the array carries
    return _sansui.terrain_mesh(array, world, cell=cell, progress=progress)


terrain_mesh.__doc__ = _sansui.terrain_mesh.__doc__


def scenery(recipe, progress=None):
    parts = _sansui.scenery(recipe, progress)
    parts["heights"] = _grids.as_grid(parts["heights"], _grids.Facts(**_sansui._grid_facts(parts["heights"])))
    return parts


scenery.__doc__ = _sansui.scenery.__doc__
