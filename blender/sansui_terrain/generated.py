"""The classes made from the parameter tables when the module is found: one property group per
recipe section, a root group (Scene.sansui for the next terrain, Object.sansui for each
terrain's own values) and one Advanced sub-panel per section."""
import bpy

from . import recipe_shape, tables

CATEGORY = "Sansui"
ADVANCED_PANEL = "SANSUI_PT_advanced"


class _State:
    def __init__(self):
        self.classes = []   # registered, in order
        self.sections = {}  # section name -> its rows (kinds this add-on knows)
        self.titles = {}    # section name -> the table's title


state = _State()


def registered():
    return bool(state.classes)


def target_group(context):
    """The values the panel edits: the active terrain's own, else those of the next terrain."""
    from .terrain_object import is_terrain
    obj = context.active_object
    return obj.sansui if is_terrain(obj) else context.scene.sansui


def draw_row(layout, group, row, label=None):
    """One row's widget; an unset-able row gets its 'set' tick box in front."""
    ident = tables.prop_ident(row["key"])
    text = label if label is not None else row["key"]
    if not tables.needs_set_flag(row):
        layout.prop(group, ident, text=text)
        return
    line = layout.row(heading=text)  # the label, then [x] value, as Blender's own panels do
    line.prop(group, tables.set_ident(row["key"]), text="")
    value = line.row()
    value.active = getattr(group, tables.set_ident(row["key"]))
    value.prop(group, ident, text="")


def _row(section, key):
    return next((r for r in state.sections.get(section, []) if r["key"] == key), None)


def _label(section, key):
    return recipe_shape.MAIN_LABELS.get((section, key), key.replace("_", " ").capitalize())


def draw_main(layout, root):
    """The main keys, with their labels; the shaping kind before the shaping node's keys."""
    for section, key in recipe_shape.MAIN_KEYS:
        if section == recipe_shape.SHAPING:
            layout.prop(root, "shaping")
            if root.shaping == recipe_shape.NO_SHAPING:
                continue
            section = recipe_shape.node_section(root.shaping)
        row = _row(section, key)
        if row is not None:
            draw_row(layout, getattr(root, tables.section_ident(section)), row, _label(section, key))
    layout.prop(root, "ground_plants")


def _shown(section, root):
    """A shaping node's section is shown only while that kind is chosen."""
    kind = section[len("node."):] if section.startswith("node.") else None
    return kind not in recipe_shape.SHAPING_KINDS or kind == root.shaping


def _section_panel(section, rows):
    def draw(self, context):
        group = getattr(target_group(context), tables.section_ident(section))
        self.layout.use_property_split = True
        self.layout.use_property_decorate = False
        for row in rows:
            if not recipe_shape.is_main(section, row["key"]):
                draw_row(self.layout, group, row)

    def poll(cls, context):
        return _shown(section, target_group(context))

    label = f"Node: {section[len('node.'):]}" if section.startswith("node.") else f"[{section}]"
    return type(f"SANSUI_PT_section_{tables.section_ident(section)}", (bpy.types.Panel,), {
        "bl_label": label, "bl_space_type": "VIEW_3D", "bl_region_type": "UI",
        "bl_category": CATEGORY, "bl_parent_id": ADVANCED_PANEL, "bl_options": {"DEFAULT_CLOSED"},
        "draw": draw, "poll": classmethod(poll)})


def _root_annotations(parameter_tables, groups):
    kinds = [k for k in recipe_shape.SHAPING_KINDS if recipe_shape.node_section(k) in parameter_tables]
    items = [(k, k.capitalize(), parameter_tables[recipe_shape.node_section(k)].get("title", k)) for k in kinds]
    items.append((recipe_shape.NO_SHAPING, "None", "The midpoint terrain as it is"))
    annotations = {tables.section_ident(s): bpy.props.PointerProperty(type=g) for s, g in zip(state.sections, groups)}
    annotations["shaping"] = bpy.props.EnumProperty(
        name="Erosion", items=items, default=items[0][0],
        description="What shapes the midpoint terrain: its node kind (its keys are under Advanced)")
    annotations["ground_plants"] = bpy.props.BoolProperty(
        name="Ground plants", default=False,
        description="Also place the ground layer (grass, small plants) as instances: hundreds of thousands "
                    "on a 257² world, millions on larger ones (trees are always placed)")
    return annotations


def _group_class(section, rows):
    return type(f"SANSUI_PG_{tables.section_ident(section)}", (bpy.types.PropertyGroup,),
                {"__annotations__": tables.annotations_of(rows)})


def register(parameter_tables):
    """Makes and registers the classes for these tables (once)."""
    if registered():
        return
    for name in recipe_shape.panel_sections(parameter_tables):
        table = parameter_tables[name]
        state.sections[name] = [r for r in table["rows"] if r["kind"] in tables.KNOWN_KINDS]
        state.titles[name] = table.get("title", name)
    groups = [_group_class(s, rows) for s, rows in state.sections.items()]
    root = type("SANSUI_PG_recipe", (bpy.types.PropertyGroup,),
                {"__annotations__": _root_annotations(parameter_tables, groups)})
    panels = [_section_panel(s, rows) for s, rows in state.sections.items()
              if any(not recipe_shape.is_main(s, r["key"]) for r in rows)]
    for cls in groups + [root] + panels:
        bpy.utils.register_class(cls)
        state.classes.append(cls)
    bpy.types.Scene.sansui = bpy.props.PointerProperty(type=root)
    bpy.types.Object.sansui = bpy.props.PointerProperty(type=root)


def unregister():
    if not registered():
        return
    del bpy.types.Object.sansui
    del bpy.types.Scene.sansui
    for cls in reversed(state.classes):
        bpy.utils.unregister_class(cls)
    state.__init__()
