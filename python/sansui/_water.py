"""Water on a grid, through the library's own functions (src/water; the CLI's --rivers and
--lakes outputs and the erosion use the same): flow routing, filled DEMs, drainage area, slope,
rivers and lakes. Grids come back on the input's world (sansui.Grid, or DataArrays for a
DataArray); rivers and lakes as GeoJSON FeatureCollections (dicts) in the grid's coordinates,
with its CRS, which geopandas.GeoDataFrame.from_features() and shapely take."""
import json

import numpy as np

from . import _grids
from . import _nodes
from . import _sansui

_WORLD = [{"name": key, "role": "world", "default": None, "annotation": annotation, "doc": ""}
          for key, annotation in (("cell", "Optional[float]"), ("sea_level", "Optional[float]"), ("crs", "Optional[str]"),
                                  ("origin", "Optional[Sequence[float]]"), ("world", "Optional[World]"), ("progress", "Progress"))]
_HEIGHTS = [{"name": "heights", "role": "input", "default": Ellipsis, "annotation": "ArrayLike", "doc": ""}]
_FLOW = _sansui._flow_parameters()
_FLOW_KEYS = [row["name"] for row in _FLOW]

_WORLD_DOC = """
The world (cell size, sea level, CRS, origin) is the one the array carries (a sansui.Grid, a
DataArray with x/y coordinates), else sansui.World()'s with a sansui.WorldWarning; cell=,
sea_level=, crs=, origin= and world= change it. Cells at or below the sea level are outlets,
as the map's edge is: water leaves the map there. progress: a callable (stage, fraction)."""


def _flow_doc():
    return "\n".join("    " + row["doc"] for row in _FLOW)


def _prepare(function, heights, keys):
    """(array, facts, DataArray or None, world dict, keys left, progress); facts.kind is "assumed"
    when the world is the default one (done() then warns)."""
    keys = dict(keys)
    progress = keys.pop("progress", None)
    world = keys.pop("world", None)
    world_keys = {key: keys.pop(key) for key in ("cell", "sea_level", "crs", "origin") if key in keys}
    array, facts, like = _grids.unwrap(heights, "heights")
    facts, assumed = _grids.settle(function, facts, world, world_keys, has_inputs=True)
    if assumed:
        facts = facts._replace(kind="assumed")
    place = {"cell": facts.cell, "sea_level": facts.sea_level, "x0": facts.x0, "y0": facts.y0, "crs": facts.crs}
    return array, facts, like, place, keys, progress


def _done(function, facts, notes):
    """After a call that succeeded: the library's notes, and the world assumed, as warnings."""
    _grids.warn_notes(notes)
    if facts.kind == "assumed":
        _grids.assumed_world(function)


def _out(values, facts, kind, like):
    return _grids.result(values, facts._replace(kind=kind), like)


def _check_keys(function, keys, allowed):
    """TypeError, naming the nearest keyword, for a key the function does not take."""
    for key in keys:
        if key not in allowed:
            _sansui._unknown_keyword(function, key, list(allowed) + [row["name"] for row in _WORLD])


def flow_routing(heights, **keys):
    array, facts, like, place, keys, progress = _prepare("flow_routing", heights, keys)
    _check_keys("flow_routing", keys, ())
    routed, notes = _sansui._flow_routing(array, place, progress)
    _done("flow_routing", facts, notes)
    return {"filled": _out(routed["filled"], facts, "heights", like), "receivers": _out(routed["receivers"], facts, "receivers", like),
            "stack": routed["stack"], "area": _out(routed["area"], facts, "area", like), "basins": _out(routed["basins"], facts, "labels", like)}


flow_routing.__doc__ = """flow_routing(heights, *, cell=None, sea_level=None, ...) -> dict

The library's flow routing (water/flow.hpp): D8 receivers across depressions (each drained over
its lowest pass, Cordonnier et al. 2019), Braun & Willett's stack and the D8 drainage area, as
the erosion and the rivers use it. Returns a dict:

    filled     float32 grid: the ground with every depression filled to its spill level, metres
    receivers  int32 grid: each cell's downstream cell, as a flat index row * cols + col (an
               outlet is its own)
    stack      int32 (rows * cols,): every cell once, each receiver before its donors (walk it
               backwards to go downstream)
    area       float64 grid: D8 drainage area, m^2 (a cell's own area and all it receives)
    basins     int32 grid: the watershed of each cell, 1 + the number of its outlet
""" + _WORLD_DOC
flow_routing.__signature__ = _nodes._signature(_HEIGHTS + _WORLD, returns="Dict[str, Any]")


def fill_depressions(heights, *, epsilon=False, **keys):
    array, facts, like, place, keys, progress = _prepare("fill_depressions", heights, keys)
    _check_keys("fill_depressions", keys, ["epsilon"])
    if not isinstance(epsilon, (bool, np.bool_)):
        raise TypeError(f"epsilon must be True or False; got {type(epsilon).__name__} {epsilon!r:.60}")
    filled, notes = _sansui._fill_depressions(array, place, bool(epsilon), progress)
    _done("fill_depressions", facts, notes)
    return _out(filled, facts, "heights", like)


fill_depressions.__doc__ = """fill_depressions(heights, *, epsilon=False, cell=None, ...) -> sansui.Grid

The filled DEM: every depression filled to its spill level by priority-flood (Barnes et al.
2014, water/priority_flood.hpp), so that water flows from every cell to the map's edge or the
sea. Lakes are flat; epsilon=True raises each filled cell by one float step per cell away from
the spill point instead, so that every cell has a strictly lower neighbour (for tools that need
a surface that drains everywhere).
""" + _WORLD_DOC
fill_depressions.__signature__ = _nodes._signature(
    _HEIGHTS + [{"name": "epsilon", "role": "key", "default": False, "annotation": "bool", "doc": ""}] + _WORLD)


