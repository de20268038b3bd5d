"""Arrays that know their world: sansui.Grid, xarray DataArrays, and what a call reads of them.

A grid's world is its cell size, sea level, coordinate reference system and where its first
sample stands. Sansui keeps it two ways, so that copies keep it:

- sansui.Grid, a numpy ndarray subclass: h.copy(), h * 1.0, np.clip(h, ...) and h[a:b, c:d]
  keep the world (a slice moves its origin); numpy code reads it as any float32 array.
- xarray.DataArray (when python3-xarray is installed): x and y coordinates in metres at the
  cells' centres (x east, y north), the CRS and geotransform on a `spatial_ref` coordinate as
  rioxarray writes them, and the sea level as a scalar coordinate `sea_level`. Arithmetic keeps
  coordinates, so it keeps the world too.

Coordinates: sample (row r, column c) stands at x = x0 + c * cell, y = y0 - r * cell, (x0, y0)
the centre of sample (0, 0). A world without an origin has x0 = y0 = 0 (the convention of
sansui.World, of every output's GeoJSON and of scenery()'s plants); with origin=(E, N), the
north-west corner of the grid, x0 = E + cell / 2 and y0 = N - cell / 2.
"""
import functools
import sys
import warnings
from typing import NamedTuple, Optional

import numpy as np

from . import _sansui


class WorldWarning(UserWarning):
    """A call assumed a world (cell size, sea level) because an array it was given carried none."""


class Facts(NamedTuple):
    """The world of a grid (internal): cell and sea level in metres, the centre of sample (0, 0)
    (east, north; metres), the CRS's id or WKT (None: none) and what the samples are."""

    cell: float
    sea_level: float
    x0: float = 0.0
    y0: float = 0.0
    crs: Optional[str] = None
    kind: str = "heights"

    def origin(self):
        """The north-west corner (east, north), or None for a world without an origin."""
        if self.x0 == 0.0 and self.y0 == 0.0:
            return None
        return (self.x0 - 0.5 * self.cell, self.y0 + 0.5 * self.cell)


_default_world = _sansui.World()
DEFAULT = Facts(float(_default_world.cell), float(_default_world.sea_level))

# What the samples of each kind of result are, for DataArray attributes.
UNITS = {"heights": ("m", "height"), "mask": ("1", "mask"), "slope": ("degree", "slope"), "area": ("m2", "drainage area"),
         "depth": ("m", "water depth"), "wetness": ("1", "wetness"), "labels": ("1", "labels"), "receivers": ("1", "receiver cell"),
         "order": ("1", "Strahler order")}

_arrays = "numpy"


def set_arrays(kind):
    """set_arrays("numpy" | "xarray"): what node functions return when no input is a DataArray.

    "numpy" (the default): sansui.Grid, a numpy ndarray that knows its world. "xarray":
    xarray.DataArray with x/y coordinates in metres and the CRS (needs python3-xarray). A call
    given a DataArray returns DataArrays either way."""
    global _arrays
    if kind not in ("numpy", "xarray"):
        raise ValueError(f"set_arrays({kind!r}) is not allowed: it must be 'numpy' or 'xarray'")
    if kind == "xarray":
        _xarray()
    _arrays = kind


def arrays():
    """What set_arrays() chose: "numpy" or "xarray"."""
    return _arrays


def _xarray():
    try:
        import xarray
    except ImportError:
        raise ModuleNotFoundError("xarray is not installed: DataArrays need python3-xarray (apt-get install python3-xarray)") from None
    return xarray


_rioxarray = None


def _rio():
    """rioxarray when it is installed (it registers the .rio accessor), else None."""
    global _rioxarray
    if _rioxarray is None:
        try:
            import rioxarray  # noqa: F401
            _rioxarray = True
        except ImportError:
            _rioxarray = False
    return _rioxarray


@functools.lru_cache(maxsize=256)
def crs_facts(text, what="crs"):
    """_sansui._crs(text, what), kept: PROJ takes milliseconds to read a CRS (a dict or None;
    ValueError for one Sansui's grids cannot carry)."""
    return _sansui._crs(text, what)


def crs_text(text, what="crs"):
    """The id or WKT a grid keeps of the CRS `text` names; None for none."""
    if not isinstance(text, str):
        raise TypeError(f"{what} must be a str (EPSG:CODE or WKT); got {type(text).__name__} {text!r:.60}")
    described = crs_facts(text, what) if text else None
    return None if described is None else described["text"]


