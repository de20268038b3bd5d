"""A scene's parts (sansui.scenery, tree, terrain_mesh, parameter_tables): what the Blender add-on
builds from. Each part is checked against the CLI's file of the same recipe where one exists
(heights, splat map, the mesh output's vertices and base colour, `sansui tree`'s mesh), and
against the invariants the docs promise elsewhere (plants on the ground, water below sea level)."""
import re

import numpy as np
import pytest
from PIL import Image

import sansui
from conftest import read_r32

SIZE, CELL = 129, 20.0
RECIPE = {"world": {"size": SIZE, "cell": CELL}, "node": [{"id": "hills", "kind": "midpoint", "seed": 3}]}


@pytest.fixture(scope="module")
def parts():
    return sansui.scenery(RECIPE)


@pytest.fixture(scope="module")
def cli_files(tmp_path_factory, cli):
    """The CLI's heightmap, mesh (with its base colour) and splat map of RECIPE."""
    out = tmp_path_factory.mktemp("scenery")
    recipe = sansui.Recipe(RECIPE).output("h.r32").output("m.obj").output("s.png", kind="splat_map")
    recipe.save(out / "scene.toml")
    cli("run", out / "scene.toml", "--out-dir", out)
    return out


def test_every_part_has_its_shape_and_dtype(parts):
    assert parts["heights"].shape == (SIZE, SIZE) and parts["heights"].dtype == np.float32
    assert parts["colour"].shape == (SIZE, SIZE, 3) and parts["colour"].dtype == np.uint8
    assert parts["splat"].shape == (SIZE, SIZE, 4) and parts["splat"].dtype == np.uint8
    assert parts["water"].shape == (SIZE, SIZE) and parts["water"].dtype == np.float32
    plants = parts["plants"]
    assert plants.ndim == 1 and len(plants) > 0
    for field, dtype in [("x", np.float32), ("y", np.float32), ("z", np.float32), ("species", np.uint16),
                         ("variant", np.uint16), ("scale", np.float32), ("rotation", np.float32), ("layer", np.uint8)]:
        assert plants.dtype[field] == dtype, field
    assert parts["cell"] == CELL
    assert isinstance(parts["sea_level"], float) and isinstance(parts["sea"], bool)
    assert parts["origin"] == (0.0, 0.0)
    assert all(isinstance(name, str) for name in parts["species"])
    assert parts["season"] == "summer" and parts["plant_snow"] is False


def test_the_arrays_are_the_library_s_buffers_not_copies(parts):
    for key in ("heights", "colour", "splat", "water", "plants"):
        assert not parts[key].flags.owndata, key
    # The colour is the RGB of an RGBA buffer: a view stepping over alpha.
    assert parts["colour"].strides == (4 * SIZE, 4, 1)


def test_heights_are_the_recipe_s_bytes_and_the_cli_s(parts, cli_files):
    assert parts["heights"].tobytes() == sansui.Recipe(RECIPE).heights().tobytes()
    assert parts["heights"].tobytes() == read_r32(cli_files / "h.r32", SIZE).tobytes()


def test_splat_is_the_splat_map_output_and_sums_to_255(parts, cli_files):
    assert (parts["splat"].sum(axis=2, dtype=np.int32) == 255).all()
    png = np.asarray(Image.open(cli_files / "s.png").convert("RGBA"))
    assert np.array_equal(parts["splat"], png)


def test_colour_is_the_mesh_output_s_base_colour(parts, cli_files):
    png = np.asarray(Image.open(cli_files / "m_basecolor.png").convert("RGB"))
    assert np.array_equal(parts["colour"], png)


def test_water_is_at_least_the_sea_s_depth_and_dry_land_is_dry(parts):
    heights, water, sea = parts["heights"], parts["water"], parts["sea_level"]
    assert (water >= 0).all()
    below = heights < sea
    assert below.any() and (~below).any()
    np.testing.assert_allclose(water[below], (sea - heights[below]), rtol=1e-6)
    # Raw fractal terrain: the scene draws no lakes or rivers (render.draw_water unset, no erosion).
    assert (water[~below] == 0).all()


def bilinear(heights, column, row):
    c0 = np.minimum(np.floor(column).astype(int), heights.shape[1] - 2)
    r0 = np.minimum(np.floor(row).astype(int), heights.shape[0] - 2)
    ax, ay = column - c0, row - r0
    h = heights.astype(np.float64)
    top = h[r0, c0] * (1 - ax) + h[r0, c0 + 1] * ax
    bottom = h[r0 + 1, c0] * (1 - ax) + h[r0 + 1, c0 + 1] * ax
    return top * (1 - ay) + bottom * ay


