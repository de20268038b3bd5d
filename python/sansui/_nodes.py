"""The node functions: one per node kind of a recipe graph (sansui.node_kinds()), made from the
kind's parameter table (keyword arguments, defaults, annotations and docstring), so they cannot
drift from the CLI. Each settles the world of its call (sansui/_grids.py) and runs the kind in
the library (_sansui._run_node)."""
import inspect
import numbers
import os
import typing

import numpy as np

from . import _grids
from . import _sansui

_WORLD_CALL_KEYS = ("size", "cell", "sea_level", "crs", "origin")
_TYPING = {name: getattr(typing, name) for name in ("Any", "Callable", "Dict", "List", "Literal", "Optional", "Sequence", "Union")}
_TYPING.update(os=os, Grid=_grids.Grid, World=_sansui.World, Progress=typing.Optional[typing.Callable[[str, float], object]])


def _annotation(text):
    """The annotation the stubs write, as a typing object where it reads as one (so that help() and
    Jupyter show Optional[float], not 'Optional[float]'); ArrayLike stays its name."""
    if "ArrayLike" in text:
        return text
    try:
        return eval(text, _TYPING)  # the tables' own type names: int, float, Literal[...], Optional[...]
    except Exception:
        return text


def _signature(parameters, returns="Grid"):
    """An inspect.Signature from the parameter rows _sansui gives (the tables')."""
    made = []
    for row in parameters:
        role, default = row["role"], row["default"]
        if role in ("input", "points"):
            kind = inspect.Parameter.POSITIONAL_OR_KEYWORD
            default = inspect.Parameter.empty if default is Ellipsis else default
        else:
            kind = inspect.Parameter.KEYWORD_ONLY
        made.append(inspect.Parameter(row["name"], kind, default=default, annotation=_annotation(row["annotation"])))
    return inspect.Signature(made, return_annotation=_annotation(returns))


def _inputs_and_keys(kind, args, keys):
    """The call's input arrays (one per slot, None where not given) and its other keywords."""
    name, slots = kind["name"], kind["inputs"]
    inputs = [None] * len(slots)
    first = kind["positional"]  # contour's points: the one positional argument of a kind without inputs
    if not slots and first and len(args) == 1:
        if first in keys:
            raise TypeError(f"{name}() got multiple values for argument '{first}'")
        keys[first] = args[0]
        args = ()
    if len(args) > len(slots):
        raise TypeError(f"{name}() takes {len(slots)} input array{'' if len(slots) == 1 else 's'}, {len(args)} given")
    inputs[:len(args)] = args
    for i, (slot, _, _) in enumerate(slots):
        if slot in keys:
            if inputs[i] is not None:
                raise TypeError(f"{name}() got multiple values for input '{slot}'")
            inputs[i] = keys.pop(slot)
    return inputs, keys


def _call(kind, args, keys):
    name = kind["name"]
    if name == "file":
        return _file(args, keys)
    inputs, keys = _inputs_and_keys(kind, args, dict(keys))
    progress = keys.pop("progress", None)
    world = keys.pop("world", None)
    world_keys = {key: keys.pop(key) for key in kind["world_keys"] if key in keys}
    arrays, facts, like = [], None, None
    for (slot, _, _), given in zip(kind["inputs"], inputs):
        if given is None:
            arrays.append(None)
            continue
        array, known, dataarray = _grids.unwrap(given, slot)
        arrays.append(array)
        facts = facts if facts is not None else known
        like = like if like is not None else dataarray
    has_inputs = any(a is not None for a in arrays)
    place, assumed = _grids.settle(name, facts, world, world_keys, has_inputs)
    size = world_keys.get("size")
    if size is not None and not isinstance(size, numbers.Real):
        # Named by its type: the repr of any value (a list nested thousands deep) could fail.
        raise TypeError(f"{name}(): size must be a number; got {type(size).__name__}")
    if has_inputs:
        shape = np.shape(next(a for a in arrays if a is not None))
        if size is not None and (len(shape) != 2 or shape[0] != size or shape[1] != size):
            sides = f"{shape[1]}x{shape[0]}" if len(shape) == 2 else str(shape)
            raise ValueError(f"{name}(): size={size} but the input arrays are {sides} samples (columns x rows)")
        size = 0
    elif size is not None:
        size = int(_sansui.World(size=size).size)  # checked by the table: 2^k+1 or an Unreal size
    else:
        size = int(world.size) if world is not None else int(_grids._default_world.size)
    values, notes = _sansui._run_node(name, arrays, keys, size, place.cell, place.sea_level, progress)
    _grids.warn_notes(notes)
    if assumed:
        _grids.assumed_world(name)
    return _grids.result(values, place._replace(kind="mask" if kind["output"] == "a mask" else "heights"), like)


