"""`cor`: numpy broadcasting, scalars, dtypes, and bad input raising with group and index."""

import threading
import time

import numpy as np
import pytest

import mdr_impact as mi


def test_scalars_give_floats():
    e = mi.cor(0.45, 0.01, 1.0)
    assert type(e) is float
    assert 0.0 < e < 1.0
    e0d = mi.cor(np.float64(0.45), np.array(0.01), 1)
    assert type(e0d) is float and e0d == e
    c, t, d = mi.cor(0.45, 0.01, 1.0, full_output=True)
    assert c == e and type(t) is float and type(d) is float and t > 0 and d > 0


def test_broadcast_shapes_and_values():
    nu = np.array([0.3, 0.45, 0.5])[:, None, None]   # (3, 1, 1)
    p2 = np.array([1e-3, 1e-2, 1e-1, 1.0])[:, None]   # (4, 1)
    p3 = [0.1, 1.0]                                   # (2,)
    e = mi.cor(nu, p2, p3)
    assert e.shape == (3, 4, 2)
    assert e.dtype == np.float64
    for i, j, k in np.ndindex(e.shape):
        assert e[i, j, k] == mi.cor(nu[i, 0, 0], p2[j, 0], p3[k])
    c, t, d = mi.cor(nu, p2, p3, full_output=True)
    assert np.array_equal(c, e) and t.shape == d.shape == (3, 4, 2)


def test_one_array_two_scalars_and_lists():
    p3 = np.logspace(-2, 2, 9)
    e = mi.cor(0.45, 0.01, p3)
    assert e.shape == (9,)
    assert np.array_equal(e, mi.cor([0.45] * 9, 0.01, list(p3)))
    # integers are numbers too
    assert mi.cor(0, 1, 1) == mi.cor(0.0, 1.0, 1.0)


def test_empty_and_non_contiguous_inputs():
    assert mi.cor(0.45, 0.01, np.array([])).shape == (0,)
    assert mi.cor(np.zeros((0, 3)), 0.01, 1.0).shape == (0, 3)
    grid = np.logspace(-2, 1, 12).reshape(3, 4)
    e_t = mi.cor(0.3, 0.05, grid.T)          # a transposed (Fortran-ordered) view
    e_s = mi.cor(0.3, 0.05, grid[:, ::2])    # a strided view
    assert np.array_equal(e_t, mi.cor(0.3, 0.05, np.ascontiguousarray(grid.T)))
    assert np.array_equal(e_s, mi.cor(0.3, 0.05, grid[:, ::2].copy()))


def test_incompatible_shapes_raise_value_error():
    with pytest.raises(mi.Error, match="^nu, p2, p3: shapes cannot be broadcast together"):
        mi.cor(np.zeros(3) + 0.3, np.ones(4), 1.0)


@pytest.mark.parametrize("args,message", [
    ((0.7, 1.0, 1.0), "nu = 7e-1 is out of range: allowed -1 < nu <= 0.5"),
    ((-1.0, 1.0, 1.0), "nu = -1e0 is out of range: allowed -1 < nu <= 0.5"),
    ((0.3, np.nan, 1.0), "p2 = NaN is out of range"),
    ((0.3, 1.0, np.inf), "p3 = inf is out of range: allowed 0 <= p3 < inf"),
    ((0.3, 0.0, 1.0), "p2 = 0e0 is out of range"),
    ((0.3, 1.0, -1e-3), "p3 = -1e-3 is out of range"),
])
def test_scalar_bad_input_raises_with_group(args, message):
    with pytest.raises(mi.Error) as err:
        mi.cor(*args)
    assert str(err.value).startswith(message)
    assert isinstance(err.value, ValueError)
    assert type(err.value).__module__ == "mdr_impact"


def test_array_bad_input_names_index():
    p2 = np.full((2, 3), 0.1)
    p2[1, 2] = np.nan
    with pytest.raises(ValueError, match=r"^index \(1, 2\): p2 = NaN is out of range"):
        mi.cor(0.45, p2, 1.0)
    nu = np.array([0.3, 0.4, 0.6])
    with pytest.raises(mi.Error, match=r"^index \(2,\): nu = 6e-1 is out of range"):
        mi.cor(nu, 1.0, 1.0)
    # the index is that of the broadcast shape
    with pytest.raises(mi.Error, match=r"^index \(0, 1\): p3 = -1e0"):
        mi.cor(0.3, [[1.0], [2.0]], [1.0, -1.0])


