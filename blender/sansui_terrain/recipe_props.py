"""The panel's values <-> a recipe dict (shaped like a scene file, what sansui.Recipe reads).

The recipe is a graph: node "terrain" (midpoint), then node "shaped" (the chosen shaping kind:
erode or stage) unless shaping is none, on the [world], with the look's sections. A key left at
its table default is left out of the recipe, so the library's defaults (and the ones it derives)
stay in force; the main keys are always written, so a stored recipe says which terrain it is."""
import numpy as np

from . import recipe_shape, tables

RECIPE_VERSION = 4
TERRAIN_ID = "terrain"
SHAPED_ID = "shaped"


def _decimal(value):
    """A float32 panel value as the shortest decimal that reads back as it (0.8, not
    0.800000011920929): the recipe then says what the user typed."""
    return float(repr(np.float32(value)))


def _same(value, default):
    if isinstance(default, float) or isinstance(value, float):
        return abs(float(value) - float(default)) <= 1e-6 * max(1.0, abs(float(default)))
    return value == default


def _value_of(group, row):
    """The row's value in the group, or None when it is unset."""
    key, kind = row["key"], row["kind"]
    value = getattr(group, tables.prop_ident(key))
    if tables.needs_set_flag(row) and not getattr(group, tables.set_ident(key)):
        return None
    if kind == "choice" and value == tables.UNSET_ITEM:
        return None
    if kind in ("text", "path") and value == "" and tables.unsettable(row):
        return None
    if kind == "real":
        return _decimal(value)
    if kind == "reals":
        if isinstance(value, str):
            return [float(v) for v in value.replace(",", " ").split()] or None
        return [_decimal(v) for v in value]
    return value


def _section_to_dict(group, rows, section):
    values = {}
    for row in rows:
        value = _value_of(group, row)
        keep = recipe_shape.is_main(section, row["key"]) or row.get("default") is None
        if value is None or (not keep and _same(value, row["default"])):
            continue
        values[row["key"]] = value
    return values


def _group(root, section):
    return getattr(root, tables.section_ident(section))


def to_recipe(root, sections):
    """The recipe dict of the panel's values. `sections` maps section name -> rows."""
    recipe = {"sansui_recipe": RECIPE_VERSION}
    nodes = []
    for section, rows in sections.items():
        values = _section_to_dict(_group(root, section), rows, section)
        if section == recipe_shape.node_section(recipe_shape.TERRAIN_KIND):
            nodes.insert(0, {"id": TERRAIN_ID, "kind": recipe_shape.TERRAIN_KIND, **values})
        elif section == recipe_shape.node_section(root.shaping):
            nodes.append({"id": SHAPED_ID, "kind": root.shaping, "inputs": [TERRAIN_ID], **values})
        elif values and not section.startswith("node."):
            recipe[section] = values
    recipe["node"] = nodes
    return recipe


def _set_row(group, row, value):
    key, kind = row["key"], row["kind"]
    if tables.needs_set_flag(row):
        setattr(group, tables.set_ident(key), value is not None)
    if value is None:
        value = row.get("default")
    if value is None:  # unset with no fixed default: back to the property's own default
        group.property_unset(tables.prop_ident(key))
        return
    if kind == "reals" and isinstance(getattr(group, tables.prop_ident(key)), str):
        value = ", ".join(str(v) for v in value)
    setattr(group, tables.prop_ident(key), value)


def _node_values(recipe):
    """{section: values} of the recipe's terrain and shaping nodes, and the shaping kind."""
    values, shaping = {}, recipe_shape.NO_SHAPING
    for node in recipe.get("node", []):
        kind = node.get("kind")
        if kind == recipe_shape.TERRAIN_KIND or kind in recipe_shape.SHAPING_KINDS:
            values[recipe_shape.node_section(kind)] = {k: v for k, v in node.items() if k not in ("id", "kind", "inputs")}
            shaping = kind if kind in recipe_shape.SHAPING_KINDS else shaping
    return values, shaping


def from_recipe(root, sections, recipe):
    """Sets the panel's values from a recipe dict made by to_recipe(); keys it lacks go back to
    their defaults."""
    nodes, root.shaping = _node_values(recipe)
    for section, rows in sections.items():
        values = nodes.get(section) if section.startswith("node.") else recipe.get(section)
        group = _group(root, section)
        for row in rows:
            _set_row(group, row, (values or {}).get(row["key"]))
