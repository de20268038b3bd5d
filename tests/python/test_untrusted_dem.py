"""A DEM from a stranger, read from Python: refused with one ValueError when it would reach past its
folder or through a driver that is not a DEM's, and the program's own GDAL is left as it was
(Sansui sets its options for its own reads only)."""
import os

import pytest

import sansui

WMS = ('<GDAL_WMS><Service name="WMS"><ServerUrl>http://127.0.0.1:9/wms?</ServerUrl><Layers>x</Layers></Service>'
       '<DataWindow><UpperLeftX>0</UpperLeftX><UpperLeftY>1</UpperLeftY><LowerRightX>1</LowerRightX><LowerRightY>0</LowerRightY>'
       '<SizeX>65</SizeX><SizeY>65</SizeY></DataWindow></GDAL_WMS>\n')


def vrt_over(name):
    return ('<VRTDataset rasterXSize="65" rasterYSize="65"><VRTRasterBand dataType="Float32" band="1"><SimpleSource>'
            f'<SourceFilename relativeToVRT="1">{name}</SourceFilename><SourceBand>1</SourceBand></SimpleSource></VRTRasterBand>'
            '</VRTDataset>\n')


def run_file_recipe(folder, name):
    recipe = sansui.Recipe({"source": "file", "file": {"path": str(folder / name), "cell": 10.0}, "output": [{"file": "h.r32"}]})
    recipe.run(out_dir=str(folder / "out"))


def test_a_vrt_source_that_is_a_service_description_is_refused(tmp_path):
    (tmp_path / "tile.asc").write_text(WMS)
    (tmp_path / "dem.vrt").write_text(vrt_over("tile.asc"))
    with pytest.raises(ValueError, match="WMS dataset, which Sansui does not read") as raised:
        run_file_recipe(tmp_path, "dem.vrt")
    assert "\n" not in str(raised.value)


def test_a_vrt_source_outside_its_folder_is_refused(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "dem.vrt").write_text(vrt_over("../secret.asc"))
    (tmp_path / "secret.asc").write_text("ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\n1 2\n3 4\n")
    with pytest.raises(ValueError, match="outside the VRT's folder"):
        run_file_recipe(tmp_path / "sub", "dem.vrt")


def test_the_programs_own_gdal_keeps_its_drivers_and_options():
    gdal = pytest.importorskip("osgeo.gdal")
    before = gdal.GetDriverCount()
    pam = gdal.GetConfigOption("GDAL_PAM_ENABLED")
    tmp = os.environ.get("TMPDIR", "/tmp")
    path = os.path.join(tmp, f"sansui-untrusted-{os.getpid()}.asc")
    with open(path, "w") as f:
        f.write("ncols 65\nnrows 65\nxllcorner 0\nyllcorner 0\ncellsize 10\n" + ("1 " * 65 + "\n") * 65)
    try:
        sansui.Recipe({"source": "file", "file": {"path": path}, "output": [{"file": "h.r32"}]}).run(out_dir=os.path.join(tmp, f"sansui-untrusted-{os.getpid()}"))
    finally:
        os.unlink(path)
    assert gdal.GetDriverCount() == before
    assert gdal.GetConfigOption("GDAL_PAM_ENABLED") == pam
    assert gdal.GetDriverByName("netCDF") is not None or before == gdal.GetDriverCount()
