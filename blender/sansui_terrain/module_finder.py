"""Finds Sansui's Python module: in the folder set in the add-on's preferences, else installed
(import sansui). Without it the add-on still registers and says, in one sentence, what to do.
The first module found stays for the session: Python cannot unload an extension module."""
import importlib
import os
import sys

MISSING = ("Sansui's Python module was not found: install Sansui (cmake --install, or the .deb), "
           "or set the folder that holds the sansui package in Edit > Preferences > Add-ons > "
           "Sansui terrain > Module folder")

_state = {"module": None, "problem": MISSING}


def _import_from(folder):
    """Imports sansui with `folder` first on sys.path (it stays there: the module's own
    imports need it later too)."""
    folder = os.path.abspath(os.path.expanduser(folder))
    if not os.path.isdir(os.path.join(folder, "sansui")):
        raise ImportError(f"{folder} holds no sansui package")
    if folder not in sys.path:
        sys.path.insert(0, folder)
    # A failed import earlier leaves nothing in sys.modules, so a retry imports afresh.
    return importlib.import_module("sansui")


def load(folder=""):
    """Imports the module: from `folder` when it is set and holds one, else the installed one.
    Remembers the result and returns the module or None; problem() then says why."""
    reasons = []
    for source in ([folder] if folder else []) + [None]:
        try:
            module = _import_from(source) if source else importlib.import_module("sansui")
            _state.update(module=module, problem=None)
            return module
        except ImportError as error:
            reasons.append(str(error))
    _state.update(module=None, problem=f"{MISSING} ({'; '.join(reasons)})" if folder else MISSING)
    return None


def module():
    """The module, or None when it is missing."""
    return _state["module"]


def problem():
    """Why the module is missing (one sentence), or None."""
    return _state["problem"]


def set_problem(text):
    """Records why the module cannot be used although it imported."""
    _state["problem"] = text
