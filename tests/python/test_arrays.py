"""numpy arrays both ways without copies, and what a converting copy is for."""
import gc

import numpy as np
import pytest

import sansui
from conftest import rss_bytes


def test_a_result_is_the_library_s_own_buffer():
    h = sansui.midpoint(size=257, seed=1)
    assert h.dtype == np.float32 and h.shape == (257, 257) and h.flags.c_contiguous
    assert h.__array_interface__["data"][0] == sansui._sansui._grid_address(h)
    view = h[10:20]
    assert sansui._sansui._grid_address(view) == sansui._sansui._grid_address(h)  # views keep the grid alive
    address = sansui._sansui._grid_address(h)
    del h
    gc.collect()
    assert view.__array_interface__["data"][0] == address + 10 * 257 * 4
    assert np.isfinite(view).all()


def test_making_a_terrain_does_not_grow_memory_by_a_second_grid():
    grid_bytes = 2049 * 2049 * 4
    sansui.midpoint(size=2049, seed=2)  # the allocator's arenas and the thread pool, once
    gc.collect()
    before = rss_bytes()
    h = sansui.midpoint(size=2049, seed=2)
    grown = rss_bytes() - before
    assert grown < 1.5 * grid_bytes, f"memory grew by {grown / grid_bytes:.2f} grids"
    assert h[0, 0] == h[0, 0]


def test_c_contiguous_float32_arrays_are_read_in_place():
    a = np.zeros((65, 65), np.float32)
    assert sansui._sansui._reads_in_place(a)
    assert sansui._sansui._reads_in_place(sansui.midpoint(size=65))
    assert not sansui._sansui._reads_in_place(a.astype(np.float64))        # converted once
    assert not sansui._sansui._reads_in_place(np.asfortranarray(np.ones((65, 65), np.float32) + a))  # not C order
    assert not sansui._sansui._reads_in_place(a.astype(">f4"))               # the other byte order
    assert not sansui._sansui._reads_in_place(np.zeros((130, 130), np.float32)[::2, ::2])  # strided


def test_other_arrays_of_real_numbers_are_converted_to_the_same_result():
    h = sansui.midpoint(size=65, seed=4)
    expected = sansui.smooth(h, cell=10.0)
    as_double = np.array(h, dtype=np.float64)
    fortran = np.asfortranarray(np.array(h))
    with pytest.warns(sansui.WorldWarning):  # plain arrays: the default world, said
        assert np.array_equal(sansui.smooth(as_double), expected)
        assert np.array_equal(sansui.smooth(fortran), expected)
        assert np.array_equal(sansui.smooth(h.tolist()), expected)
    assert np.array_equal(sansui.smooth(h.astype(np.float64)), expected)  # a Grid's copy keeps its world


def test_an_input_array_is_not_changed():
    h = sansui.midpoint(size=129, seed=5)
    before = h.copy()
    sansui.erode(h, stage="old")
    assert np.array_equal(h, before)


def test_results_are_writable_numpy_arrays():
    h = sansui.midpoint(size=33)
    h += 1.0
    assert h.flags.writeable