def drainage_area(heights, *, method="d8", **keys):
    array, facts, like, place, keys, progress = _prepare("drainage_area", heights, keys)
    _check_keys("drainage_area", keys, ["method"] + _FLOW_KEYS)
    if not isinstance(method, str):
        raise TypeError(f"method must be a str; got {type(method).__name__} {method!r:.60}")
    area, notes = _sansui._drainage_area(array, place, method, keys, progress)
    _done("drainage_area", facts, notes)
    return _out(area, facts, "area", like)


drainage_area.__doc__ = f"""drainage_area(heights, *, method="d8", flow_exponent=..., cell=None, ...) -> sansui.Grid

Drainage area (flow accumulation) in m^2, float64: each cell's own area plus the area of all
cells that drain through it. method "d8": steepest descent to one neighbour, across depressions
(what flow_routing() gives); "mfd": Freeman's multiple flow directions (1991) on the
epsilon-filled surface, each cell passing its area to all lower neighbours in proportion to
tan(slope)^flow_exponent.

Keys:
    method (Literal["d8", "mfd"]): D8 or multiple flow directions. Default: d8.
{_flow_doc()}
""" + _WORLD_DOC
drainage_area.__signature__ = _nodes._signature(
    _HEIGHTS + [{"name": "method", "role": "key", "default": "d8", "annotation": "Literal['d8', 'mfd']", "doc": ""}] + _FLOW + _WORLD)


def slope(heights, **keys):
    array, facts, like, place, keys, progress = _prepare("slope", heights, keys)
    _check_keys("slope", keys, ())
    degrees, notes = _sansui._slope(array, place, progress)
    _done("slope", facts, notes)
    return _out(degrees, facts, "slope", like)


slope.__doc__ = """slope(heights, *, cell=None, ...) -> sansui.Grid

The slope of every sample in degrees, float32: the gradient by central differences (one-sided
along the map's edge), as select_slope and the landform measures take it.
""" + _WORLD_DOC
slope.__signature__ = _nodes._signature(_HEIGHTS + _WORLD)


def surface_water(heights, **keys):
    array, facts, like, place, keys, progress = _prepare("surface_water", heights, keys)
    _check_keys("surface_water", keys, _FLOW_KEYS)
    made, notes = _sansui._surface_water(array, place, keys, progress)
    _done("surface_water", facts, notes)
    return {"surface": _out(made["surface"], facts, "heights", like), "depth": _out(made["depth"], facts, "depth", like),
            "wetness": _out(made["wetness"], facts, "wetness", like), "area": _out(made["area"], facts, "area", like),
            "strahler": _out(made["strahler"], facts, "order", like), "lake": _out(made["lake"], facts, "labels", like),
            "rivers": json.loads(made["rivers"]), "lakes": json.loads(made["lakes"])}


surface_water.__doc__ = f"""surface_water(heights, *, channel_area=..., runoff=..., cell=None, ...) -> dict

Rivers, lakes and wetness as the CLI's --rivers, --lakes and render outputs make them
(water/surface_water.hpp): lakes are the depressions of at least 16 cells, filled to their spill
level; rivers the D8 channels whose drainage area reaches channel_area. Returns a dict:

    surface   float32 grid: the ground with lakes filled to their level (lakes are flat), metres
    depth     float32 grid: water over the ground (lakes, and rivers as deep as their discharge
              makes them), metres, 0 where dry
    wetness   float32 grid: 0 dry .. 1 wet (the topographic wetness index, 1 under water)
    area      float64 grid: D8 drainage area on the filled surface, m^2
    strahler  uint8 grid: the Strahler order of river cells, 0 elsewhere
    lake      int32 grid: 0 on dry land, k on a cell of lake k
    rivers    GeoJSON FeatureCollection (dict): one LineString per reach, upstream to downstream,
              with strahler_order, area_m2 and discharge_m3_per_s: the bytes of the CLI's --rivers
    lakes     GeoJSON FeatureCollection (dict): one feature per lake, with its level, area and
              volume: the bytes of the CLI's --lakes

Keys:
{_flow_doc()}
""" + _WORLD_DOC
surface_water.__signature__ = _nodes._signature(_HEIGHTS + _FLOW + _WORLD, returns="Dict[str, Any]")


def rivers(heights, **keys):
    return surface_water(heights, **keys)["rivers"]


rivers.__doc__ = """rivers(heights, *, channel_area=..., runoff=..., cell=None, ...) -> dict

The rivers of surface_water() alone: a GeoJSON FeatureCollection, one LineString per reach
(upstream to downstream) with strahler_order, area_m2 and discharge_m3_per_s, in the grid's
coordinates and CRS (geopandas.GeoDataFrame.from_features(fc["features"]) makes a frame of it).
""" + _WORLD_DOC
rivers.__signature__ = _nodes._signature(_HEIGHTS + _FLOW + _WORLD, returns="Dict[str, Any]")


def lakes(heights, **keys):
    return surface_water(heights, **keys)["lakes"]


lakes.__doc__ = """lakes(heights, *, channel_area=..., runoff=..., cell=None, ...) -> dict

The lakes of surface_water() alone: a GeoJSON FeatureCollection, one feature per lake with its
water level, area and volume, in the grid's coordinates and CRS.
""" + _WORLD_DOC
lakes.__signature__ = _nodes._signature(_HEIGHTS + _FLOW + _WORLD, returns="Dict[str, Any]")

for _function in (flow_routing, fill_depressions, drainage_area, slope, surface_water, rivers, lakes):
    _function.__module__ = "sansui"
