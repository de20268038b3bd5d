"""Water from Python: routing, filled DEMs, drainage area, slope, rivers and lakes are the
library's (the CLI's --rivers and --lakes are the same features), on the grid's world."""
import json
import warnings

import numpy as np
import pytest

import sansui

CELL = 30.0
ORIGIN = (500000.0, 4100000.0)


@pytest.fixture(scope="module")
def eroded():
    return sansui.erode(sansui.midpoint(size=257, cell=CELL, crs="EPSG:32654", origin=ORIGIN, seed=3))


def test_rivers_and_lakes_are_the_cli_s_features(eroded, cli, tmp_path):
    cli("terrain", "--size", 257, "--cell", 30, "--crs", "EPSG:32654", "--origin", "500000,4100000", "--seed", 3,
        "-o", tmp_path / "t.tif", "--rivers", tmp_path / "rivers.geojson", "--lakes", tmp_path / "lakes.geojson")
    assert np.array_equal(sansui.file(path=tmp_path / "t.tif"), eroded)
    with warnings.catch_warnings():
        warnings.simplefilter("error", sansui.WorldWarning)
        water = sansui.surface_water(eroded)
    rivers = json.loads((tmp_path / "rivers.geojson").read_text())
    lakes = json.loads((tmp_path / "lakes.geojson").read_text())
    assert water["rivers"] == rivers and sansui.rivers(eroded) == rivers
    assert water["lakes"] == lakes and sansui.lakes(eroded) == lakes
    assert rivers["features"] and "32654" in json.dumps(rivers["crs"])
    # Coordinates are the grid's: every river point stands on a cell centre of its x and y.
    x, y = eroded.x, eroded.y
    for feature in rivers["features"][:20]:
        for east, north in feature["geometry"]["coordinates"]:
            assert np.isclose(x, east).any() and np.isclose(y, north).any()


def test_surface_water_grids_are_on_the_world(eroded):
    water = sansui.surface_water(eroded, channel_area=2e5)
    for key in ("surface", "depth", "wetness", "area", "strahler", "lake"):
        assert water[key].shape == eroded.shape and water[key].cell == CELL and water[key].origin == ORIGIN, key
    assert (water["surface"] >= eroded).all() and (water["depth"] >= 0).all()
    assert water["strahler"].dtype == np.uint8 and water["strahler"].max() >= 2
    assert len(sansui.rivers(eroded, channel_area=2e5)["features"]) > len(sansui.rivers(eroded)["features"])


def test_routing_area_and_filled_dem(eroded):
    routed = sansui.flow_routing(eroded)
    rows, cols = eroded.shape
    assert routed["receivers"].shape == eroded.shape and routed["stack"].shape == (rows * cols,)
    assert sorted(routed["stack"]) == list(range(rows * cols))
    area = routed["area"]
    assert area.dtype == np.float64 and area.min() == CELL * CELL
    # Every cell's area reaches an outlet: the outlets hold the whole map.
    outlets = routed["receivers"].ravel() == np.arange(rows * cols)
    assert np.isclose(area.ravel()[outlets].sum(), rows * cols * CELL * CELL)
    assert np.array_equal(sansui.drainage_area(eroded), area)
    mfd = sansui.drainage_area(eroded, method="mfd", flow_exponent=1.1)
    assert mfd.min() >= CELL * CELL * 0.999 and mfd.max() > 100 * CELL * CELL
    filled = sansui.fill_depressions(eroded)
    assert (filled >= eroded).all() and np.array_equal(filled, routed["filled"])
    assert (sansui.fill_depressions(eroded, epsilon=True) >= filled).all()
    assert routed["basins"].min() >= 1


def test_slope_is_the_central_difference_gradient_in_degrees(eroded):
    slope = sansui.slope(eroded)
    gy, gx = np.gradient(np.asarray(eroded, dtype=np.float64), CELL)
    expected = np.degrees(np.arctan(np.hypot(gx, gy)))
    np.testing.assert_allclose(slope, expected, rtol=1e-5, atol=1e-4)
    assert slope.kind == "slope" and slope.cell == CELL


def test_a_rectangle_routes_and_drains():
    rows, cols = np.mgrid[0:90, 0:140]
    dem = sansui.grid((200.0 - 0.5 * rows + 20 * np.sin(cols / 9.0)).astype(np.float32), cell=10.0)
    routed = sansui.flow_routing(dem)
    assert routed["area"].shape == (90, 140)
    assert np.isclose(routed["area"].ravel()[routed["receivers"].ravel() == np.arange(90 * 140)].sum(), 90 * 140 * 100.0)
    assert sansui.rivers(dem, channel_area=2e4)["features"]


xarray = pytest.importorskip("xarray")


def test_water_of_a_dataarray_comes_as_dataarrays(eroded):
    da = eroded.to_xarray()
    slope = sansui.slope(da)
    assert isinstance(slope, xarray.DataArray) and slope.x.equals(da.x) and slope.attrs["units"] == "degree"
    water = sansui.surface_water(da)
    assert isinstance(water["depth"], xarray.DataArray) and water["rivers"] == sansui.rivers(eroded)