def is_dataarray(obj):
    xarray = sys.modules.get("xarray")
    return xarray is not None and isinstance(obj, xarray.DataArray)


class Grid(np.ndarray):
    """A numpy array of a grid on its world: heights in metres (or a mask, a slope...), shape
    (rows, cols), row 0 north, that knows its cell size, sea level, CRS and origin.

    It is a numpy ndarray: every numpy operation works on it, and copies (h.copy(), h * 1.0,
    np.clip(h, ...), h.astype(...)) keep the world, so the next call takes it. A slice with
    steps of 1 (or the same step on both axes) keeps it too, moved to the slice's first sample.
    np.asarray(h) is a plain ndarray without it. Make one of any array with sansui.grid().

    Attributes: cell, sea_level (metres), crs (its id or WKT; None: a local plane), origin (the
    north-west corner (east, north), None: sample (0, 0) at 0, 0), x and y (the cells' centres,
    metres east and north), transform (GDAL's geotransform), bounds, world (a sansui.World), kind.
    """

    _facts = None

    def __array_finalize__(self, obj):
        facts = getattr(obj, "_facts", None)
        if facts is not None and (self.ndim != 2 or obj.shape != self.shape):
            facts = None
        self._facts = facts

    # A transposed grid's rows are columns: it has no world (numpy sets a view's strides after
    # __array_finalize__, so these say it).
    def transpose(self, *axes):
        out = super().transpose(*axes)
        if isinstance(out, Grid) and out.strides != self.strides:
            out._facts = None
        return out

    def swapaxes(self, axis1, axis2):
        out = super().swapaxes(axis1, axis2)
        if isinstance(out, Grid) and out.strides != self.strides:
            out._facts = None
        return out

    @property
    def T(self):
        return self.transpose()

    def __array_wrap__(self, array, context=None, return_scalar=False):  # return_scalar: numpy 2's
        if array.ndim == 0:
            return array[()]  # a reduction: a number, not a 0-d grid
        if array.ndim != 2:
            return array.view(np.ndarray)
        return super().__array_wrap__(array, context)

    def __getitem__(self, key):
        out = super().__getitem__(key)
        if isinstance(out, Grid):
            if out.ndim != 2:
                return out.view(np.ndarray)
            out._facts = _sliced(self._facts, key, self.shape)
        return out

    def __reduce__(self):
        function, arguments, state = super().__reduce__()
        return function, arguments, (state, self._facts)

    def __setstate__(self, state):
        array_state, facts = state
        super().__setstate__(array_state)
        self._facts = Facts(*facts) if facts is not None else None

    # The world, read-only; None on a grid that lost it (a transposed view, an irregular slice).
    @property
    def cell(self):
        """Metres between neighbouring samples."""
        return None if self._facts is None else self._facts.cell

    @property
    def sea_level(self):
        """The world's sea level, metres."""
        return None if self._facts is None else self._facts.sea_level

    @property
    def crs(self):
        """The coordinate reference system: its id ("EPSG:32654") or WKT; None: a local plane."""
        return None if self._facts is None else self._facts.crs

    @property
    def origin(self):
        """The north-west corner (east, north) in metres; None: sample (0, 0) stands at 0, 0."""
        return None if self._facts is None else self._facts.origin()

    @property
    def kind(self):
        """What the samples are: "heights", "mask", "slope", "area"..."""
        return None if self._facts is None else self._facts.kind

    @property
    def x(self):
        """Metres east of the cells' centres, one per column."""
        return None if self._facts is None else self._facts.x0 + self._facts.cell * np.arange(self.shape[1], dtype=np.float64)

    @property
    def y(self):
        """Metres north of the cells' centres, one per row (decreasing: row 0 is north)."""
        return None if self._facts is None else self._facts.y0 - self._facts.cell * np.arange(self.shape[0], dtype=np.float64)

    @property
    def transform(self):
        """GDAL's geotransform: (west, cell, 0, north, 0, -cell), for SetGeoTransform()."""
        return None if self._facts is None else geotransform(self._facts)

    @property
    def bounds(self):
        """(west, south, east, north) of the cells' outer edges, metres."""
        if self._facts is None:
            return None
        west, cell, _, north, _, _ = geotransform(self._facts)
        return (west, north - cell * self.shape[0], west + cell * self.shape[1], north)

    @property
    def world(self):
        """A sansui.World of this grid (size, cell, sea level, CRS, origin), to make more on it;
        None unless it is square with a size a World takes (2^k+1...)."""
        if self._facts is None or self.shape[0] != self.shape[1]:
            return None
        keys = {"size": self.shape[0], "cell": self._facts.cell, "sea_level": self._facts.sea_level}
        if self._facts.crs:
            keys["crs"] = self._facts.crs
        if self._facts.origin() is not None:
            keys["origin"] = list(self._facts.origin())
        try:
            return _sansui.World(**keys)
        except ValueError:
            return None

    def to_xarray(self):
        """This grid as an xarray.DataArray: x/y coordinates in metres, CRS and geotransform on a
        `spatial_ref` coordinate (rioxarray's convention), sea_level as a scalar coordinate. The
        samples are not copied."""
        facts = self._facts
        if facts is None:
            facts = assumed_world("to_xarray", "the grid")
        return to_dataarray(self.view(np.ndarray), facts)


