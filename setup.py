"""Builds the extension sansui._sansui with CMake for `pip install .` (pyproject.toml).

setuptools runs this: build_py copies python/sansui/*.py, and the build_ext below configures
CMake in build-python/ (or $SANSUI_BUILD_DIR), builds the target sansui_python there (the
library, static, and the module: nothing is downloaded) and copies the extension and its type
stubs into the wheel. The CMake folder is kept, so a second install builds only what changed;
compilations go through ccache when it is installed, as scripts/build's do.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(sansui VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, extension):
        build = pathlib.Path(os.environ.get("SANSUI_BUILD_DIR", ROOT / "build-python")).resolve()
        env = dict(os.environ)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DSANSUI_BUILD_TESTS=OFF",
                     "-DSANSUI_BUILD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
            env.update(CCACHE_BASEDIR=str(ROOT), CCACHE_NOHASHDIR="1")
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(configure, check=True, env=env)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "sansui_python", "-j", jobs], check=True, env=env)
        built = build / "python" / "sansui"
        module = next(built.glob("_sansui*.so"), None)
        if module is None:
            raise RuntimeError(f"CMake built no {built}/_sansui*.so: is the Python module left out (pybind11-dev, python3-dev, "
                               "python3-numpy; see CMake's output)?")
        target = pathlib.Path(self.get_ext_fullpath(extension.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        for name in ("__init__.pyi", "py.typed"):
            shutil.copyfile(built / name, target.parent / name)


setup(
    version=version(),
    ext_modules=[Extension("sansui._sansui", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(pathlib.Path("build-python") / "setuptools")}},
)