def test_plants_stand_on_the_ground_inside_the_world(parts):
    plants, heights = parts["plants"], parts["heights"]
    extent = (SIZE - 1) * CELL
    assert (plants["x"] >= 0).all() and (plants["x"] <= extent).all()
    assert (plants["y"] <= 0).all() and (plants["y"] >= -extent).all()
    column, row = plants["x"].astype(np.float64) / CELL, -plants["y"].astype(np.float64) / CELL
    np.testing.assert_allclose(plants["z"], bilinear(heights, column, row), atol=0.02)
    assert (plants["z"] > parts["sea_level"]).all()
    assert plants["species"].max() < len(parts["species"])
    assert plants["variant"].max() <= 3
    assert set(np.unique(plants["layer"])) <= {0, 1}
    assert ((plants["rotation"] >= 0) & (plants["rotation"] < 2 * np.pi)).all()
    # Trees first, then the ground layer.
    assert (np.diff(plants["layer"].astype(int)) >= 0).all()


def test_scenery_takes_a_recipe_a_dict_or_a_scene_file_and_reports_progress(parts, cli_files):
    stages = []
    from_file = sansui.scenery(cli_files / "scene.toml", progress=lambda stage, fraction: stages.append(stage))
    assert from_file["heights"].tobytes() == parts["heights"].tobytes()
    assert from_file["plants"].tobytes() == parts["plants"].tobytes()
    assert "scenery" in stages
    assert sansui.scenery(sansui.Recipe(RECIPE))["splat"].tobytes() == parts["splat"].tobytes()


def test_tree_meshes_are_valid_and_the_same_bytes_for_the_same_arguments():
    oak = sansui.tree("oak", 1)
    assert oak["vertices"].dtype == np.float32 and oak["vertices"].shape[1] == 3
    assert oak["faces"].dtype == np.uint32 and oak["faces"].shape[1] == 3
    assert oak["colours"].shape == oak["vertices"].shape and oak["normals"].shape == oak["vertices"].shape
    assert oak["faces"].max() < len(oak["vertices"])
    assert ((oak["colours"] >= 0) & (oak["colours"] <= 1)).all()
    # Standing on the origin, z up.
    assert oak["vertices"][:, 2].min() > -0.5 and oak["vertices"][:, 2].max() > 5
    again = sansui.tree("oak", variant=1)
    for key in oak:
        assert oak[key].tobytes() == again[key].tobytes(), key
    assert sansui.tree("oak", seed=5)["vertices"].tobytes() == oak["vertices"].tobytes()  # seed 5 is variant 1
    assert sansui.tree("oak", 2)["vertices"].tobytes() != oak["vertices"].tobytes()
    bare = sansui.tree("oak", 1, season="winter")
    assert len(bare["faces"]) < len(oak["faces"])  # no leaves in winter


def obj_arrays(path):
    vertices, faces = [], []
    for line in path.read_text().splitlines():
        if line.startswith("v "):
            vertices.append([float(v) for v in line.split()[1:4]])
        elif line.startswith("f "):
            faces.append([int(corner.split("/")[0]) - 1 for corner in line.split()[1:4]])
    return np.array(vertices, dtype=np.float32), np.array(faces, dtype=np.uint32)


def test_tree_is_sansui_tree_s_mesh_turned_to_z_up(tmp_path, cli):
    cli("tree", "--species", "spruce", "--seed", "2", "--season", "autumn", "-o", tmp_path / "t.obj")
    vertices, faces = obj_arrays(tmp_path / "t.obj")
    spruce = sansui.tree("spruce", 2, season="autumn")
    assert np.array_equal(spruce["faces"], faces)
    turned = np.stack([vertices[:, 0], 0 - vertices[:, 2], vertices[:, 1]], axis=1)
    assert np.array_equal(spruce["vertices"], turned)


def test_terrain_mesh_is_the_mesh_output_s_triangulation_turned_to_z_up(parts, cli_files):
    heights = parts["heights"]
    vertices, faces = sansui.terrain_mesh(heights)  # the cell from the world the array was made on
    assert vertices.shape == (SIZE * SIZE, 3) and vertices.dtype == np.float32
    assert faces.shape == (2 * (SIZE - 1) ** 2, 3) and faces.dtype == np.uint32
    obj_vertices, obj_faces = obj_arrays(cli_files / "m.obj")
    assert np.array_equal(faces, obj_faces)
    turned = np.stack([obj_vertices[:, 0], 0 - obj_vertices[:, 2], obj_vertices[:, 1]], axis=1)
    assert np.array_equal(vertices, turned)
    assert np.array_equal(vertices[:, 2], heights.ravel())
    # Counter-clockwise seen from above.
    a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
    assert (np.cross(b - a, c - a)[:, 2] > 0).all()
    plain, _ = sansui.terrain_mesh(np.asarray(heights).copy(), cell=5)
    assert plain[SIZE, 1] == -5.0 and plain[1, 0] == 5.0