def test_bad_options_and_types_raise():
    with pytest.raises(mi.Error, match=r"^rtol = 1e0 is out of range: allowed 1e-12 <= rtol"):
        mi.cor(0.3, 1.0, 1.0, rtol=1.0)
    with pytest.raises(mi.Error, match="solver: cannot read 'foo': expected one of auto"):
        mi.cor(0.3, 1.0, 1.0, solver="foo")
    with pytest.raises(mi.Error, match="^nu: not a real number"):
        mi.cor("abc", 1.0, 1.0)
    # numbers in strings, complex numbers and None are refused, never converted
    for bad in ["0.45", 0.45 + 0.1j, np.array([0.3, 0.4 + 0j]), None]:
        with pytest.raises(mi.Error, match="^nu: not a real number"):
            mi.cor(bad, 1.0, 1.0)
    # integers and booleans are numbers
    assert mi.cor(0, 1, 1) == mi.cor(0.0, 1.0, 1.0)


def test_refused_solve_raises_not_nan():
    # the paper's explicit Euler cannot verify 1e-6 on a dissipative case: a refusal, never a
    # NaN or a crash
    with pytest.raises(mi.Error, match="mdr-euler"):
        mi.cor(0.45, 0.01, 1.0, solver="mdr-euler", rtol=1e-6)


def test_solvers_agree_within_rtol():
    nu, p2, p3 = 0.45, 0.01, 1.0
    truth = mi.cor(nu, p2, p3, solver="reference", rtol=1e-10)
    for solver, rtol in [("auto", 1e-6), ("fast", 1e-6), ("mdr", 1e-4)]:
        assert abs(mi.cor(nu, p2, p3, solver=solver, rtol=rtol) - truth) <= 2 * rtol * truth


def test_gil_is_released_during_solves():
    p3 = np.logspace(-2, 3, 4000)
    done = threading.Event()
    result = {}

    def work():
        result["e"] = mi.cor(0.45, 0.01, p3, rtol=1e-8)
        done.set()

    ticks = []
    t0 = time.perf_counter()
    worker = threading.Thread(target=work)
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.002)
    worker.join()
    total = time.perf_counter() - t0
    assert result["e"].shape == p3.shape
    # with the GIL held for the whole solve this loop could not run in between
    gaps = np.diff([t0, *ticks, time.perf_counter()])
    assert total > 0.05, "too little work to observe"
    assert gaps.max() < 0.5 * total


def test_first_failing_solve_is_named_across_chunks():
    # p3 = 0 is elastic (Hertz, any solver); one dissipative row far into the array makes the
    # paper's explicit Euler refuse rtol 1e-6 there
    p3 = np.zeros(9000)
    p3[[7000, 8000]] = 1.0
    with pytest.raises(mi.Error, match=r"^index \(7000,\): mdr-euler"):
        mi.cor(0.45, 0.01, p3, solver="mdr-euler", rtol=1e-6)


def test_keyboard_interrupt_ends_a_long_call():
    import _thread
    import signal

    # A process started in the background by a shell without job control inherits SIGINT
    # ignored, and Python then keeps it ignored, so that interrupt_main() would do nothing:
    # install Python's own handler for the test, as an interactive session has it.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    p3 = np.logspace(-2, 3, 40000)
    timer = threading.Timer(0.05, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            mi.cor(0.45, 0.01, p3, rtol=1e-8)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


def test_cor_accepts_misaligned_and_read_only_arrays():
    # what a pickled chunk (dask on a worker) can look like: a read-only view of a byte buffer
    # at an odd offset
    values = np.array([0.1, 1.0, 10.0])
    raw = b"\0" + values.tobytes()
    p2 = np.frombuffer(raw, dtype=np.float64, offset=1)
    assert not p2.flags.aligned and not p2.flags.writeable
    assert np.array_equal(mi.cor(0.3, p2, 1.0), mi.cor(0.3, values, 1.0))
