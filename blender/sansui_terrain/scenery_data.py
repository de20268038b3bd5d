"""The library's side of a terrain: every sansui call the add-on makes, before any Blender data
is touched. If one fails (a bad value), nothing in the scene has changed yet."""
from dataclasses import dataclass, field

import numpy as np


@dataclass
class SceneryData:
    """What one terrain object is built from (sansui.scenery's dict, with the plants' meshes)."""
    recipe: dict
    heights: np.ndarray        # float32 (rows, cols), metres, row 0 north
    cell: float                # metres between samples
    colour: np.ndarray         # uint8 (rows, cols, 3), sRGB ground colour
    splat: np.ndarray          # uint8 (rows, cols, 4): sand, grass, rock, snow
    water: np.ndarray          # float32 (rows, cols), water depth in metres
    plants: np.ndarray         # structured: x, y, z, species, variant, scale, rotation
    kinds: list = field(default_factory=list)      # [(species name, variant)], one per mesh
    kind_of_plant: np.ndarray = None               # int32 index into kinds, one per plant
    trees: list = field(default_factory=list)      # sansui.tree() dicts, one per kind


def plant_kinds(plants, species):
    """The distinct (species, variant) pairs in sorted order, and each plant's
    index among them."""
    if len(plants) == 0:
        return [], np.zeros(0, np.int32)
    keys = plants["species"].astype(np.int64) * 65536 + plants["variant"].astype(np.int64)
    unique, inverse = np.unique(keys, return_inverse=True)
    kinds = [(species[int(k) // 65536], int(k) % 65536) for k in unique]
    return kinds, inverse.astype(np.int32)


def compute(sansui, recipe, ground_plants=False, progress=None):
    """Runs the recipe through the library: the scenery, then one plant mesh per plant kind
    (in the scene's season, with its snow). Without `ground_plants`, only the trees (layer 0).
    Raises ValueError (a bad value) or TypeError as the module does."""
    scenery = sansui.scenery(sansui.Recipe(recipe), progress=progress)
    plants = scenery["plants"]
    if not ground_plants:
        plants = plants[plants["layer"] == 0]
    kinds, kind_of_plant = plant_kinds(plants, scenery["species"])
    trees = [sansui.tree(species, variant=variant, season=scenery["season"], snow=scenery["plant_snow"])
             for species, variant in kinds]
    return SceneryData(recipe=recipe, heights=scenery["heights"], cell=float(scenery["cell"]),
                       colour=scenery["colour"], splat=scenery["splat"], water=scenery["water"],
                       plants=plants, kinds=kinds, kind_of_plant=kind_of_plant, trees=trees)
