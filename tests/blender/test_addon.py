"""The Blender add-on (blender/sansui_terrain), headless:

    blender -b --factory-startup --python tests/blender/test_addon.py -- --build build

Enables the add-on from the source tree (first without the module: one clear message; then with
the module folder set in its preferences), adds a 257² terrain and checks its vertices against
the recipe's heights, its bounds, material, water and plants (instances of shared meshes, at the
plants' places); Regenerate after a seed change; a failed Add and a failed Regenerate leave the
scene as it was; Export, then `sansui run`, writes the object's heights byte for byte. Exits
non-zero on the first failure."""
import argparse
import importlib.util
import os
import subprocess
import sys
import tempfile
import time
import traceback

import addon_utils
import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ADDON = "sansui_terrain"
SIZE = 257


def options():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="test_addon.py")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build tree (python/, sansui)")
    return parser.parse_args(argv)


def raise_it(error):
    """addon_utils' error handler: fail the test (its default prints and goes on)."""
    raise error


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def fails_with(operator, text, **keys):
    """Runs a Blender operator that must report an error containing `text`."""
    try:
        operator(**keys)
    except RuntimeError as error:
        check(text in str(error), f"the error says '{text}': {error}")
        return
    raise AssertionError(f"{operator.idname_py()} should have failed")


def vertices_of(mesh):
    co = np.empty(len(mesh.vertices) * 3, np.float32)
    mesh.vertices.foreach_get("co", co)
    return co.reshape(-1, 3)


def orphans():
    """The datablocks nothing uses (what a rebuild must not leave behind)."""
    return {(name, item.name) for name in ("meshes", "materials", "images", "collections", "node_groups", "objects")
            for item in getattr(bpy.data, name) if item.users == 0}


def scene_counts():
    return {name: len(getattr(bpy.data, name)) for name in
            ("objects", "meshes", "materials", "images", "collections", "node_groups")}


def enable_addon(build):
    sys.path.insert(0, os.path.join(ROOT, "blender"))
    missing = importlib.util.find_spec("sansui") is None
    addon_utils.enable(ADDON, default_set=True, handle_error=raise_it)
    if missing:  # not installed: the add-on registered anyway and says what to do
        fails_with(bpy.ops.mesh.sansui_terrain_add, "Python module was not found")
        check(not hasattr(bpy.types.Scene, "sansui"), "no panel values without the module")
    bpy.context.preferences.addons[ADDON].preferences.module_path = os.path.join(os.path.abspath(build), "python")
    check(hasattr(bpy.types.Scene, "sansui"), "the module folder in the preferences brings the panel")
    import sansui
    return sansui


def check_terrain(sansui, obj):
    """Vertices, bounds and material against the recipe's own heights and scenery."""
    from sansui_terrain import terrain_object
    recipe = terrain_object.stored_recipe(obj)
    heights = sansui.Recipe(recipe).heights()
    cell = recipe["world"].get("cell", 10.0)
    co = vertices_of(obj.data)
    check(len(co) == SIZE * SIZE, f"{SIZE}² vertices: {len(co)}")
    check(np.array_equal(co[:, 2], heights.ravel()), "vertex z are the heights, as float32")
    extent = (SIZE - 1) * cell
    for axis in (0, 1):
        check(np.isclose(co[:, axis].min(), -extent / 2) and np.isclose(co[:, axis].max(), extent / 2),
              f"axis {axis} spans the world's {extent} m")
    check(co[0, 1] > co[-1, 1] and co[0, 0] < co[SIZE - 1, 0], "row 0 north, column 0 west")
    check(len(obj.data.polygons) == (SIZE - 1) ** 2 and len(obj.data.uv_layers) == 1, "a quad a cell, with UVs")
    material = obj.data.materials[0]
    shader = material.node_tree.nodes["Principled BSDF"]
    base = shader.inputs["Base Color"].links[0].from_node
    check(base.type == "TEX_IMAGE" and tuple(base.image.size) == (SIZE, SIZE), "base colour: the colour image")
    images = [n.image for n in material.node_tree.nodes if n.type == "TEX_IMAGE"]
    check(any(i.colorspace_settings.name == "Non-Color" and i is not base.image for i in images), "the splat image")
    check(base.image.packed_file is not None, "images are packed into the .blend")
    return recipe, heights


