"""Sansui: deterministic natural terrain, water, plants and scenes, from Python.

    import sansui
    h = sansui.midpoint(size=1025, hurst=0.8, seed=7)   # numpy float32 (1025, 1025), metres
    e = sansui.erode(h, stage="mature")
    sansui.run("scene.toml", out_dir="out")

Every node kind of a recipe graph is a function whose keyword arguments are its parameter
table's keys (help(sansui.midpoint)); sansui.Recipe and sansui.run run whole recipes. See
docs/python.md.
"""
from ._sansui import *  # noqa: F401,F403  (the names are the library's own)
from ._sansui import __version__  # noqa: F401
