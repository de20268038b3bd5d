"""`pip install .` from a clone, offline, with Debian's tools: pyproject.toml and setup.py make a
wheel of the module that a venv imports (docs/python.md). The clone is the files pip reads
(copied, so that the test writes nothing into the source tree); setup.py builds the extension's
target in this build folder (SANSUI_BUILD_DIR), where it is up to date. scripts/setup --test
installs python3-venv, python3-pip, python3-setuptools and python3-wheel."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_pip_installs_the_module_into_a_venv(tmp_path):
    build = os.environ.get("SANSUI_BUILD_DIR", str(ROOT / "build"))
    if not (pathlib.Path(build) / "CMakeCache.txt").exists():
        pytest.skip(f"no configured build in {build}")
    clone = tmp_path / "clone"
    for name in ("pyproject.toml", "setup.py", "CMakeLists.txt", "docs/python.md"):
        (clone / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(ROOT / name, clone / name)
    shutil.copytree(ROOT / "python" / "sansui", clone / "python" / "sansui")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, timeout=300)
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", SANSUI_BUILD_DIR=build)
    # pip, CMake and the compilers need no sanitizer runtime (the sanitizer build preloads it for the
    # interpreter that imports the module).
    pip_env = {key: value for key, value in env.items() if key != "LD_PRELOAD"}
    done = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "--no-deps", "--no-cache-dir", str(clone)],
                          capture_output=True, text=True, env=pip_env, timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    check = (
        "import inspect, numpy as np, sansui\n"
        "h = sansui.midpoint(size=33, cell=20.0)\n"
        "hurst = inspect.signature(sansui.midpoint).parameters['hurst']\n"
        "print(sansui.__file__, sansui.__version__, sansui.erode(h.copy()).cell, hurst.annotation.__name__, hurst.default)\n")
    done = subprocess.run([str(venv / "bin" / "python"), "-c", check], capture_output=True, text=True, env=env, cwd=tmp_path, timeout=120)
    assert done.returncode == 0, done.stderr
    location, version, cell, annotation, default = done.stdout.split()
    assert location.startswith(str(venv)) and cell == "20.0" and (annotation, default) == ("float", "0.7")
    assert (pathlib.Path(location).parent / "__init__.pyi").exists() and (pathlib.Path(location).parent / "py.typed").exists()
    assert version == subprocess.run([sys.executable, "-c", "import sansui; print(sansui.__version__)"], capture_output=True,
                                     text=True).stdout.strip()