def geotransform(facts):
    half = 0.5 * facts.cell
    return (facts.x0 - half, facts.cell, 0.0, facts.y0 + half, 0.0, -facts.cell)


def _sliced(facts, key, shape):
    """The world of h[key] for a 2-D result: moved to the slice's first sample, the cell times its
    step; None when the slice is not regular (fancy indices, different steps, reversed)."""
    if facts is None:
        return None
    if not isinstance(key, tuple):
        key = (key,)
    if any(k is Ellipsis for k in key):
        at = next(i for i, k in enumerate(key) if k is Ellipsis)
        key = key[:at] + (slice(None),) * (2 - (len(key) - 1)) + key[at + 1:]
    key = key + (slice(None),) * (2 - len(key))
    if len(key) != 2 or not all(isinstance(k, slice) for k in key):
        return None
    (row0, _, row_step), (col0, _, col_step) = (k.indices(n) for k, n in zip(key, shape))
    if row_step != col_step or row_step <= 0:
        return None
    return facts._replace(cell=facts.cell * row_step, x0=facts.x0 + col0 * facts.cell, y0=facts.y0 - row0 * facts.cell)


def as_grid(values, facts):
    """`values` (a 2-D ndarray) viewed as a Grid with `facts` (no copy)."""
    grid = values.view(Grid)
    grid._facts = facts
    return grid


def _same_place(a, b):
    return a.cell == b.cell and a.x0 == b.x0 and a.y0 == b.y0 and a.crs == b.crs


def to_dataarray(values, facts, like=None):
    """`values` as a DataArray with the coordinates of `facts`; `like`: (the DataArray an input came
    as, its facts), whose dimension names, x/y coordinates and spatial_ref are kept when the result
    stands where it does (so that results align with it exactly)."""
    xarray = _xarray()
    units, long_name = UNITS.get(facts.kind, ("", facts.kind))
    attrs = {"units": units, "long_name": long_name, "sansui_kind": facts.kind}
    like, like_facts = like if like is not None else (None, None)
    if like is not None and like.shape == values.shape and like_facts is not None and _same_place(like_facts, facts):
        y_dim, x_dim = like.dims
        coords = {name: coordinate for name, coordinate in like.coords.items() if set(coordinate.dims) <= {y_dim, x_dim}}
        coords["sea_level"] = facts.sea_level
        return xarray.DataArray(values, dims=like.dims, coords=coords, attrs=attrs, name=like.name)
    rows, cols = values.shape
    coords = {"y": facts.y0 - facts.cell * np.arange(rows, dtype=np.float64),
              "x": facts.x0 + facts.cell * np.arange(cols, dtype=np.float64), "sea_level": facts.sea_level,
              "spatial_ref": _spatial_ref(facts.crs, geotransform(facts)).copy(deep=False)}
    array = xarray.DataArray(values, dims=("y", "x"), coords=coords, attrs=attrs)
    array.encoding["grid_mapping"] = "spatial_ref"
    return array


@functools.lru_cache(maxsize=64)
def _spatial_ref(crs, transform):
    """The `spatial_ref` coordinate of a grid: its CRS and geotransform as rioxarray writes them
    (made by rioxarray when it is installed, else by hand with the same attributes). Kept for
    the grids of the same place: rioxarray takes milliseconds to write a CRS."""
    xarray = _xarray()
    if _rio():
        from affine import Affine
        template = xarray.DataArray(np.zeros((1, 1), np.float32), dims=("y", "x"))
        if crs:
            template.rio.write_crs(crs, inplace=True)
        template.rio.write_transform(Affine.from_gdal(*transform), inplace=True)
        return template.coords["spatial_ref"].variable
    reference = {"GeoTransform": " ".join(repr(float(v)) for v in transform)}
    if crs:
        described = crs_facts(crs)
        wkt = described["wkt1"] or described["wkt"]
        reference.update(crs_wkt=wkt, spatial_ref=wkt)
    return xarray.Variable((), 0, reference)


