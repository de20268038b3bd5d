"""Blender properties from Sansui's parameter tables (sansui.parameter_tables()): one property
per table row, so no widget is written by hand and the panel cannot drift from the CLI.

A row is {"key", "kind", "unit", "help", "optional", "default", "min", "max", "choices",
"count", ...}. Rows that may stay unset (optional, or no fixed default) get a companion flag
"<key>__set": unset, the recipe leaves the key out and the library picks its default."""
import bpy

UNSET_ITEM = "__unset__"
INT_LIMIT = 2**31 - 1  # Blender's IntProperty is 32-bit
_RESERVED = {"name", "rna_type", "bl_rna"}  # names a PropertyGroup already has


def prop_ident(key):
    """The property's identifier for a table key."""
    return f"key_{key}" if key in _RESERVED else key


def set_ident(key):
    """The identifier of the flag saying an unset-able key is set."""
    return f"{key}__set"


def section_ident(section):
    """The identifier of a section's property group ('node.erode' -> 'node_erode')."""
    return section.replace(".", "_")


def unsettable(row):
    """Whether the row may stay unset (the library then derives its value)."""
    return bool(row.get("optional")) or row.get("default") is None


def fixed_count(row):
    """The number of values of a 'reals' row when it is fixed and small, else None."""
    count = row.get("count") or [0, 0]
    return count[0] if count[0] == count[1] and 1 <= count[0] <= 4 else None


def _description(row):
    parts = [row.get("help", "")]
    if row.get("unit"):
        parts.append(f"Unit: {row['unit']}")
    if row.get("default") is not None:
        parts.append(f"Default: {row['default']}")
    elif unsettable(row):
        parts.append(f"Unset: {row.get('default_text') or 'the library derives it'}")
    return ". ".join(p for p in parts if p)


def _clamped_int(value, fallback):
    if value is None:
        return fallback
    return max(-INT_LIMIT, min(INT_LIMIT, int(value)))


def _number_limits(row, clamp):
    limits = {}
    if row.get("min") is not None:
        limits["min"] = clamp(row["min"])
    if row.get("max") is not None:
        limits["max"] = clamp(row["max"])
    return limits


def _integer(row, common):
    default = row.get("default")
    limits = _number_limits(row, lambda v: _clamped_int(v, 0))
    start = default if default is not None else limits.get("min", 0)
    return bpy.props.IntProperty(default=_clamped_int(start, 0), **limits, **common)


def _real(row, common):
    default = row.get("default")
    limits = _number_limits(row, float)
    start = float(default) if default is not None else limits.get("min", 0.0)
    # Small defaults (erodibility 2e-05) need the panel's most digits to show at all.
    small = default not in (None, 0) and abs(default) < 0.01
    return bpy.props.FloatProperty(default=start, precision=6 if small else 3, **limits, **common)


def _choice(row, common):
    items = [(c, c, "") for c in row.get("choices", [])]
    default = row.get("default")
    if unsettable(row):
        derived = row.get("default_text") or "the library derives it"
        items.insert(0, (UNSET_ITEM, "(unset)", f"Unset: {derived}"))
        default = default if default is not None else UNSET_ITEM
    return bpy.props.EnumProperty(items=items, default=str(default), **common)


def _reals(row, common):
    size = fixed_count(row)
    default = row.get("default")
    if size is None:
        text = ", ".join(str(v) for v in default) if default else ""
        return bpy.props.StringProperty(default=text, **common)
    values = tuple(float(v) for v in default) if default else (0.0,) * size
    return bpy.props.FloatVectorProperty(size=size, default=values, **common)


def _text(row, common):
    subtype = "FILE_PATH" if row["kind"] == "path" else "NONE"
    return bpy.props.StringProperty(default=str(row.get("default") or ""), subtype=subtype, **common)


_MAKERS = {"flag": lambda row, common: bpy.props.BoolProperty(default=bool(row.get("default")), **common),
           "integer": _integer, "real": _real, "choice": _choice, "reals": _reals, "text": _text,
           "path": _text}


def needs_set_flag(row):
    """Whether the row gets an '__set' flag: unset-able numbers and fixed-size vectors (choices
    have an unset item; text is unset when empty)."""
    if not unsettable(row):
        return False
    return row["kind"] in ("flag", "integer", "real") or (row["kind"] == "reals" and fixed_count(row))


def annotations_of(rows):
    """The property annotations of a section's rows (skipping kinds this add-on does not know)."""
    annotations = {}
    for row in rows:
        make = _MAKERS.get(row["kind"])
        if make is None:
            continue
        common = {"name": row["key"], "description": _description(row)}
        annotations[prop_ident(row["key"])] = make(row, common)
        if needs_set_flag(row):
            annotations[set_ident(row["key"])] = bpy.props.BoolProperty(
                name=f"Set {row['key']}", description=f"Set {row['key']} (unset: the library derives it)")
    return annotations

KNOWN_KINDS = tuple(_MAKERS)
