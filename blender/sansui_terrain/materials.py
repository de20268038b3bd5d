"""Images from the library's maps and the materials that use them."""
import bpy
import numpy as np


def image_from_pixels(name, pixels, colour_space):
    """A packed image (saved inside the .blend) from uint8 (rows, cols, 3 or 4) pixels, row 0
    north. Blender stores images bottom row first and reads byte images' pixels as value / 255
    in their colour space, so sRGB bytes go in as they are."""
    rows, cols, channels = pixels.shape
    rgba = np.ones((rows, cols, 4), np.float32)
    rgba[..., :channels] = pixels[::-1] / np.float32(255)
    image = bpy.data.images.new(name, cols, rows, alpha=channels == 4)
    image.colorspace_settings.name = colour_space
    image.pixels.foreach_set(rgba.ravel())
    image.pack()
    return image


def _image_node(nodes, image, location, label):
    node = nodes.new("ShaderNodeTexImage")
    node.image = image
    node.extension = "EXTEND"
    node.interpolation = "Linear"
    node.location = location
    node.label = label
    return node


def _principled(material):
    material.use_nodes = True
    return material.node_tree.nodes["Principled BSDF"]


def terrain_material(name, colour, splat):
    """The ground: base colour from the colour image. The splat image (sand, grass, rock, snow
    weights in R, G, B, A) is in the node tree, unconnected, for users' own texture mixes."""
    material = bpy.data.materials.new(name)
    shader = _principled(material)
    shader.inputs["Roughness"].default_value = 0.9
    shader.inputs["Specular"].default_value = 0.2
    nodes = material.node_tree.nodes
    colour_node = _image_node(nodes, colour, (-400, 300), "Ground colour")
    _image_node(nodes, splat, (-400, -50), "Splat: sand, grass, rock, snow (R, G, B, A)")
    material.node_tree.links.new(colour_node.outputs["Color"], shader.inputs["Base Color"])
    return material


def water_material(name):
    """Water: dark, smooth and glossy (the sky and the shore colour it)."""
    material = bpy.data.materials.new(name)
    shader = _principled(material)
    shader.inputs["Base Color"].default_value = (0.01, 0.04, 0.06, 1.0)
    shader.inputs["Roughness"].default_value = 0.05
    shader.inputs["Specular"].default_value = 0.6
    material.diffuse_color = (0.02, 0.1, 0.15, 1.0)
    return material


def plant_material(name, attribute, viewport_colour):
    """Plants: base colour from the mesh's colour attribute `attribute`; the Solid viewport,
    which does not read it, shows `viewport_colour` (linear RGB)."""
    material = bpy.data.materials.new(name)
    material.diffuse_color = (*viewport_colour, 1.0)
    shader = _principled(material)
    shader.inputs["Roughness"].default_value = 0.8
    shader.inputs["Specular"].default_value = 0.2
    colour = material.node_tree.nodes.new("ShaderNodeVertexColor")
    colour.layer_name = attribute
    colour.location = (-300, 300)
    material.node_tree.links.new(colour.outputs["Color"], shader.inputs["Base Color"])
    return material