def _regular_step(values, axis_name, increasing):
    """The spacing of coordinates `values`, checked: regular, and increasing or decreasing."""
    steps = np.diff(np.asarray(values, dtype=np.float64))
    step = steps[0]
    if not np.allclose(steps, step, rtol=1e-6, atol=0.0):
        raise ValueError(f"the array's {axis_name} coordinates are not evenly spaced: Sansui's grids are regular (resample it first)")
    if (step > 0) != increasing or step == 0:
        order = "increase (west to east)" if increasing else "decrease (row 0 north)"
        hint = "" if increasing else f": da.sortby('{axis_name}', ascending=False)"
        raise ValueError(f"the array's {axis_name} coordinates must {order}{hint}")
    return abs(step)


def _dataarray_crs(array):
    """The CRS a DataArray carries (rioxarray's, or a spatial_ref's crs_wkt), checked: its id or
    WKT, or None."""
    text = None
    if _rio():
        try:
            crs = array.rio.crs
        except Exception:  # rioxarray raises for a spatial_ref it cannot read
            crs = None
        if crs is not None:
            epsg = crs.to_epsg()
            text = f"EPSG:{epsg}" if epsg else crs.to_wkt()
    if text is None:
        for name in ("spatial_ref", "crs"):
            if name in array.coords:
                attrs = array.coords[name].attrs
                text = attrs.get("crs_wkt") or attrs.get("spatial_ref")
                if text:
                    break
        text = text or array.attrs.get("crs")
    if not text:
        return None
    return crs_text(str(text), "the array's CRS")


def from_dataarray(array, name):
    """(values, facts or None, (the 2-D DataArray, facts)): the samples of a 2-D DataArray (a 2-D
    ndarray, not copied when it holds one) and the world its coordinates say. A leading dimension
    of length 1 (rioxarray's band) is dropped."""
    if array.ndim > 2:
        extra = [dim for dim in array.dims[:-2] if array.sizes[dim] == 1]
        array = array.squeeze(extra, drop=True)
    if array.ndim != 2:
        raise ValueError(f"{name} must be a 2-D DataArray (y, x); it has dimensions {tuple(array.dims)}")
    y_dim, x_dim = array.dims
    values = np.asarray(array.data) if isinstance(array.data, np.ndarray) else np.asarray(array.values)
    nodata = array.rio.nodata if _rio() else array.attrs.get("_FillValue")
    if nodata is not None and not np.isnan(nodata) and values.dtype.kind in "fiu":
        holes = np.argwhere(values == nodata)
        if len(holes):
            row, col = holes[0]
            raise ValueError(f"{name} holds its nodata value {nodata:g} at row {row}, column {col}: fill it first (da.rio.interpolate_na()), "
                             "or read the file with sansui.file(), which fills NoData")
    if x_dim not in array.coords or y_dim not in array.coords:
        return values, None, (array, None)
    xs, ys = array.coords[x_dim].values, array.coords[y_dim].values
    cells = []
    if len(xs) > 1:
        cells.append(_regular_step(xs, x_dim, True))
    if len(ys) > 1:
        cells.append(_regular_step(ys, y_dim, False))
    if not cells:
        return values, None, (array, None)
    if len(cells) == 2 and abs(cells[0] - cells[1]) > 1e-6 * max(cells):
        raise ValueError(f"{name} has cells of {cells[0]:g} x {cells[1]:g}: Sansui's grids have square cells (resample it first)")
    sea_level = 0.0
    if "sea_level" in array.coords and array.coords["sea_level"].ndim == 0:
        sea_level = float(array.coords["sea_level"])
    elif "sea_level" in array.attrs:
        sea_level = float(array.attrs["sea_level"])
    kind = array.attrs.get("sansui_kind", "heights")
    facts = Facts(float(cells[0]), sea_level, float(xs[0]), float(ys[0]), _dataarray_crs(array), kind)
    return values, facts, (array, facts)


def unwrap(obj, name):
    """(array to hand the library, facts or None, (the DataArray it came as, its facts) or None)."""
    if isinstance(obj, Grid):
        return obj, obj._facts, None
    if is_dataarray(obj):
        return from_dataarray(obj, name)
    return obj, None, None  # a plain array (np.asarray(grid) too): no world


