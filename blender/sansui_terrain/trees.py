"""Plants as instances: one mesh per (species, variant), each plant an instance of it.

A collection holds one object per (species, variant); a point cloud (one vertex per plant, with
its kind, scale and turn as attributes) instances them with geometry nodes (Collection Info,
separate children -> Instance on Points, picking the child by the plant's kind). Nothing is
copied: a million plants share a few dozen meshes."""
import bpy
import numpy as np

from . import mesh_build

KIND = "sansui_kind"          # point attribute: index of the plant's (species, variant)
SCALE = "sansui_scale"        # point attribute: the plant's size factor
ROTATION = "sansui_rotation"  # point attribute: its turn about z, radians
COLOUR = "sansui_colour"      # a plant mesh's colour attribute


def kind_name(index, species, variant):
    """A plant object's name. The zero-padded index comes first because Collection Info sorts
    its children by name, and the instance index picks them in that order."""
    return f"{index:04d} {species} v{variant}"


def linear_from_srgb(srgb):
    """sRGB 0..1 to linear (the IEC 61966-2-1 curve): float colour attributes hold linear light."""
    srgb = np.asarray(srgb, np.float32)
    return np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4).astype(np.float32)


def mean_colour(plant_meshes):
    """The plants' mean colour, linear (for the Solid viewport)."""
    colours = [np.asarray(t["colours"], np.float32) for t in plant_meshes if "colours" in t]
    if not colours:
        return (0.1, 0.2, 0.05)
    return tuple(float(c) for c in linear_from_srgb(np.concatenate(colours).mean(axis=0)))


def plant_mesh(name, tree, material):
    """A Blender mesh of one sansui.tree() result (sRGB colours per vertex, as a colour
    attribute)."""
    mesh = mesh_build.triangle_mesh(name, tree["vertices"], tree["faces"])
    if "colours" in tree:
        rgba = np.ones((len(tree["vertices"]), 4), np.float32)
        rgba[:, :3] = linear_from_srgb(tree["colours"])
        layer = mesh.color_attributes.new(COLOUR, "FLOAT_COLOR", "POINT")
        layer.data.foreach_set("color", rgba.ravel())
    mesh.materials.append(material)
    return mesh


def plant_collection(name, kinds, meshes):
    """A collection (not linked to the scene) of one object per kind, in kind order."""
    collection = bpy.data.collections.new(name)
    for index, ((species, variant), mesh) in enumerate(zip(kinds, meshes)):
        collection.objects.link(bpy.data.objects.new(kind_name(index, species, variant), mesh))
    return collection


def _link(tree, output, node, socket):
    tree.links.new(output, node.inputs[socket])


def _named(nodes, name, data_type, location):
    node = nodes.new("GeometryNodeInputNamedAttribute")
    node.data_type = data_type
    node.inputs["Name"].default_value = name
    node.location = location
    return node


SHARE = "Share"  # the node group's input: the fraction of the plants it instances


def instancing_nodes(name, collection):
    """Geometry nodes: the points -> one instance of collection child `KIND` at each of a
    random `SHARE` of them (the same ones for the same share: the points' indices seed it)."""
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    share = tree.inputs.new("NodeSocketFloatFactor", SHARE)
    share.min_value, share.max_value, share.default_value = 0.0, 1.0, 1.0
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    nodes = tree.nodes
    points_in = nodes.new("NodeGroupInput")
    points_in.location = (-600, 0)
    info = nodes.new("GeometryNodeCollectionInfo")
    info.inputs["Collection"].default_value = collection
    info.inputs["Separate Children"].default_value = True
    info.inputs["Reset Children"].default_value = True
    info.location = (-400, -150)
    turn = nodes.new("ShaderNodeCombineXYZ")
    turn.location = (-400, -450)
    _link(tree, _named(nodes, ROTATION, "FLOAT", (-600, -450)).outputs["Attribute"], turn, "Z")
    instance = nodes.new("GeometryNodeInstanceOnPoints")
    instance.inputs["Pick Instance"].default_value = True
    _link(tree, points_in.outputs["Geometry"], instance, "Points")
    chosen = nodes.new("FunctionNodeRandomValue")
    chosen.data_type = "BOOLEAN"
    chosen.location = (-400, 150)
    _link(tree, points_in.outputs[SHARE], chosen, "Probability")
    _link(tree, next(o for o in chosen.outputs if o.type == "BOOLEAN"), instance, "Selection")
    _link(tree, info.outputs["Geometry"], instance, "Instance")
    _link(tree, _named(nodes, KIND, "INT", (-400, -300)).outputs["Attribute"], instance, "Instance Index")
    _link(tree, turn.outputs["Vector"], instance, "Rotation")
    _link(tree, _named(nodes, SCALE, "FLOAT", (-400, -600)).outputs["Attribute"], instance, "Scale")
    result = nodes.new("NodeGroupOutput")
    result.location = (200, 0)
    _link(tree, instance.outputs["Instances"], result, "Geometry")
    return tree


def add_instancing(obj, nodes, viewport_share):
    """Two modifiers over the same nodes: all plants in renders, `viewport_share` of them in the
    viewport (a million trees of thousands of triangles each is more than a viewport draws;
    Blender 3.4 has no node that tells the viewport from a render, so each modifier is switched
    off in the other)."""
    for label, share, viewport in (("viewport", viewport_share, True), ("render", 1.0, False)):
        modifier = obj.modifiers.new(f"Sansui plants ({label})", "NODES")
        modifier.node_group = nodes
        modifier[nodes.inputs[SHARE].identifier] = share
        modifier.show_viewport, modifier.show_render = viewport, not viewport


def plant_points(name, plants, kind_of_plant, offsets):
    """The point cloud of the plants in the terrain object's coordinates. `offsets` (east,
    north): the world's half extents (plants' x runs east from the west edge, y north from the
    north edge, so negative)."""
    east, north = offsets
    points = np.stack([plants["x"] - east, plants["y"] + north, plants["z"]], axis=1)
    return mesh_build.point_mesh(name, points, {KIND: ("INT", kind_of_plant),
                                                SCALE: ("FLOAT", plants["scale"]),
                                                ROTATION: ("FLOAT", plants["rotation"])})