def cli_rows(params_markdown, heading):
    """The rows of one table of `sansui params` as {key: (allowed, default)}."""
    section = params_markdown.split(heading + "\n", 1)[1].split("\n#", 1)[0]
    rows = {}
    for line in section.splitlines():
        match = re.match(r"\| `([^`]+)` \|", line)
        if match:
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            rows[match.group(1)] = (cells[3].replace("\\|", "|"), cells[4].replace("\\|", "|"))
    return rows


def test_parameter_tables_match_sansui_params(cli):
    tables = sansui.parameter_tables()
    assert {"world", "node.midpoint", "node.erode", "climate", "season", "weather", "time", "vegetation", "flow", "land",
            "render"} <= set(tables)
    assert "midpoint" not in tables  # a source's section: not the look's
    markdown = cli("params").stdout
    for table, heading in [("world", "## [world]"), ("node.midpoint", '### kind = "midpoint"'), ("node.erode", '### kind = "erode"'),
                           ("climate", "## [climate]"), ("vegetation", "## [vegetation]"), ("time", "## [time]")]:
        expected = cli_rows(markdown, heading)
        rows = {row["key"]: row for row in tables[table]["rows"]}
        assert set(rows) == set(expected), table
        for key, (allowed, default) in expected.items():
            assert rows[key]["default_text"] == default, f"{table}.{key}"
            assert rows[key]["allowed"] == allowed or rows[key]["kind"] == "choice", f"{table}.{key}"
    cell = {row["key"]: row for row in tables["world"]["rows"]}["cell"]
    assert (cell["kind"], cell["unit"], cell["default"], cell["min"], cell["min_exclusive"]) == ("real", "m", 10.0, 0.0, True)
    hurst = {row["key"]: row for row in tables["node.midpoint"]["rows"]}["hurst"]
    assert (hurst["default"], hurst["min"], hurst["max"], hurst["max_exclusive"]) == (0.7, 0.0, 1.0, False)
    koppen = tables["climate"]["rows"][0]
    assert koppen["kind"] == "choice" and "Cfb" in koppen["choices"] and koppen["default"] == "Cfb"
    sun = {row["key"]: row for row in tables["time"]["rows"]}["sun"]
    assert sun["kind"] == "reals" and sun["count"] == [2, 2] and sun["optional"] and sun["default"] is None
    # Superseded keys are left out: the sea level is the world's.
    assert "sea_level" not in {row["key"] for row in tables["render"]["rows"]}


def one_line(error):
    return "\n" not in str(error.value) and str(error.value)


@pytest.mark.parametrize("call, error", [
    (lambda: sansui.tree("no_such_plant"), ValueError),
    (lambda: sansui.tree(3), TypeError),
    (lambda: sansui.tree("oak", 9), ValueError),
    (lambda: sansui.tree("oak", "1"), TypeError),
    (lambda: sansui.tree("oak", 2, seed=5), ValueError),
    (lambda: sansui.tree("oak", season="monsoon"), ValueError),
    (lambda: sansui.scenery(42), TypeError),
    (lambda: sansui.scenery({"world": {"size": -1}}), ValueError),
    (lambda: sansui.scenery({"world": {"size": 65}, "node": [{"id": "h", "kind": "midpoint"}], "climate": {"koppen": "X"}}),
     ValueError),
    (lambda: sansui.scenery(RECIPE, progress=3), TypeError),
    (lambda: sansui.terrain_mesh(np.zeros((3, 3, 3), np.float32)), ValueError),
    (lambda: sansui.terrain_mesh(np.zeros((3, 3), np.float32), cell=-1), ValueError),
    (lambda: sansui.terrain_mesh(np.zeros((3, 3), np.float32), world=3), TypeError),
    (lambda: sansui.terrain_mesh(np.zeros((1, 1), np.float32)), ValueError),
])
def test_bad_input_raises_one_line(call, error):
    with pytest.raises(error) as raised:
        call()
    assert one_line(raised)


def test_lakes_and_rivers_hold_water_where_the_scene_draws_them_and_no_plant_stands_in_them():
    recipe = {"world": {"size": SIZE, "cell": CELL}, "render": {"draw_water": True},
              "node": [{"id": "hills", "kind": "midpoint", "seed": 3},
                       {"id": "eroded", "kind": "erode", "inputs": ["hills"], "stage": "mature"}]}
    parts = sansui.scenery(recipe)
    heights, water, plants = parts["heights"], parts["water"], parts["plants"]
    inland = (water > 0) & (heights > parts["sea_level"])
    assert inland.any()
    # The renderer's rule: no plant whose nearest sample is under a lake or river (one by the
    # sea stands on the beach, its nearest sample under the sea).
    column = np.rint(plants["x"] / CELL).astype(int)
    row = np.rint(-plants["y"] / CELL).astype(int)
    assert not inland[row, column].any()
