"""A terrain object and its parts in Blender, from SceneryData: the ground mesh (UVs, material
from the colour and splat images), the water as a child object, the plants as a child point cloud
instancing one mesh per plant kind.

Everything new is made first and linked last; if making fails, what was made is removed and the
scene is as it was. Regenerate swaps the object's mesh (same object, new data) and replaces its
parts, removing the old ones where nothing else uses them."""
import json

import bpy

from . import materials, mesh_build, trees

RECIPE_PROPERTY = "sansui_recipe"  # on the terrain object: the recipe as JSON
PART_PROPERTY = "sansui_part"      # on its children: "water" or "plants"
VIEWPORT_PLANTS = 10000            # about as many plants drawn in the viewport (all in renders)


def is_terrain(obj):
    return obj is not None and obj.type == "MESH" and RECIPE_PROPERTY in obj


def stored_recipe(obj):
    return json.loads(obj[RECIPE_PROPERTY])


class _Made:
    """The datablocks made so far, to remove them all if a later step fails."""

    def __init__(self):
        self.items = []

    def add(self, pool, item):
        self.items.append((pool, item))
        return item

    def remove_all(self):
        for pool, item in reversed(self.items):
            pool.remove(item)
        self.items.clear()


def _new_object(made, name, data, part=None):
    obj = made.add(bpy.data.objects, bpy.data.objects.new(name, data))
    if part:
        obj[PART_PROPERTY] = part
    return obj


def _ground(made, name, data):
    mesh = made.add(bpy.data.meshes, mesh_build.terrain_mesh(name, data.heights, data.cell))
    colour = made.add(bpy.data.images, materials.image_from_pixels(f"{name} colour", data.colour, "sRGB"))
    splat = made.add(bpy.data.images, materials.image_from_pixels(f"{name} splat", data.splat, "Non-Color"))
    mesh.materials.append(made.add(bpy.data.materials, materials.terrain_material(name, colour, splat)))
    return mesh


def _water(made, name, data):
    mesh = mesh_build.water_mesh(f"{name} water", data.heights, data.water, data.cell)
    if mesh is None:
        return None
    made.add(bpy.data.meshes, mesh)
    mesh.materials.append(made.add(bpy.data.materials, materials.water_material(f"{name} water")))
    return _new_object(made, f"{name} water", mesh, "water")


def _plants(made, name, data):
    if not data.kinds:
        return None
    material = made.add(bpy.data.materials, materials.plant_material(f"{name} plant", trees.COLOUR,
                                                                     trees.mean_colour(data.trees)))
    meshes = [made.add(bpy.data.meshes, trees.plant_mesh(trees.kind_name(i, *kind), tree, material))
              for i, (kind, tree) in enumerate(zip(data.kinds, data.trees))]
    collection = made.add(bpy.data.collections, trees.plant_collection(f"{name} plant kinds", data.kinds, meshes))
    for child in collection.objects:
        made.add(bpy.data.objects, child)
    offsets = mesh_build.grid_offsets(*data.heights.shape, data.cell)
    points = made.add(bpy.data.meshes, trees.plant_points(f"{name} plants", data.plants, data.kind_of_plant, offsets))
    obj = _new_object(made, f"{name} plants", points, "plants")
    nodes = made.add(bpy.data.node_groups, trees.instancing_nodes(f"{name} plants", collection))
    trees.add_instancing(obj, nodes, min(1.0, VIEWPORT_PLANTS / len(data.plants)))
    return obj


def _make_parts(name, data):
    """The new ground mesh and the unlinked water and plant objects."""
    made = _Made()
    try:
        ground = _ground(made, name, data)
        children = [c for c in (_water(made, name, data), _plants(made, name, data)) if c is not None]
    except Exception:
        made.remove_all()
        raise
    return ground, children


def _attach(obj, children, collections):
    for child in children:
        for collection in collections:
            collection.objects.link(child)
        child.parent = obj


def _remove_unused(pool, item):
    if item is not None and item.users == 0:
        pool.remove(item)


def _remove_mesh(mesh):
    """Removes a mesh no one else uses, with its materials' images and the materials."""
    if mesh is None or mesh.users > 0:
        return
    used = [m for m in mesh.materials if m is not None]
    bpy.data.meshes.remove(mesh)
    for material in used:
        images = [n.image for n in material.node_tree.nodes if n.type == "TEX_IMAGE"] if material.node_tree else []
        _remove_unused(bpy.data.materials, material)
        for image in images:
            _remove_unused(bpy.data.images, image)


def _remove_plants(obj):
    groups = list({m.node_group for m in obj.modifiers if m.type == "NODES" and m.node_group})
    collections = [n.inputs["Collection"].default_value for g in groups if g for n in g.nodes
                   if n.type == "COLLECTION_INFO"]
    bpy.data.objects.remove(obj)
    for group in groups:
        _remove_unused(bpy.data.node_groups, group)
    for collection in collections:
        if collection is None or collection.users > 0:
            continue
        kinds = list(collection.objects)
        bpy.data.collections.remove(collection)
        for kind in kinds:
            if kind.users == 0:
                mesh = kind.data
                bpy.data.objects.remove(kind)
                _remove_mesh(mesh)


def _remove_parts(obj):
    for child in [c for c in obj.children if PART_PROPERTY in c]:
        mesh = child.data
        if child[PART_PROPERTY] == "plants":
            _remove_plants(child)
        else:
            bpy.data.objects.remove(child)
        _remove_mesh(mesh)


def create(collection, name, data, location=(0.0, 0.0, 0.0)):
    """A new terrain object (and its parts) linked into `collection`."""
    ground, children = _make_parts(name, data)
    obj = bpy.data.objects.new(name, ground)
    obj.location = location
    obj[RECIPE_PROPERTY] = json.dumps(data.recipe)
    collection.objects.link(obj)
    _attach(obj, children, [collection])
    return obj


def rebuild(obj, data):
    """The same object, with a new mesh and new parts from `data`."""
    ground, children = _make_parts(obj.name, data)
    old, mesh_name = obj.data, obj.data.name
    obj.data = ground
    _remove_mesh(old)
    _remove_parts(obj)
    _attach(obj, children, list(obj.users_collection))
    obj[RECIPE_PROPERTY] = json.dumps(data.recipe)
    # The old datablocks are gone: the new ones take their names (not "... .001").
    ground.name = mesh_name
    for child in children:
        child.name = f"{obj.name} {child[PART_PROPERTY]}"
