"""Sansui terrain for Blender: Add > Mesh > Sansui terrain makes a terrain object from a Sansui
recipe (ground mesh with its colour and splat images, water, plants as instances); the sidebar's
Sansui panel, generated from the library's parameter tables, edits the recipe, regenerates the
terrain in place and exports the recipe for `sansui run`. docs/blender.md."""

bl_info = {
    "name": "Sansui terrain",
    "author": "Sansui",
    "version": (0, 2, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Add > Mesh > Sansui terrain; View3D > Sidebar > Sansui",
    "description": "Deterministic natural terrain, water and plants from Sansui recipes",
    "category": "Add Mesh",
}

import bpy

from . import generated, operators, panels, preferences

_CLASSES = preferences.classes + operators.classes + panels.classes


def register():
    for cls in _CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_mesh_add.append(operators.add_menu_entry)
    preferences.connect(preferences.saved_folder())


def unregister():
    generated.unregister()
    bpy.types.VIEW3D_MT_mesh_add.remove(operators.add_menu_entry)
    for cls in reversed(_CLASSES):
        bpy.utils.unregister_class(cls)
