"""Calls run without the GIL, report progress to a callable, and stop on Ctrl-C."""
import os
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import sansui


@pytest.fixture
def one_thread():
    sansui.set_threads(1)  # a core stays free for the other Python thread
    yield
    sansui.set_threads(0)


def test_another_python_thread_runs_during_a_long_call(one_thread):
    h = sansui.midpoint(size=1025, seed=1)
    stamps, stop = [], threading.Event()

    def spin():  # pure Python: it runs only while it holds the GIL
        while not stop.is_set():
            stamps.append(time.monotonic())
            time.sleep(0.001)

    thread = threading.Thread(target=spin)
    thread.start()
    start = time.monotonic()
    sansui.erode(h, erosion_steps=4)
    end = time.monotonic()
    stop.set()
    thread.join()
    assert end - start > 0.15, "the call was too short to tell"
    middle = [t for t in stamps if start + 0.05 < t < end - 0.05]
    assert len(middle) > 10, f"the other thread ran {len(middle)} times in a {end - start:.2f} s call"


def test_the_thread_count_does_not_change_the_bytes():
    h = sansui.midpoint(size=257, seed=8)
    sansui.set_threads(1)
    one = sansui.erode(h)
    sansui.set_threads(0)
    assert sansui.threads() == 0
    assert np.array_equal(one, sansui.erode(h))
    with pytest.raises(ValueError, match="threads -1 is not allowed"):
        sansui.set_threads(-1)


def test_progress_goes_to_a_callable_in_order():
    seen = []
    sansui.erode(sansui.midpoint(size=257), progress=lambda stage, fraction: seen.append((stage, fraction)))
    assert seen and all(isinstance(s, str) and 0.0 <= f <= 1.0 for s, f in seen)
    fractions = [f for s, f in seen if s == seen[0][0]]
    assert fractions == sorted(fractions)


def test_an_exception_in_the_progress_callable_cancels_the_call():
    class Stop(Exception):
        pass

    def stop(stage, fraction):
        raise Stop(stage)

    with pytest.raises(Stop):
        sansui.erode(sansui.midpoint(size=257), progress=stop)
    with pytest.raises(TypeError, match="progress must be a callable"):
        sansui.midpoint(size=33, progress=3)


INTERRUPTED = textwrap.dedent(
    """
    import os, signal, sys, threading, time
    import sansui
    h = sansui.midpoint(size=1025, seed=2)
    threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    start = time.monotonic()
    try:
        CALL
    except KeyboardInterrupt:
        print(f"interrupted after {time.monotonic() - start:.2f} s")
        sys.exit(0)
    print("finished")
    sys.exit(1)
    """
)


def run_interrupted(call, cwd):
    script = INTERRUPTED.replace("CALL", call)
    env = dict(os.environ)
    return subprocess.run([sys.executable, "-c", script], cwd=cwd, capture_output=True, text=True, env=env, timeout=120)


def test_ctrl_c_cancels_a_long_call_at_the_next_check(tmp_path):
    done = run_interrupted("sansui.erode(h, erosion_steps=400, force=True)", tmp_path)  # about a minute unless cancelled
    assert done.returncode == 0, done.stdout + done.stderr
    seconds = float(done.stdout.split()[2])
    assert seconds < 5.0, done.stdout


def test_ctrl_c_during_a_run_leaves_no_files(tmp_path):
    recipe = (
        "{'world': {'size': 1025}, 'node': [{'id': 'h', 'kind': 'midpoint'}, "
        "{'id': 'e', 'kind': 'erode', 'inputs': ['h'], 'erosion_steps': 400, 'force': True}], "
        "'output': [{'file': 'e.tif', 'node': 'e'}]}"
    )
    done = run_interrupted(f"sansui.run({recipe}, out_dir='out')", tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert list((tmp_path / "out").iterdir()) == []


def test_a_program_with_its_own_sigint_handler_keeps_it(tmp_path):
    script = textwrap.dedent(
        """
        import os, signal, threading
        import sansui
        got = []
        signal.signal(signal.SIGINT, lambda *a: got.append(1))
        threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        sansui.erode(sansui.midpoint(size=513), erosion_steps=40)
        print("handled", len(got))
        """
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and "handled 1" in done.stdout, done.stdout + done.stderr
