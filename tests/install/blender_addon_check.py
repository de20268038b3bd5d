"""The Blender add-on as the sansui-blender package installs it, in a real Blender, headless:

    blender -b --factory-startup --python-exit-code 1 --python tests/install/blender_addon_check.py -- ROOT

ROOT is a folder the packages were installed into (dpkg --root). Checks that this Blender reads
its system add-ons from /usr/share/blender/scripts/addons, where the package puts the add-on;
then finds the add-on under ROOT's copy of that folder (as a scripts folder of the
preferences), enables it with the module of ROOT's dist-packages, and adds a small terrain."""
import os
import sys

import addon_utils
import bpy

root = sys.argv[sys.argv.index("--") + 1]
system_addons = "/usr/share/blender/scripts/addons"
paths = [os.path.normpath(path) for path in addon_utils.paths()]
if system_addons not in paths:
    raise AssertionError(f"Blender does not read add-ons from {system_addons}: {paths}")

sys.path.insert(0, os.path.join(root, "usr/lib/python3/dist-packages"))
bpy.context.preferences.filepaths.script_directory = os.path.join(root, "usr/share/blender/scripts")
bpy.utils.refresh_script_paths()


def raise_it(error):
    raise error


addon_utils.enable("sansui_terrain", default_set=True, handle_error=raise_it)
import sansui  # noqa: E402  (the add-on's module: ROOT's)

if not sansui.__file__.startswith(root):
    raise AssertionError(f"the module came from {sansui.__file__}, not from {root}")
module = sys.modules["sansui_terrain"]
if not module.__file__.startswith(os.path.join(root, "usr/share/blender/scripts/addons")):
    raise AssertionError(f"the add-on came from {module.__file__}")
before = len(bpy.data.objects)
bpy.context.scene.sansui.world.size = 65  # small: this checks the installed files, not the terrain
bpy.ops.mesh.sansui_terrain_add()
if len(bpy.data.objects) <= before:
    raise AssertionError("Add > Mesh > Sansui terrain added no object")
print(f"deb: Blender {bpy.app.version_string} enables the installed add-on ({module.__file__}) and adds a terrain")
