"""Makes docs/blender.md's pictures in Blender (docs/blender.sh runs it):

    blender -b --factory-startup --python docs/blender_pictures.py -- --build build --render OUT.png
    xvfb-run -s "-screen 0 1280x800x24" blender --factory-startup --enable-event-simulate \\
        --python docs/blender_pictures.py \\
        -- --build build --panel OUT.png

--render: a 513² terrain added by the add-on, rendered with Cycles on the CPU under a sky.
--panel: Blender's window with the same terrain and the Sidebar's Sansui panel (a screenshot of
the 3-D view; it needs a display, hence Xvfb)."""
import argparse
import math
import os
import sys

import addon_utils
import bpy
from mathutils import Euler, Vector

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def options():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender_pictures.py")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--render", help="write the rendered picture here")
    parser.add_argument("--panel", help="write the screenshot of the panel here")
    parser.add_argument("--samples", type=int, default=48)
    return parser.parse_args(argv)


def add_terrain(build, size, rough):
    sys.path.insert(0, os.path.join(ROOT, "blender"))
    addon_utils.enable("sansui_terrain", default_set=True)
    bpy.context.preferences.addons["sansui_terrain"].preferences.module_path = os.path.join(os.path.abspath(build), "python")
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    values = bpy.context.scene.sansui
    values.world.size = size
    values.node_midpoint.seed = 46
    values.node_midpoint.land_fraction = 0.6
    if rough:  # a rougher land than the default for its extent: mountains in the picture
        values.node_midpoint.sigma__set = True
        values.node_midpoint.sigma = 400.0
    values.shaping = "erode"
    values.node_erode.stage = "mature"
    bpy.ops.mesh.sansui_terrain_add()
    return bpy.context.active_object


def light_and_camera(terrain):
    scene = bpy.context.scene
    half = max(terrain.dimensions.x, terrain.dimensions.y) / 2
    top = terrain.matrix_world.translation.z + terrain.dimensions.z
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.data.lens = 30
    camera.data.clip_end = 10 * half
    camera.location = Vector((-0.3 * half, -1.15 * half, top + 0.15 * half))
    target = Vector((-0.04 * half, 0.15 * half, -0.52 * half))
    camera.rotation_euler = (target - camera.location).to_track_quat("-Z", "Y").to_euler()
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 4.0
    sun.data.angle = math.radians(2)
    sun.rotation_euler = (math.radians(55), 0, math.radians(-40))
    for obj in (camera, sun):
        scene.collection.objects.link(obj)
    scene.camera = camera
    scene.world = bpy.data.worlds.new("Sky")
    scene.world.use_nodes = True
    nodes = scene.world.node_tree.nodes
    sky = nodes.new("ShaderNodeTexSky")
    sky.sky_type = "NISHITA"
    sky.sun_elevation = math.radians(35)
    sky.sun_rotation = math.radians(140)
    scene.world.node_tree.links.new(sky.outputs["Color"], nodes["Background"].inputs["Color"])
    nodes["Background"].inputs["Strength"].default_value = 0.35


def render(path, samples):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.cycles.filter_width = 2.0     # a little softer, a lot less noise for the PNG to hold
    scene.render.resolution_x, scene.render.resolution_y = 800, 450
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Filmic"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 100
    scene.render.filepath = os.path.abspath(path)
    bpy.ops.render.render(write_still=True)


def open_advanced():
    """Re-registers the Advanced panel open (it starts closed), so that the picture shows its
    generated sections; its sub-panels go and come back with it."""
    from sansui_terrain import generated, panels
    sections = [c for c in generated.state.classes if issubclass(c, bpy.types.Panel)]
    for cls in reversed(sections):
        bpy.utils.unregister_class(cls)
    bpy.utils.unregister_class(panels.SANSUI_PT_advanced)
    panels.SANSUI_PT_advanced.bl_options = set()
    for cls in [panels.SANSUI_PT_advanced] + sections:
        bpy.utils.register_class(cls)


def screenshot_panel(terrain, path):
    """Opens the Sidebar on its Sansui tab, takes a screenshot of the 3-D view once the window
    has drawn, and quits. Blender 3.4 has no Python setting for the Sidebar's tab: Ctrl+Wheel
    over the Sidebar steps through its tabs (Item, Tool, View, Sansui), sent as simulated events
    (hence --enable-event-simulate)."""
    bpy.context.preferences.view.show_splash = False
    open_advanced()
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    space = area.spaces.active
    space.show_region_ui = True
    space.shading.type = "SOLID"
    space.shading.color_type = "TEXTURE"
    region = next(r for r in area.regions if r.type == "WINDOW")
    view = space.region_3d
    view.view_perspective = "PERSP"
    view.view_location = (0.0, 0.0, 0.0)
    view.view_rotation = Euler((math.radians(58), 0.0, math.radians(-28))).to_quaternion()
    view.view_distance = 1.6 * max(terrain.dimensions.x, terrain.dimensions.y)

    def step_tabs():
        sidebar = next(r for r in area.regions if r.type == "UI")
        x, y = sidebar.x + sidebar.width // 2, sidebar.y + sidebar.height // 2
        window.event_simulate("MOUSEMOVE", "NOTHING", x=x, y=y)
        for _ in range(3):
            window.event_simulate("WHEELDOWNMOUSE", "PRESS", x=x, y=y, ctrl=True)
        bpy.app.timers.register(shoot, first_interval=2.0)

    def shoot():
        try:
            with bpy.context.temp_override(window=window, area=area, region=region):
                bpy.ops.screen.screenshot_area(filepath=os.path.abspath(path))
        finally:
            bpy.ops.wm.quit_blender()

    bpy.app.timers.register(step_tabs, first_interval=2.0)


def main():
    args = options()
    terrain = add_terrain(args.build, 513 if args.render else 257, rough=bool(args.render))
    if args.render:
        light_and_camera(terrain)
        render(args.render, args.samples)
    if args.panel:
        screenshot_panel(terrain, args.panel)


main()
