"""Arrays keep their world: copies, slices and pickles of a sansui.Grid, xarray DataArrays with
rioxarray's conventions, rectangles, file() with the file's own size, cell and CRS, and a
warning whenever a call has to assume a world."""
import pickle
import subprocess
import sys
import warnings

import numpy as np
import pytest

import sansui

CELL = 30.0


@pytest.fixture(scope="module")
def hills():
    return sansui.midpoint(size=257, cell=CELL, sea_level=5.0, seed=4)


@pytest.fixture
def no_world_warnings():
    """Turns a WorldWarning into an error: the calls inside must find their world."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", sansui.WorldWarning)
        yield


def test_copies_keep_their_world(hills, no_world_warnings):
    expected = sansui.erode(np.array(hills), cell=CELL, sea_level=5.0)
    assert hills.cell == CELL and hills.sea_level == 5.0
    assert np.array_equal(sansui.erode(hills), expected)
    assert np.array_equal(sansui.erode(hills.copy()), expected)
    assert np.array_equal(sansui.erode(hills * 1.0), expected)
    assert np.array_equal(sansui.erode(hills.astype(np.float64)), expected)
    low, high = float(np.percentile(hills, 5)), float(np.percentile(hills, 95))
    clipped = np.clip(hills, low, high)
    assert clipped.cell == CELL
    assert np.array_equal(sansui.erode(clipped), sansui.erode(np.clip(np.asarray(hills), low, high), cell=CELL, sea_level=5.0))
    again = pickle.loads(pickle.dumps(hills))
    assert again.cell == CELL and again.sea_level == 5.0 and np.array_equal(again, hills)


def test_results_are_numpy_arrays_and_numbers(hills):
    assert isinstance(hills, np.ndarray) and hills.dtype == np.float32
    assert isinstance(hills.max(), np.floating) and f"{hills.min():.0f}"  # reductions are numbers
    assert type(np.asarray(hills)) is np.ndarray and type(hills[hills > 0]) is np.ndarray
    assert hills[3, 4] == np.asarray(hills)[3, 4]


def test_a_slice_moves_its_origin_and_a_transposed_view_has_no_world():
    h = sansui.midpoint(size=65, cell=10.0, origin=(1000.0, 5000.0))
    assert h.origin == (1000.0, 5000.0) and h.transform == (1000.0, 10.0, 0.0, 5000.0, 0.0, -10.0)
    part = h[8:40, 16:]
    assert part.origin == (1160.0, 4920.0) and part.cell == 10.0
    assert np.array_equal(part.x, h.x[16:]) and np.array_equal(part.y, h.y[8:40])
    coarse = h[::4, ::4]
    assert coarse.cell == 40.0 and coarse.x[1] - coarse.x[0] == 40.0
    assert h.T.cell is None and h[::2, ::4].cell is None


def test_a_plain_array_gets_the_default_world_with_a_warning(hills):
    with pytest.warns(sansui.WorldWarning, match="assuming 10 m cells and sea level 0 m"):
        plain = sansui.smooth(np.array(hills))
    assert plain.cell == 10.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", sansui.WorldWarning)
        sansui.smooth(np.asarray(hills), cell=CELL)  # a world given: no warning
        sansui.smooth(sansui.grid(np.asarray(hills), cell=CELL))
        with pytest.raises(ValueError):
            sansui.smooth(np.full((5, 5), np.nan))  # a call that fails warns of nothing


def test_the_world_s_crs_and_origin_come_with_the_results():
    h = sansui.midpoint(size=129, cell=25.0, crs="EPSG:32654", origin=(500000.0, 4100000.0))
    e = sansui.erode(h)
    assert e.crs == "EPSG:32654" and e.origin == (500000.0, 4100000.0) and e.cell == 25.0
    assert e.bounds == (500000.0, 4100000.0 - 129 * 25.0, 500000.0 + 129 * 25.0, 4100000.0)
    world = e.world
    assert world.size == 129 and world.cell == 25.0 and world.crs == "EPSG:32654"
    assert np.array_equal(sansui.midpoint(world=world), h)


def test_a_300_by_250_dem_erodes(no_world_warnings):
    # A real-looking rectangle: a ridge and a valley with noise, 300 columns by 250 rows of 30 m.
    rows, cols = np.mgrid[0:250, 0:300]
    noise = np.random.default_rng(7).normal(0.0, 3.0, (250, 300))
    dem = (400.0 + 300.0 * np.sin(cols / 60.0) * np.cos(rows / 45.0) + 0.8 * rows + noise).astype(np.float32)
    grid = sansui.grid(dem, cell=CELL, crs="EPSG:32633", origin=(400000.0, 5200000.0))
    eroded = sansui.erode(grid, stage="mature")
    assert eroded.shape == (250, 300) and np.isfinite(eroded).all()
    assert eroded.cell == CELL and eroded.crs == "EPSG:32633" and eroded.origin == (400000.0, 5200000.0)
    assert float(np.abs(eroded - dem).max()) > 1.0  # it changed the land
    assert sansui.select_slope(eroded).shape == (250, 300)
    assert sansui.blend(eroded, grid, sansui.select_height(grid, min=500)).shape == (250, 300)
    assert sansui.erode(np.asarray(dem), cell=CELL).shape == (250, 300)


def test_a_rectangle_and_its_transpose_erode_alike():
    """Rows and columns are not mixed up anywhere: the land turned on its side erodes the same way
    (not to the byte: D8 breaks ties in raster order), by much more than the two differ."""
    r = sansui.midpoint(size=257, cell=CELL, seed=5)[0:180, :]
    along = np.asarray(sansui.erode(r))
    across = np.asarray(sansui.erode(sansui.grid(np.ascontiguousarray(np.asarray(r).T), cell=CELL))).T
    assert along.shape == (180, 257)
    eroded_by = np.abs(along - np.asarray(r)).mean()
    assert np.abs(along - across).mean() < 0.1 * eroded_by
    assert abs(along.mean() - across.mean()) < 0.02 * eroded_by


def test_file_takes_the_file_s_own_size_cell_crs_and_origin(cli, tmp_path, no_world_warnings):
    tif = tmp_path / "t.tif"
    cli("terrain", "--size", 257, "--cell", 30, "--crs", "EPSG:32654", "--origin", "500000,4100000", "--seed", 3, "-o", tif)
    h = sansui.file(path=str(tif))
    assert h.shape == (257, 257) and h.cell == 30.0
    assert h.crs == "EPSG:32654" and h.origin == (500000.0, 4100000.0)
    assert np.array_equal(sansui.file(tif), h)  # the path positional, as os.PathLike
    cli("terrain", "--size", 257, "--cell", 30, "--seed", 3, "-o", tmp_path / "t.r32")
    assert np.array_equal(sansui.file(path=tmp_path / "t.r32"), h)  # its sidecar says the cell
    with pytest.raises(ValueError, match="t.tif is 257x257 samples .* size=1025 was given"):
        sansui.file(path=tif, size=1025)


def test_file_of_a_file_without_a_cell_warns(tmp_path):
    np.zeros((25, 25), "<f4").tofile(tmp_path / "bare.r32")  # no sidecar: square from the file's size
    with pytest.warns(sansui.WorldWarning, match="says no cell size"):
        bare = sansui.file(path=tmp_path / "bare.r32")
    assert bare.shape == (25, 25) and bare.cell == 10.0
    assert sansui.file(path=tmp_path / "bare.r32", cell=2.5).cell == 2.5


def test_file_takes_the_range_of_a_16_bit_file_as_a_recipe_s_file_does(tmp_path, no_world_warnings):
    np.array([[0, 65535], [32768, 65535]], "<u2").tofile(tmp_path / "bare.raw")  # 16-bit, no sidecar
    h = sansui.file(path=tmp_path / "bare.raw", cell=5.0, range=[100.0, 300.0])
    assert float(np.min(h)) == 100.0 and float(np.max(h)) == 300.0
    with pytest.raises(ValueError, match="MIN must be below MAX"):
        sansui.file(path=tmp_path / "bare.raw", cell=5.0, range=[300.0, 100.0])


xarray = pytest.importorskip("xarray")


def test_dataarrays_carry_coordinates_crs_and_sea_level(hills, no_world_warnings):
    h = sansui.midpoint(size=129, cell=CELL, sea_level=5.0, crs="EPSG:32654", origin=(500000.0, 4100000.0), seed=2)
    da = h.to_xarray()
    assert da.dims == ("y", "x") and np.shares_memory(da.values, h)
    assert da.x.values[0] == 500000.0 + CELL / 2 and da.y.values[0] == 4100000.0 - CELL / 2
    assert np.all(np.diff(da.x) == CELL) and np.all(np.diff(da.y) == -CELL)
    assert float(da.sea_level) == 5.0 and da.attrs["units"] == "m"
    assert "spatial_ref" in da.coords
    # Arithmetic drops a DataArray's attributes but keeps its coordinates: the world stays.
    expected = sansui.erode(h)
    for copy in (da, da.copy(), da * 1.0, xarray.where(da > -1e9, da, 0.0)):
        eroded = sansui.erode(copy)
        assert isinstance(eroded, xarray.DataArray) and np.array_equal(eroded.values, expected)
        assert eroded.x.equals(da.x) and eroded.y.equals(da.y) and float(eroded.sea_level) == 5.0
    assert float(abs(sansui.erode(da) - da).max()) > 0  # aligned: the same coordinates


def test_set_arrays_xarray_makes_every_result_a_dataarray():
    sansui.set_arrays("xarray")
    try:
        assert sansui.arrays() == "xarray"
        h = sansui.midpoint(size=65, cell=20.0)
        assert isinstance(h, xarray.DataArray) and h.x.values[1] == 20.0
        recipe = sansui.Recipe({"world": {"size": 65, "cell": 20.0}, "node": [{"id": "h", "kind": "midpoint"}]})
        assert isinstance(recipe.heights(), xarray.DataArray)
    finally:
        sansui.set_arrays("numpy")
    assert isinstance(sansui.midpoint(size=65), sansui.Grid)


rioxarray = pytest.importorskip("rioxarray")


def test_a_round_trip_through_rioxarray_keeps_crs_transform_and_bytes(tmp_path, no_world_warnings):
    h = sansui.midpoint(size=129, cell=CELL, crs="EPSG:32654", origin=(500000.0, 4100000.0), seed=6)
    da = h.to_xarray()
    assert da.rio.crs.to_epsg() == 32654
    assert tuple(da.rio.transform())[:6] == (CELL, 0.0, 500000.0, 0.0, -CELL, 4100000.0)
    assert da.rio.transform().to_gdal() == h.transform
    eroded = sansui.erode(da)
    assert eroded.rio.crs.to_epsg() == 32654 and eroded.rio.transform() == da.rio.transform()
    eroded.rio.to_raster(tmp_path / "e.tif")
    back = rioxarray.open_rasterio(tmp_path / "e.tif")  # (band, y, x): the band is dropped
    assert np.array_equal(back.values[0], eroded.values)
    again = sansui.smooth(back)
    assert again.dims == ("y", "x") and again.rio.crs.to_epsg() == 32654
    assert np.array_equal(again.values, sansui.smooth(sansui.erode(h)))
    from_file = sansui.file(path=tmp_path / "e.tif")  # GDAL's GeoTIFF, read by Sansui
    assert from_file.crs == "EPSG:32654" and from_file.transform == h.transform and np.array_equal(from_file, eroded.values)


def test_without_rioxarray_its_convention_is_written_by_hand(monkeypatch):
    h = sansui.midpoint(size=33, cell=CELL, crs="EPSG:32654", origin=(500000.0, 4100000.0))
    by_rioxarray = h.to_xarray()
    monkeypatch.setattr(sansui._grids, "_rioxarray", False)
    sansui._grids._spatial_ref.cache_clear()
    by_hand = h.to_xarray()
    sansui._grids._spatial_ref.cache_clear()
    assert by_hand.coords["spatial_ref"].attrs["GeoTransform"] == "500000.0 30.0 0.0 4100000.0 0.0 -30.0"
    assert by_hand.rio.crs == by_rioxarray.rio.crs and by_hand.rio.transform() == by_rioxarray.rio.transform()


def test_without_xarray_results_are_plain_grids(tmp_path):
    script = (
        "import sys; sys.modules['xarray'] = None\n"
        "import numpy as np, sansui\n"
        "h = sansui.midpoint(size=33, cell=5.0)\n"
        "assert type(h) is sansui.Grid and h.cell == 5.0\n"
        "try:\n"
        "    sansui.set_arrays('xarray')\n"
        "except ModuleNotFoundError as error:\n"
        "    print('refused:', error)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "refused: xarray is not installed" in done.stdout


def test_nodata_is_filled_by_file_and_refused_in_a_dataarray(tmp_path):
    gdal = pytest.importorskip("osgeo.gdal")
    gdal.UseExceptions()
    dem = np.random.default_rng(1).random((50, 60)).astype(np.float32) * 100
    dem[10:15, 20:30] = -9999
    tif = gdal.GetDriverByName("GTiff").Create(str(tmp_path / "holes.tif"), 60, 50, 1, gdal.GDT_Float32)
    tif.SetGeoTransform((1000.0, 25.0, 0.0, 9000.0, 0.0, -25.0))
    band = tif.GetRasterBand(1)
    band.SetNoDataValue(-9999)
    band.WriteArray(dem)
    tif = band = None
    with pytest.warns(UserWarning, match="50 of 3000 samples .* were NoData"):
        filled = sansui.file(path=tmp_path / "holes.tif")
    assert filled.shape == (50, 60) and filled.cell == 25.0 and filled.origin == (1000.0, 9000.0) and filled.min() >= 0
    with pytest.raises(ValueError, match="holds its nodata value -9999 at row 10, column 20"):
        sansui.erode(rioxarray.open_rasterio(tmp_path / "holes.tif"))


def test_a_dataarray_given_another_world_gets_coordinates_of_that_world():
    da = sansui.midpoint(size=33, cell=10.0).to_xarray()
    moved = sansui.smooth(da, cell=20.0, origin=(1000.0, 2000.0))
    assert moved.x.values[0] == 1010.0 and moved.y.values[0] == 1990.0 and moved.x.values[1] == 1030.0
    assert np.array_equal(sansui.smooth(da, sea_level=3.0).x, da.x)  # the same place: the input's coordinates
