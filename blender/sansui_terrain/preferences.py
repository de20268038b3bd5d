"""The add-on's preferences: where to find Sansui's Python module when it is not installed."""
import bpy

from . import generated, module_finder

ADDON = __package__


def connect(folder=""):
    """Finds the module (installed, else in `folder`) and, found, makes the panel's properties
    from its parameter tables. Never raises: a problem is kept for the panel and reports."""
    module = module_finder.load(folder) if module_finder.module() is None else module_finder.module()
    if module is None or generated.registered():
        return
    if not hasattr(module, "parameter_tables"):
        module_finder.set_problem(f"The sansui module at {module.__file__} is too old for this add-on "
                                  "(it has no parameter_tables()): build or install a newer Sansui")
        return
    try:
        generated.register(module.parameter_tables())
    except Exception as error:  # noqa: BLE001 (register must not raise: say it in the panel)
        generated.unregister()
        module_finder.set_problem(f"Sansui's parameter tables could not be read: {error}")


def _folder_changed(self, context):
    connect(self.module_path)


class SANSUI_AP_preferences(bpy.types.AddonPreferences):
    bl_idname = ADDON

    module_path: bpy.props.StringProperty(
        name="Module folder", subtype="DIR_PATH", update=_folder_changed,
        description="The folder holding the sansui package (e.g. Sansui's build/python), when Sansui "
                    "is not installed into Python's dist-packages")

    def draw(self, context):
        self.layout.prop(self, "module_path")
        if module_finder.module() is None or not generated.registered():
            from .panels import draw_message
            draw_message(self.layout, module_finder.problem() or module_finder.MISSING, width=90)
        else:
            self.layout.label(text=f"Using {module_finder.module().__file__}", icon="CHECKMARK")


def saved_folder():
    """The module folder set in the preferences, or "" (also while the add-on is being enabled
    for the first time, before Blender has made its preferences)."""
    addon = bpy.context.preferences.addons.get(ADDON)
    return addon.preferences.module_path if addon and addon.preferences else ""


classes = (SANSUI_AP_preferences,)