_PACKAGE = __file__.rsplit("/", 1)[0] + "/"


def warn(message, category):
    """warnings.warn at the caller's line: the first frame outside this package."""
    frame, level = sys._getframe(1), 2
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)


def assumed_world(function, what="the input array"):
    warn(
        f"sansui.{function}(): {what} carries no world (a plain array, not a sansui.Grid or a DataArray with x/y coordinates); "
        f"assuming {DEFAULT.cell:g} m cells and sea level {DEFAULT.sea_level:g} m: pass cell= and sea_level= (or world=), or "
        f"make it with sansui.grid(array, cell=...)", WorldWarning)
    return DEFAULT


def warn_notes(notes):
    for note in notes:
        warn(note, UserWarning)


def result(values, facts, like=None, xarray=False):
    """A result as the caller wants it: a DataArray when asked or when an input was one, else a Grid."""
    if xarray or like is not None or _arrays == "xarray":
        return to_dataarray(values.view(np.ndarray) if isinstance(values, Grid) else values, facts, like)
    return as_grid(values, facts)


def world_facts(world, name):
    """The facts of a sansui.World given as world=."""
    if not isinstance(world, _sansui.World):
        raise TypeError(f"{name}: world must be a sansui.World; got {type(world).__name__}")
    cell = float(world.cell)
    origin = world.origin
    x0, y0 = (0.0, 0.0) if origin is None else (origin[0] + 0.5 * cell, origin[1] - 0.5 * cell)
    return Facts(cell, float(world.sea_level), x0, y0, crs_text(world.crs))


def settle(function, facts, world, keys, has_inputs):
    """(facts, assumed): the world of a call: world= if given, else the inputs' (`facts`), else
    the default; then cell=, sea_level=, crs=, origin= from `keys` (checked by sansui.World's
    table). `assumed` is True when there are inputs and neither they nor the keys gave a world:
    the caller warns (assumed_world()) once the call has succeeded."""
    assumed = False
    if world is not None:
        facts = world_facts(world, f"{function}()")
    elif facts is None:
        facts = DEFAULT
        assumed = has_inputs and keys.get("cell") is None
    given = {key: keys[key] for key in ("cell", "sea_level", "origin") if key in keys and keys[key] is not None}
    crs = crs_text(keys["crs"]) if keys.get("crs") is not None else facts.crs
    if not given:
        return facts._replace(crs=crs), assumed
    checked = _sansui.World(**given)  # ValueError/TypeError with the table's messages
    cell = float(checked.cell) if "cell" in given else facts.cell
    origin = facts._replace(cell=cell).origin() if "origin" not in given else tuple(checked.origin)
    x0, y0 = (0.0, 0.0) if origin is None else (origin[0] + 0.5 * cell, origin[1] - 0.5 * cell)
    sea_level = float(checked.sea_level) if "sea_level" in given else facts.sea_level
    return facts._replace(cell=cell, sea_level=sea_level, x0=x0, y0=y0, crs=crs), assumed


def grid(array, *, cell=None, sea_level=None, crs=None, origin=None, world=None, kind="heights"):
    """grid(array, cell=..., sea_level=..., crs=..., origin=..., world=None) -> sansui.Grid

    Any 2-D array of real numbers (a DEM read with GDAL, a DataArray, a list of rows) as a
    sansui.Grid on the world given: cell size and sea level in metres, the CRS ("EPSG:32654" or
    WKT) and the north-west corner origin=(east, north). A DataArray or a Grid brings its own,
    which the keywords given change. Float32 C-contiguous arrays are not copied."""
    values, facts, _ = unwrap(array, "array")
    values = np.asarray(values)
    if values.ndim != 2:
        raise ValueError(f"grid(): the array must be 2-D (rows, cols); it is {values.ndim}-D, shape {values.shape}")
    if values.dtype.kind not in "fiub":
        raise TypeError(f"grid(): the array must hold real numbers; its dtype is {values.dtype}")
    keys = {"cell": cell, "sea_level": sea_level, "crs": crs, "origin": origin}
    facts, assumed = settle("grid", facts, world, {k: v for k, v in keys.items() if v is not None}, has_inputs=True)
    if kind not in UNITS:
        raise ValueError(f"grid(): kind {kind!r} is not allowed: it must be one of {', '.join(UNITS)}")
    made = as_grid(np.ascontiguousarray(values, dtype=np.float32), facts._replace(kind=kind))
    if assumed:
        assumed_world("grid", "the array")
    return made
