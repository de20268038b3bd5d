"""Whole recipes from Python: dicts, node calls, files, and the same bytes as `sansui run`."""
import pathlib

import numpy as np
import pytest

import sansui
from conftest import read_r32

GRAPH = {
    "world": {"size": 129, "cell": 20.0},
    "node": [
        {"id": "hills", "kind": "midpoint", "seed": 5},
        {"id": "eroded", "kind": "erode", "inputs": ["hills"], "stage": "young"},
    ],
    "output": [{"file": "e.r32", "node": "eroded"}],
}


def test_a_dict_a_chain_of_node_calls_and_node_functions_agree():
    from_dict = sansui.Recipe(GRAPH)
    chained = (
        sansui.Recipe({"world": sansui.World(size=129, cell=20.0)})
        .node("hills", "midpoint", seed=5)
        .node("eroded", "erode", "hills", stage="young")
        .output("e.r32", node="eroded")
    )
    assert from_dict.node_ids == chained.node_ids == ["hills", "eroded"]
    heights = from_dict.heights()
    assert np.array_equal(heights, chained.heights())
    world = sansui.World(size=129, cell=20.0)
    assert np.array_equal(heights, sansui.erode(sansui.midpoint(world=world, seed=5), stage="young"))
    assert np.array_equal(from_dict.heights("hills"), sansui.midpoint(world=world, seed=5))


def test_run_writes_the_bytes_the_cli_writes(tmp_path, cli):
    recipe = sansui.Recipe(GRAPH)
    written = recipe.run(out_dir=tmp_path / "py")
    assert [pathlib.Path(p).name for p in written] == ["e.r32"]
    recipe.save(tmp_path / "scene.toml")
    cli("run", tmp_path / "scene.toml", "--out-dir", tmp_path / "cli")
    assert (tmp_path / "py" / "e.r32").read_bytes() == (tmp_path / "cli" / "e.r32").read_bytes()
    assert np.array_equal(read_r32(tmp_path / "py" / "e.r32", 129), recipe.heights())


def test_toml_and_dict_round_trips_keep_the_recipe():
    recipe = sansui.Recipe(GRAPH)
    again = sansui.Recipe.from_toml(recipe.to_toml())
    assert again.to_dict() == recipe.to_dict()
    assert sansui.Recipe(recipe.to_dict()).to_dict() == recipe.to_dict()
    assert recipe.world.size == 129 and recipe.world.cell == 20.0


def test_run_takes_a_scene_file(examples, tmp_path):
    written = sansui.run(examples / "scenes" / "graphs" / "terraces-on-steep-slopes.toml", out_dir=tmp_path)
    assert written and all(pathlib.Path(p).parent == tmp_path for p in written)
    assert all(pathlib.Path(p).stat().st_size > 0 for p in written)


def test_a_recipe_s_warnings_are_kept():
    recipe = sansui.Recipe({"world": {"size": 65}, "render": {"width": 64}, "node": [{"id": "a", "kind": "constant"}]})
    assert any("render" in warning for warning in recipe.warnings), recipe.warnings


def test_unknown_node_ids_are_refused():
    with pytest.raises(ValueError, match="no node 'nope'"):
        sansui.Recipe(GRAPH).heights("nope")