def plant_instances(plants_obj):
    """(positions, instanced mesh names) of the plant object's instances, from the depsgraph."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    positions, meshes = [], []
    for instance in depsgraph.object_instances:
        if instance.is_instance and instance.parent and instance.parent.original == plants_obj:
            positions.append(tuple(instance.matrix_world.translation))
            meshes.append(instance.object.data.original.name)
    return np.array(positions, np.float64).reshape(-1, 3), meshes


def check_parts(sansui, obj, recipe, heights):
    """Water over the wet samples; plants as instances of one shared mesh per kind."""
    parts = {c["sansui_part"]: c for c in obj.children if "sansui_part" in c}
    scenery = sansui.scenery(recipe)
    if (scenery["water"] > 0).any():
        water = vertices_of(parts["water"].data)
        check(len(water) >= int((scenery["water"] > 0).sum()), "a water vertex for every wet sample")
    trees = scenery["plants"][scenery["plants"]["layer"] == 0]
    check(len(trees) > 0, "the default climate grows trees")
    plants_obj = parts["plants"]
    check(len(plants_obj.data.vertices) == len(trees), "a point a tree")
    viewport, render = (m for m in plants_obj.modifiers if m.type == "NODES")
    share_key = viewport.node_group.inputs["Share"].identifier
    check(render.show_render and not render.show_viewport and render[share_key] == 1.0, "renders draw every plant")
    share = viewport[share_key]
    shown = len(plant_instances(plants_obj)[0])
    spread = 5 * np.sqrt(len(trees) * share * (1 - share)) + 1
    check(abs(shown - share * len(trees)) <= spread, f"the viewport draws a share {share:.3f} of the plants: {shown}")
    viewport[share_key] = 1.0
    plants_obj.update_tag()
    positions, meshes = plant_instances(plants_obj)
    kinds = {(int(s), int(v)) for s, v in zip(trees["species"], trees["variant"])}
    check(len(positions) == len(trees), f"an instance a tree: {len(positions)} of {len(trees)}")
    check(len(set(meshes)) == len(kinds), f"one mesh a kind: {len(set(meshes))} meshes, {len(kinds)} kinds")
    check(len(bpy.data.meshes) < len(kinds) + 10, "instances, not copies: no mesh a plant")
    half = (SIZE - 1) * scenery["cell"] / 2
    expected = np.stack([trees["x"] - half, trees["y"] + half, trees["z"]], axis=1) + np.array(obj.location)
    order = lambda p: p[np.lexsort(p.T[::-1])]  # noqa: E731
    check(np.allclose(order(positions), order(expected.astype(np.float64)), atol=1e-2), "instances stand on the plants' places")


def run_export(obj, build, folder):
    path = os.path.join(folder, "exported.toml")
    bpy.ops.object.sansui_export(filepath=path)
    subprocess.run([os.path.join(build, "sansui"), "--quiet", "run", path], check=True, cwd=folder)
    written = np.fromfile(os.path.join(folder, "exported.r32"), "<f4")
    check(written.tobytes() == vertices_of(obj.data)[:, 2].tobytes(), "sansui run gives the object's heights, bytes")


def main():
    args = options()
    build = os.path.abspath(args.build)
    started = time.perf_counter()
    sansui = enable_addon(build)
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    settings = bpy.context.scene.sansui
    settings.world.size = SIZE
    settings.node_midpoint.seed = 7
    settings.shaping = "erode"

    before = scene_counts()
    settings.world.size = 300  # not 2^k+1: the library refuses it
    fails_with(bpy.ops.mesh.sansui_terrain_add, "size")
    check(scene_counts() == before, f"a failed Add leaves the scene as it was: {scene_counts()} vs {before}")
    settings.world.size = SIZE

    bpy.ops.mesh.sansui_terrain_add()
    obj = bpy.context.active_object
    recipe, heights = check_terrain(sansui, obj)
    check(recipe["node"][0]["seed"] == 7 and recipe["node"][1]["kind"] == "erode", "the recipe is stored on the object")
    check_parts(sansui, obj, recipe, heights)

    from sansui_terrain import generated, recipe_props
    check(recipe_props.to_recipe(obj.sansui, generated.state.sections) == recipe, "the object's panel values are its recipe")
    settings.node_midpoint.sigma__set = True
    settings.node_midpoint.sigma = 80.0
    check(recipe_props.to_recipe(settings, generated.state.sections)["node"][0]["sigma"] == 80.0, "a key set: in the recipe")
    settings.node_midpoint.sigma__set = False
    check("sigma" not in recipe_props.to_recipe(settings, generated.state.sections)["node"][0], "unset: left out")

    left_over = orphans()
    obj.sansui.node_midpoint.seed = 8
    mesh_before = obj.data
    bpy.ops.object.sansui_regenerate()
    check(orphans() == left_over, f"Regenerate leaves nothing behind: {orphans() - left_over}")
    check(bpy.context.active_object == obj and obj.data != mesh_before, "Regenerate: the same object, new mesh data")
    recipe, new_heights = check_terrain(sansui, obj)
    check(recipe["node"][0]["seed"] == 8 and not np.array_equal(new_heights, heights), "a new seed, new heights")
    check_parts(sansui, obj, recipe, new_heights)

    before, z_before = scene_counts(), vertices_of(obj.data)[:, 2].tobytes()
    obj.sansui.world.size = 300
    fails_with(bpy.ops.object.sansui_regenerate, "size")
    check(scene_counts() == before and vertices_of(obj.data)[:, 2].tobytes() == z_before,
          "a failed Regenerate leaves the scene as it was")
    obj.sansui.world.size = SIZE

    with tempfile.TemporaryDirectory() as folder:
        run_export(obj, build, folder)

    addon_utils.disable(ADDON, default_set=True, handle_error=raise_it)
    check(not hasattr(bpy.types.Scene, "sansui"), "disabling the add-on takes its properties away")
    print(f"test_addon: all checks passed in {time.perf_counter() - started:.1f} s")


try:
    main()
except Exception:  # noqa: BLE001 (any failure: non-zero exit code for CTest)
    traceback.print_exc()
    sys.stdout.flush()
    os._exit(1)
