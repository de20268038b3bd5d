"""Every node kind as a Python function: called with its defaults, docstrings from its table,
and the same bytes as the CLI's files."""
import inspect

import numpy as np
import pytest

import sansui
from conftest import read_r32

SIDE = 129

# What the kinds that read a file need, and nothing more: the rest are their defaults.
NEEDS = {
    "file": lambda ex, tmp: {"path": str(tmp / "t.r32")},
    "contour": lambda ex, tmp: {"file": str(ex / "contours" / "c_shape.geojson")},
    "contour_map": lambda ex, tmp: {"file": str(ex / "contours" / "jacksboro_40m.geojson")},
    "mesh": lambda ex, tmp: {"file": str(ex / "meshes" / "mountain80.obj")},
    "mask_polygon": lambda ex, tmp: {"file": str(ex / "contours" / "c_shape.geojson")},
}


@pytest.fixture(scope="module")
def terrain():
    return sansui.midpoint(size=SIDE, seed=3)


@pytest.mark.parametrize("kind", [k["name"] for k in sansui.node_kinds()])
def test_every_node_kind_runs_with_its_defaults(kind, terrain, examples, tmp_path, cli):
    info = next(k for k in sansui.node_kinds() if k["name"] == kind)
    if kind == "file":
        cli("terrain", "--size", SIDE, "--seed", 3, "-o", tmp_path / "t.r32")
    keys = NEEDS.get(kind, lambda ex, tmp: {})(examples, tmp_path)
    inputs = []
    for name, value_type, optional in info["inputs"]:
        if optional:
            continue
        inputs.append(terrain if value_type == "heights" else np.full((SIDE, SIDE), 0.5, np.float32))
    world = {} if inputs else {"size": SIDE}
    out = getattr(sansui, kind)(*inputs, **world, **keys)
    assert out.shape == (SIDE, SIDE) and out.dtype == np.float32
    assert np.isfinite(out).all()
    if info["output"] == "mask":
        assert out.min() >= 0 and out.max() <= 1


def test_docstrings_carry_unit_range_default_and_help():
    doc = sansui.midpoint.__doc__
    assert doc.startswith("midpoint(")
    line = next(l for l in doc.splitlines() if l.strip().startswith("hurst "))
    assert "Allowed: > 0 and <= 1" in line and "Default: 0.7" in line
    erode_cell = next(l for l in sansui.erode.__doc__.splitlines() if l.strip().startswith("cell "))
    assert ", m)" in erode_cell


def test_the_same_seed_gives_the_cli_s_bytes(cli, tmp_path):
    cli("terrain", "--size", 257, "--seed", 7, "--hurst", 0.75, "--no-erode", "-o", tmp_path / "raw.r32")
    cli("terrain", "--size", 257, "--seed", 7, "--hurst", 0.75, "-o", tmp_path / "eroded.r32")  # eroded, mature: the default
    raw = sansui.midpoint(size=257, seed=7, hurst=0.75)
    assert np.array_equal(raw, read_r32(tmp_path / "raw.r32", 257))
    assert np.array_equal(sansui.erode(raw), read_r32(tmp_path / "eroded.r32", 257))


def test_a_graph_of_node_calls_gives_the_bytes_of_the_same_graph_run_by_the_cli(cli, tmp_path):
    (tmp_path / "g.toml").write_text(
        """[world]
size = 257
cell = 30.0
sea_level = 5.0
[[node]]
id = "hills"
kind = "midpoint"
seed = 11
[[node]]
id = "steep"
kind = "select_slope"
inputs = ["hills"]
[[node]]
id = "eroded"
kind = "erode"
inputs = ["hills", "steep"]
stage = "old"
[[output]]
file = "e.r32"
node = "eroded"
"""
    )
    cli("run", tmp_path / "g.toml")
    world = sansui.World(size=257, cell=30.0, sea_level=5.0)
    hills = sansui.midpoint(world=world, seed=11)
    eroded = sansui.erode(hills, sansui.select_slope(hills), stage="old")
    assert np.array_equal(eroded, read_r32(tmp_path / "e.r32", 257))


def test_inputs_carry_their_world_to_the_next_call():
    hills = sansui.midpoint(size=65, cell=25.0, sea_level=3.0, seed=1)
    explicit = sansui.smooth(hills, world=sansui.World(size=65, cell=25.0, sea_level=3.0))
    assert np.array_equal(sansui.smooth(hills), explicit)
    assert np.array_equal(sansui.smooth(hills.copy()), explicit)  # copies keep it
    with pytest.warns(sansui.WorldWarning, match="assuming 10 m cells"):
        assert not np.array_equal(sansui.smooth(np.array(hills)), explicit)  # a plain array: the default world, with a warning


def test_contour_takes_its_seed_as_points():
    ring = np.array([[-400.0, -300.0], [400.0, -300.0], [400.0, 300.0], [-400.0, 300.0]])
    h = sansui.contour(ring, interval=10, size=129, cell=20.0)
    assert h.max() > 10.0 and h[0, 0] == 0.0


def test_a_mask_is_not_taken_for_heights():
    hills = sansui.midpoint(size=33)
    with pytest.raises(TypeError, match="takes heights as 'heights'; the array given is a mask"):
        sansui.smooth(sansui.select_slope(hills))


def test_the_signature_is_keyword_only_past_the_inputs():
    assert "hurst" in sansui.midpoint.__doc__
    with pytest.raises(TypeError, match="takes 0 input arrays"):
        sansui.midpoint(np.zeros((3, 3), np.float32))
    # The node functions are Python functions now (they give arrays their world), whose
    # signature comes from the tables: inspect.signature and Jupyter show it.
    signature = inspect.signature(sansui.erode)
    assert list(signature.parameters)[:2] == ["heights", "mask"]
    assert all(p.kind == p.KEYWORD_ONLY for p in list(signature.parameters.values())[2:])


def test_inspect_signature_shows_the_table_s_keys_defaults_and_types():
    signature = inspect.signature(sansui.midpoint)
    hurst = signature.parameters["hurst"]
    assert hurst.default == 0.7 and hurst.annotation is float and hurst.kind == hurst.KEYWORD_ONLY
    assert signature.parameters["seed"].annotation is int
    assert {"size", "cell", "sea_level", "crs", "origin", "world", "progress"} <= set(signature.parameters)
    assert signature.return_annotation is sansui.Grid
    stage = inspect.signature(sansui.erode).parameters["stage"]
    assert stage.default == "mature" and "mature" in str(stage.annotation)
    assert str(inspect.signature(sansui.contour)).startswith("(points")
    rivers = inspect.signature(sansui.rivers).parameters
    assert rivers["channel_area"].default == 1e6 and rivers["runoff"].annotation is float
    for function in (sansui.midpoint, sansui.blend, sansui.file, sansui.slope, sansui.surface_water):
        assert "**keys" not in str(inspect.signature(function))
