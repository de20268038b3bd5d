"""Shared fixtures of the Python module's tests (run by CTest with PYTHONPATH=build/python and
SANSUI_CLI=build/sansui; by hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python)."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Subprocesses the tests start elsewhere import the same module: its path, absolute.
os.environ["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)


@pytest.fixture(scope="session")
def cli():
    """Runs the sansui CLI; returns its CompletedProcess (text), failing the test on a non-zero exit."""
    path = os.environ.get("SANSUI_CLI", str(ROOT / "build" / "sansui"))

    # The sanitizer build preloads its runtime for the interpreter; the CLI links its own.
    env = {key: value for key, value in os.environ.items() if key != "LD_PRELOAD"}

    def run(*args, cwd=None, check=True):
        done = subprocess.run([path, *map(str, args)], cwd=cwd, capture_output=True, text=True, env=env)
        if check and done.returncode != 0:
            raise AssertionError(f"sansui {' '.join(map(str, args))} failed: {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def examples():
    return ROOT / "examples"


def read_r32(path, side):
    """A .r32 heightmap as float32 (side, side): raw little-endian, row 0 north."""
    data = np.fromfile(path, dtype="<f4")
    assert data.size == side * side, f"{path}: {data.size} samples, not {side}x{side}"
    return data.reshape(side, side)


def rss_bytes():
    """This process's resident memory now."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
