"""Add > Mesh > Sansui terrain, Regenerate and Export. Each runs the library first and touches
the scene only when that succeeded: a bad value leaves the scene as it was and is reported in the
status bar."""
import contextlib
import os
import time

import bpy
from bpy_extras.io_utils import ExportHelper

from . import generated, module_finder, recipe_props, scenery_data, terrain_object


def _module_or_report(operator):
    module = module_finder.module()
    if module is not None and generated.registered():
        return module
    operator.report({"ERROR"}, module_finder.problem() or module_finder.MISSING)
    return None


def _compute(operator, context, module, root):
    """SceneryData for the panel's values `root`, or None after reporting why not."""
    manager = context.window_manager
    manager.progress_begin(0, 100)
    try:
        recipe = recipe_props.to_recipe(root, generated.state.sections)
        return scenery_data.compute(module, recipe, root.ground_plants,
                                    lambda stage, fraction: manager.progress_update(100 * fraction))
    except (ValueError, TypeError) as error:
        operator.report({"ERROR"}, f"Sansui: {error}")
        return None
    finally:
        manager.progress_end()


def _see_it_all(context, data):
    """Views clip at 1 km by default: a 10 km terrain would be cut off. The near plane moves out
    with the far one, or the depth buffer's precision runs out and water flickers through land."""
    extent = max(data.heights.shape) * data.cell
    for area in context.screen.areas if context.screen else []:
        for space in area.spaces:
            if space.type == "VIEW_3D" and space.clip_end < 4 * extent:
                space.clip_end = 4 * extent
                space.clip_start = max(space.clip_start, space.clip_end / 20000)


class SANSUI_OT_add_terrain(bpy.types.Operator):
    """Add a Sansui terrain made from the Sansui panel's values (View3D > Sidebar > Sansui)"""
    bl_idname = "mesh.sansui_terrain_add"
    bl_label = "Sansui terrain"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        module = _module_or_report(self)
        if module is None:
            return {"CANCELLED"}
        start = time.perf_counter()
        data = _compute(self, context, module, context.scene.sansui)
        if data is None:
            return {"CANCELLED"}
        obj = terrain_object.create(context.collection, "Sansui terrain", data, context.scene.cursor.location)
        recipe_props.from_recipe(obj.sansui, generated.state.sections, data.recipe)
        obj.sansui.ground_plants = context.scene.sansui.ground_plants
        for other in context.selected_objects:
            other.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        _see_it_all(context, data)
        self.report({"INFO"}, f"Sansui terrain {data.heights.shape[1]}x{data.heights.shape[0]}, "
                              f"{len(data.plants)} plants, in {time.perf_counter() - start:.1f} s")
        return {"FINISHED"}


class SANSUI_OT_regenerate(bpy.types.Operator):
    """Rebuild the active Sansui terrain from its panel values (the same object, new mesh data)"""
    bl_idname = "object.sansui_regenerate"
    bl_label = "Regenerate"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return terrain_object.is_terrain(context.active_object)

    def execute(self, context):
        module = _module_or_report(self)
        if module is None:
            return {"CANCELLED"}
        obj = context.active_object
        data = _compute(self, context, module, obj.sansui)
        if data is None:
            return {"CANCELLED"}
        terrain_object.rebuild(obj, data)
        return {"FINISHED"}


@contextlib.contextmanager
def _working_directory(folder):
    """Recipes made from dicts resolve file names from the working directory, and save() writes
    them relative to the scene file: working in its folder keeps them plain names."""
    before = os.getcwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(before)


def export_recipe(module, recipe, path, splat=True, plants=False, picture=False):
    """Writes `recipe` as a scene file at `path`, with outputs beside it: NAME.r32 (the heights,
    float32), and optionally NAME-splat.png, NAME-plants.csv and NAME.png (a rendered picture).
    The library writes only the sections some output reads: the splat map keeps [climate],
    [season], [weather] and [land]; the plants keep [vegetation]; the picture keeps them all."""
    folder, name = os.path.split(os.path.abspath(path))
    stem = os.path.splitext(name)[0]
    outputs = [{"file": f"{stem}.r32"}]
    if splat:
        outputs.append({"file": f"{stem}-splat.png", "kind": "splat_map"})
    if plants:
        outputs.append({"file": f"{stem}-plants.csv"})
    if picture:
        outputs.append({"file": f"{stem}.png", "kind": "render"})
    with _working_directory(folder):
        module.Recipe(dict(recipe, output=outputs)).save(name)


class SANSUI_OT_export(bpy.types.Operator, ExportHelper):
    """Write the active terrain's recipe as a Sansui scene file: `sansui run FILE` then writes
    the same heights (NAME.r32) beside it"""
    bl_idname = "object.sansui_export"
    bl_label = "Export recipe"
    filename_ext = ".toml"
    filter_glob: bpy.props.StringProperty(default="*.toml", options={"HIDDEN"})
    splat: bpy.props.BoolProperty(
        name="Splat map output", default=True,
        description="NAME-splat.png: the ground's sand, grass, rock and snow weights (keeps the look's sections in the file)")
    plants: bpy.props.BoolProperty(
        name="Plants output", default=False,
        description="NAME-plants.csv: every tree and ground plant (large: millions of rows on large worlds; keeps [vegetation])")
    picture: bpy.props.BoolProperty(
        name="Picture output", default=False, description="NAME.png: the scene as Sansui renders it")

    @classmethod
    def poll(cls, context):
        return terrain_object.is_terrain(context.active_object)

    def execute(self, context):
        module = _module_or_report(self)
        if module is None:
            return {"CANCELLED"}
        try:
            recipe = terrain_object.stored_recipe(context.active_object)
            export_recipe(module, recipe, self.filepath, self.splat, self.plants, self.picture)
        except (ValueError, TypeError, OSError) as error:  # json's errors are ValueErrors
            self.report({"ERROR"}, f"Sansui: {error}")
            return {"CANCELLED"}
        self.report({"INFO"}, f"Wrote {self.filepath}")
        return {"FINISHED"}


def add_menu_entry(self, context):
    self.layout.operator(SANSUI_OT_add_terrain.bl_idname, icon="RNDCURVE")


classes = (SANSUI_OT_add_terrain, SANSUI_OT_regenerate, SANSUI_OT_export)
