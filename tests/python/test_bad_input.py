"""Bad input raises ValueError or TypeError with one line, and the interpreter survives it, also
10,000 times over (no leak: the process's memory stays flat)."""
import gc

import numpy as np
import pytest

import sansui
from conftest import rss_bytes

GOOD = np.zeros((33, 33), np.float32)
NAN = GOOD.copy()
NAN[4, 7] = np.nan

def deeply_nested(depth):
    """{"a": {"a": ... }} `depth` deep: built in a loop (a recursive build would hit Python's own limit)."""
    inner = {"size": 65}
    for _ in range(depth):
        inner = {"a": inner}
    return {"world": inner}


def nested_list(depth):
    """[[...[1]...]] `depth` deep: its repr fails with RecursionError."""
    inner = [1]
    for _ in range(depth):
        inner = [inner]
    return inner


def containing_itself(kind):
    if kind == "dict":
        world = {"size": 65}
        world["world"] = world
        return {"world": world}
    items = [1.0]
    items.append(items)
    return {"world": {"size": 65}, "shape": [{"step": "erode", "points": items}]}


BAD_CALLS = [
    (TypeError, "dtype is complex128", lambda: sansui.smooth(np.zeros((33, 33), np.complex128))),
    (TypeError, "dtype is object", lambda: sansui.smooth(np.array([[object()] * 3] * 3))),
    (TypeError, "dtype is <U1", lambda: sansui.smooth(np.array([["a"] * 3] * 3))),
    (ValueError, "must be a 2-D array", lambda: sansui.smooth(np.zeros((3, 33, 33), np.float32))),
    (ValueError, "must be a 2-D array", lambda: sansui.smooth(np.zeros(33, np.float32))),
    (ValueError, "the input arrays differ in size", lambda: sansui.blend(np.zeros((33, 17)), np.zeros((17, 33)), GOOD)),
    (ValueError, "is empty", lambda: sansui.smooth(np.zeros((0, 0), np.float32))),
    (ValueError, "holds NaN at row 4, column 7", lambda: sansui.smooth(NAN)),
    (ValueError, "holds an infinity", lambda: sansui.smooth(np.full((5, 5), np.inf, np.float32))),
    (ValueError, "size -5 is not allowed", lambda: sansui.midpoint(size=-5)),
    (ValueError, "hurst 2 is not allowed: it must be > 0 and <= 1", lambda: sansui.midpoint(hurst=2)),
    (ValueError, "stage 'ancient' is not allowed: it must be one of", lambda: sansui.erode(GOOD, stage="ancient")),
    (TypeError, "hurst must be a number; got str", lambda: sansui.midpoint(hurst="0.5")),
    (TypeError, "unexpected keyword argument 'hurts'; did you mean 'hurst'", lambda: sansui.midpoint(hurts=0.5)),
    (TypeError, "needs its input array 'heights'", lambda: sansui.erode()),
    (TypeError, "takes 2 input arrays, 3 given", lambda: sansui.erode(GOOD, GOOD, GOOD)),
    (ValueError, "the input arrays differ in size", lambda: sansui.blend(GOOD, np.zeros((65, 65), np.float32), GOOD)),
    (ValueError, "size=65 but the input arrays are 33x33", lambda: sansui.smooth(GOOD, size=65)),
    (ValueError, "recipe: .*sizee", lambda: sansui.Recipe({"world": {"sizee": 3}})),
    (ValueError, "recipe: .*colour", lambda: sansui.Recipe({"colour": {"x": 1}})),
    (TypeError, "recipe: world.size is a object", lambda: sansui.Recipe({"world": {"size": object()}})),
    (ValueError, "kind 'hills' is not allowed", lambda: sansui.Recipe().node("a", "hills")),
    (ValueError, "seed -1 is not allowed", lambda: sansui.Recipe().node("a", "midpoint", seed=-1)),
    (ValueError, "no such file|does not exist|cannot", lambda: sansui.Recipe("/no/such/scene.toml")),
    (ValueError, "a midpoint node needs a world of 2\\^k\\+1", lambda: sansui.midpoint(size=1009)),
    (ValueError, "nested more than 64 deep", lambda: sansui.Recipe(deeply_nested(30000))),
    (ValueError, "contains itself", lambda: sansui.Recipe(containing_itself("dict"))),
    (ValueError, "contains itself", lambda: sansui.Recipe(containing_itself("list"))),
    (ValueError, "set_arrays\\('pandas'\\) is not allowed", lambda: sansui.set_arrays("pandas")),
    (ValueError, "crs EPSG:4326 .* is not allowed: it is in degrees", lambda: sansui.grid(GOOD, cell=10, crs="EPSG:4326")),
    (ValueError, "crs 'EPSG:999999' is not a coordinate reference system PROJ knows", lambda: sansui.midpoint(size=33, crs="EPSG:999999")),
    (ValueError, "cell -3 is not allowed", lambda: sansui.erode(GOOD, cell=-3)),
    (TypeError, "world must be a sansui.World; got dict", lambda: sansui.smooth(GOOD, world={"cell": 3})),
    (ValueError, "method 'd16' is not allowed: it must be one of d8, mfd", lambda: sansui.drainage_area(GOOD, cell=10, method="d16")),
    (TypeError, "unexpected keyword argument 'chanel_area'; did you mean 'channel_area'", lambda: sansui.rivers(GOOD, chanel_area=1)),
    (TypeError, "unexpected keyword argument 'sea_levle'; did you mean 'sea_level'", lambda: sansui.smooth(GOOD, sea_levle=1)),
    (ValueError, "a file node needs path", lambda: sansui.file()),
    (ValueError, "size=65 but the input arrays are 17x33", lambda: sansui.erode(np.zeros((33, 17)), size=65)),
    (TypeError, "size must be a number; got list", lambda: sansui.erode(GOOD, size=nested_list(3000))),
    (TypeError, "hurst must be a number; got dict", lambda: sansui.midpoint(size=33, hurst={"a": "\ufffd" * 30})),
    (ValueError, "cannot read .*@ / ", lambda: sansui.Recipe("@\n")),
]


@pytest.mark.parametrize("error, message, call", BAD_CALLS, ids=[m for _, m, _ in BAD_CALLS])
def test_bad_input_raises_one_line(error, message, call):
    with pytest.raises(error, match=message) as raised:
        call()
    text = str(raised.value)
    assert "\n" not in text and text and "internal error" not in text


def test_ten_thousand_bad_calls_leave_memory_flat():
    def round_of_bad_calls():
        for error, _, call in BAD_CALLS[:18]:  # the calls that do not read files
            try:
                call()
            except error:
                pass

    for _ in range(40):  # warm up caches and the allocator
        round_of_bad_calls()
    gc.collect()
    before = rss_bytes()
    for _ in range(10_000 // 18 + 1):
        round_of_bad_calls()
    gc.collect()
    grown = rss_bytes() - before
    assert grown < 2 << 20, f"10,000 bad calls grew memory by {grown / 1024:.0f} kB"


def test_a_progress_callable_that_calls_sansui_again_gets_an_error_not_a_deadlock():
    """The callable runs inside the first call: a second call from there is refused with a clear
    error (the first call then raises it), never a wait that does not end."""
    import subprocess
    import sys
    program = (
        "import numpy as np, sansui\n"
        "h = sansui.midpoint(size=129)\n"
        "def again(stage, fraction):\n"
        "    sansui.erode(h)\n"
        "try:\n"
        "    sansui.erode(h, progress=again)\n"
        "except RuntimeError as e:\n"
        "    print('refused:', e)\n")
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "refused:" in done.stdout and "progress callable" in done.stdout
