"""The recipe the panel edits, and which of its keys are on top: the choices the panel's layout
makes; everything else about a key comes from its table (tables.py)."""

# The panel's recipe is a graph: a midpoint terrain, then one shaping node (erode or the stage
# filter, or none), on the [world], with the sections a scene's look reads. Its sections are the
# tables of those node kinds, "world" and every look section sansui.parameter_tables() gives,
# except those that shape only the renderer's own picture or a lone tree output: Blender has its
# own camera, sky and world.
TERRAIN_KIND = "midpoint"
SHAPING_KINDS = ("erode", "stage")
NO_SHAPING = "none"
EXCLUDED_SECTIONS = ("camera", "sky", "atmosphere", "rock", "tree")


def node_section(kind):
    return f"node.{kind}"


def panel_sections(parameter_tables):
    """The section names the panel edits, in the order it shows them."""
    first = ["world", node_section(TERRAIN_KIND)] + [node_section(k) for k in SHAPING_KINDS]
    rest = [name for name in parameter_tables
            if not name.startswith("node.") and name not in first and name not in EXCLUDED_SECTIONS]
    return [name for name in first if name in parameter_tables] + rest


# The main keys, shown on top (with the shaping kind); every other row goes under Advanced.
# "node.shaping" stands for whichever shaping node kind is chosen.
SHAPING = "node.shaping"
MAIN_KEYS = (("world", "size"), ("world", "cell"), ("climate", "koppen"), ("season", "season"),
             (node_section(TERRAIN_KIND), "seed"), (node_section(TERRAIN_KIND), "hurst"),
             (SHAPING, "stage"))

# Labels of the main keys where the bare key would not say what it is.
MAIN_LABELS = {("climate", "koppen"): "Climate", (node_section(TERRAIN_KIND), "hurst"): "H (Hurst)",
               ("world", "cell"): "Cell (m)"}


def is_main(section, key):
    shaping = section.startswith("node.") and section[len("node."):] in SHAPING_KINDS
    return (SHAPING if shaping else section, key) in MAIN_KEYS
