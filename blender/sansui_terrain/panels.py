"""The sidebar panel (View3D > Sidebar > Sansui): the main keys and the buttons on top, every
other key under Advanced (generated.py makes one sub-panel per section)."""
import textwrap

import bpy

from . import generated, module_finder
from .terrain_object import is_terrain


def draw_message(layout, text, icon="ERROR", width=40):
    """A long message as wrapped labels (a panel label does not wrap)."""
    column = layout.column(align=True)
    for i, line in enumerate(textwrap.wrap(text, width)):
        column.label(text=line, icon=icon if i == 0 else "BLANK1")


class SANSUI_PT_main(bpy.types.Panel):
    bl_label = "Sansui terrain"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = generated.CATEGORY

    def draw(self, context):
        layout = self.layout
        if not generated.registered():
            draw_message(layout, module_finder.problem() or module_finder.MISSING)
            return
        obj = context.active_object
        terrain = is_terrain(obj)
        layout.label(text=f"{obj.name}'s recipe" if terrain else "The next terrain", icon="RNDCURVE")
        values = layout.column()
        values.use_property_split = True
        values.use_property_decorate = False
        generated.draw_main(values, generated.target_group(context))
        buttons = layout.column(align=True)
        if terrain:
            buttons.operator("object.sansui_regenerate", icon="FILE_REFRESH")
            buttons.operator("object.sansui_export", text="Export recipe", icon="EXPORT")
        buttons.operator("mesh.sansui_terrain_add", text="Add a terrain", icon="ADD")


class SANSUI_PT_advanced(bpy.types.Panel):
    bl_idname = generated.ADVANCED_PANEL
    bl_label = "Advanced"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = generated.CATEGORY
    bl_parent_id = "SANSUI_PT_main"
    bl_options = {"DEFAULT_CLOSED"}

    @classmethod
    def poll(cls, context):
        return generated.registered()

    def draw(self, context):
        self.layout.label(text="Every other key, by section")


classes = (SANSUI_PT_main, SANSUI_PT_advanced)