def _file(args, keys):
    """file(path=...): a heightmap file with its own size, cell, origin and CRS."""
    keys = dict(keys)
    if args:
        if len(args) > 1 or "path" in keys:
            raise TypeError(f"file() takes one positional argument, the path; {len(args)} given")
        keys["path"] = args[0]
    path = keys.pop("path", None)
    progress = keys.pop("progress", None)
    world = keys.pop("world", None)
    size = keys.pop("size", None)
    given = {key: keys.pop(key) for key in ("cell", "sea_level", "crs", "origin") if key in keys and keys[key] is not None}
    height_range = keys.pop("range", None)  # the reader checks it: two numbers, MIN below MAX
    if keys:
        _sansui._run_node("file", [], keys, 3, 10.0, 0.0)  # raises the table's TypeError for the first unknown key
    if path is None or path == "":
        raise ValueError("a file node needs path: the heightmap to read")
    if not isinstance(path, str) and not hasattr(path, "__fspath__"):
        raise TypeError(f"path must be a str or os.PathLike; got {type(path).__name__} {path!r:.60}")
    base = _grids.world_facts(world, "file()") if world is not None else None
    cell = float(_sansui.World(cell=given["cell"]).cell) if "cell" in given else None
    values, read, notes = _sansui._read_heightmap(path, cell, progress, height_range)
    if size is not None and values.shape != (size, size):
        raise ValueError(f"file(): {path} is {values.shape[1]}x{values.shape[0]} samples (columns x rows); size={size} was given")
    _grids.warn_notes(notes)
    if read["cell_assumed"]:  # the file says none: cell=, else world='s, else the default with a warning
        read["cell"] = cell if cell is not None else base.cell if base is not None else _grids.DEFAULT.cell
        if cell is None and base is None:
            _grids.warn(f"sansui.file(): {path} says no cell size (no georeference, no sidecar); assuming {read['cell']:g} m cells: "
                        "pass cell=", _grids.WorldWarning)
    facts = _grids.Facts(read["cell"], base.sea_level if base else _grids.DEFAULT.sea_level, read["x0"], read["y0"], read["crs"])
    if base is not None:  # world= given: its sea level, and its CRS and origin where the file has none
        facts = facts._replace(crs=facts.crs or base.crs)
        if facts.x0 == 0.0 and facts.y0 == 0.0:
            facts = facts._replace(x0=base.x0, y0=base.y0)
    facts, _ = _grids.settle("file", facts, None, given, has_inputs=False)
    return _grids.result(values, facts)


# What file() does in Python beyond its table's help ("a heightmap file of the world's size", as
# a recipe's file node reads one).
_FILE_DOC = ("A heightmap file as it is: its own size (any rows x cols), cell, CRS and origin (a GeoTIFF's tags, else its "
             "sidecar's), NoData filled as the command line fills it. cell=, crs= and origin= given replace what the file says; "
             "size= given must be its size; a file that says no cell size takes world='s or 10 m, with a sansui.WorldWarning")


def _make(kind, parameters):
    name = kind["name"]

    def node(*inputs, **keys):
        return _call(kind, inputs, keys)

    node.__name__ = node.__qualname__ = name
    node.__module__ = "sansui"
    node.__doc__ = _sansui._node_docstring(name)
    if name == "file":
        node.__doc__ = node.__doc__.replace(kind["help"] + ".", _FILE_DOC + ".", 1)
    node.__signature__ = _signature(parameters)
    return node


def node_functions():
    """{name: function} for every node kind."""
    functions = {}
    for kind in _sansui.node_kinds():
        parameters = _sansui._node_parameters(kind["name"])
        kind = dict(kind, positional=next((p["name"] for p in parameters if p["role"] == "points"), None),
                    world_keys=[p["name"] for p in parameters if p["role"] == "world" and p["name"] in _WORLD_CALL_KEYS])
        functions[kind["name"]] = _make(kind, parameters)
    return functions
