"""gecko's elliptic integrals from Python: values against mpmath at the exact double inputs,
numpy broadcasting semantics, error handling, and the GIL being released in the loops."""
import math
import threading

import numpy as np
import pytest

import gecko

mpmath = pytest.importorskip("mpmath")
mpmath.mp.dps = 40
EPS = np.finfo(float).eps


def rel_err_eps(got, want):
    want = float(want)
    return abs(got - want) / (abs(want) * EPS)


@pytest.fixture(scope="module")
def points():
    rng = np.random.default_rng(20261121)
    phi = rng.uniform(0, math.pi / 2, 150)
    m = np.concatenate([rng.uniform(-5, 1, 100), 1 - 10.0 ** -rng.uniform(0, 16, 50)])
    return phi, m


def test_ellint_f_and_e_match_mpmath(points):
    phi, m = points
    f = gecko.ellint_f(phi, m)
    e = gecko.ellint_e(phi, m)
    worst_f = max(rel_err_eps(f[i], mpmath.ellipf(mpmath.mpf(phi[i]), mpmath.mpf(m[i]))) for i in range(len(phi)))
    worst_e = max(rel_err_eps(e[i], mpmath.ellipe(mpmath.mpf(phi[i]), mpmath.mpf(m[i]))) for i in range(len(phi)))
    assert worst_f <= 3, worst_f
    assert worst_e <= 4, worst_e


def test_complete_integrals_match_mpmath(points):
    _, m = points
    k = gecko.ellint_k(m)
    ek = gecko.ellint_ek(m)
    for i in range(len(m)):
        K = mpmath.ellipk(mpmath.mpf(m[i]))
        E = mpmath.ellipe(mpmath.mpf(m[i]))
        assert rel_err_eps(k[i], K) <= 3
        assert rel_err_eps(ek.K[i], K) <= 3
        assert rel_err_eps(ek.E[i], E) <= 4


def test_carlson_match_mpmath():
    rng = np.random.default_rng(7)
    x, y, z, p = (10.0 ** rng.uniform(-6, 6, 60) for _ in range(4))
    rf, rd, rj, rc = (gecko.carlson_rf(x, y, z), gecko.carlson_rd(x, y, z),
                      gecko.carlson_rj(x, y, z, p), gecko.carlson_rc(x, y))
    mp = mpmath.mpf
    for i in range(60):
        assert rel_err_eps(rf[i], mpmath.elliprf(mp(x[i]), mp(y[i]), mp(z[i]))) <= 3
        assert rel_err_eps(rd[i], mpmath.elliprd(mp(x[i]), mp(y[i]), mp(z[i]))) <= 8
        assert rel_err_eps(rj[i], mpmath.elliprj(mp(x[i]), mp(y[i]), mp(z[i]), mp(p[i]))) <= 8
        assert rel_err_eps(rc[i], mpmath.elliprc(mp(x[i]), mp(y[i]))) <= 3


def test_broadcasting_like_a_ufunc():
    phi = np.linspace(0.1, 1.5, 6).reshape(2, 3)
    m = np.array([0.0, 0.5, 0.9])
    out = gecko.ellint_f(phi, m)
    assert out.shape == (2, 3)
    assert out.dtype == np.float64
    for i in range(2):
        for j in range(3):
            assert out[i, j] == gecko.ellint_f(float(phi[i, j]), float(m[j]))
    assert isinstance(gecko.ellint_f(0.3, 0.2), float)
    assert gecko.ellint_f([0.3], 0.2).shape == (1,)
    assert gecko.ellint_k(np.empty((0, 4))).shape == (0, 4)
    # non-contiguous input (a transposed view) gives the same as its contiguous copy
    assert np.array_equal(gecko.ellint_e(phi.T, 0.3), gecko.ellint_e(np.ascontiguousarray(phi.T), 0.3))
    ek = gecko.ellint_ek(np.array([[0.1, 0.2]]))
    assert ek.E.shape == ek.K.shape == (1, 2)
    with pytest.raises(ValueError):
        gecko.ellint_f(np.zeros(3), np.zeros(4))  # shapes do not broadcast


def test_exact_special_values():
    assert gecko.ellint_f(0.0, 0.7) == 0.0
    assert gecko.ellint_k(0.0) == pytest.approx(math.pi / 2, rel=EPS)
    assert gecko.ellint_k(1.0) == math.inf
    assert gecko.ellint_ek(1.0).E == pytest.approx(1.0, rel=EPS)
    assert gecko.carlson_rf(4.0, 4.0, 4.0) == pytest.approx(0.5, rel=EPS)


def test_domain_errors_name_the_argument():
    with pytest.raises(ValueError, match=r"\bm\b"):
        gecko.ellint_k(1.5)
    with pytest.raises(ValueError, match="m"):
        gecko.ellint_f(1.2, 2.0)  # sin^2(1.2) > 1/2
    with pytest.raises(ValueError):
        gecko.carlson_rf(-1.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="errors"):
        gecko.ellint_k(0.5, errors="ignore")


def test_nan_policy_and_nan_propagation():
    out = gecko.ellint_k(np.array([0.5, 1.5, 0.2]), errors="nan")
    assert math.isnan(out[1]) and np.isfinite(out[[0, 2]]).all()
    assert math.isnan(gecko.ellint_f(math.nan, 0.5))
    assert math.isnan(gecko.carlson_rf(1.0, math.nan, 2.0))


def test_threads_give_identical_results_and_gil_is_released():
    rng = np.random.default_rng(3)
    phi = rng.uniform(0, 1.5, 3_000_000)
    m = rng.uniform(0, 1, 3_000_000)
    serial = gecko.ellint_f(phi, m)
    results = [None, None]

    def work(i):
        results[i] = gecko.ellint_f(phi, m)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    ticks = 0
    for t in threads:
        t.start()
    # While the C++ loops run, this thread must keep running Python code: it could not if the
    # kernels held the GIL for their whole loop.
    while any(t.is_alive() for t in threads):
        ticks += 1
    for t in threads:
        t.join()
    assert np.array_equal(results[0], serial) and np.array_equal(results[1], serial)
    assert ticks > 1000, ticks


# ---- ufuncs (src/bindings/elliptic_ufuncs.cpp) --------------------------------------------------
from _tables import table  # noqa: E402
from gecko import elliptic as ell  # noqa: E402

UFUNC_NAMES = ["ellint_f", "ellint_e", "ellint_k", "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc"]


def test_raw_ufuncs_have_float32_and_float64_loops():
    for name in UFUNC_NAMES:
        u = getattr(ell.ufuncs, name)
        assert isinstance(u, np.ufunc), name
        assert u.nout == 1
        sig = "f" * u.nin + "->f", "d" * u.nin + "->d"
        assert sig[0] in u.types and sig[1] in u.types, (name, u.types)


def test_out_where_and_dtype_are_numpys():
    rng = np.random.default_rng(11)
    phi, m = rng.uniform(0, 1.5, (4, 5)), rng.uniform(-2, 1, 5)
    want = gecko.ellint_f(phi, m)
    out = np.empty((4, 5))
    got = gecko.ellint_f(phi, m, out=out)
    assert got is out and np.array_equal(out, want)
    got = ell.ufuncs.ellint_f(phi, m, out=out)
    assert got is out and np.array_equal(out, want)
    # where=: masked elements keep what out held
    mask = phi > 0.7
    out = np.full((4, 5), -1.0)
    gecko.ellint_e(phi, m, out=out, where=mask)
    assert np.array_equal(out[mask], gecko.ellint_e(phi, m)[mask])
    assert (out[~mask] == -1.0).all()
    # dtype= and float32 inputs give float32, computed by the float kernel (<= 3 eps(float))
    for res in (gecko.ellint_f(phi, m, dtype=np.float32),
                gecko.ellint_f(phi.astype(np.float32), m.astype(np.float32)),
                ell.ufuncs.ellint_f(phi, m, dtype=np.float32)):
        assert res.dtype == np.float32
        ref = gecko.ellint_f(phi.astype(np.float32).astype(float), m.astype(np.float32).astype(float))
        assert np.all(np.abs(res - ref) <= 3 * np.finfo(np.float32).eps * np.abs(ref))
    assert gecko.carlson_rf(np.float32([1, 2]), 2.0, 3.0).dtype == np.float32
    assert gecko.ellint_k(np.float32(0.5)).dtype == np.float32
    # broadcasting of all four R_J arguments
    assert gecko.carlson_rj(np.ones((2, 1, 1, 1)), np.ones((3, 1, 1)), np.ones((4, 1)), np.ones(5)).shape == (2, 3, 4, 5)


def test_raise_policy_names_argument_value_index_and_range():
    m = np.array([[0.5, 0.2, 0.1], [0.3, 1.5, 0.1]])
    with pytest.raises(ValueError, match=r"gecko::ellint_k: m = 1.5 is out of range: need m <= 1 \(at index \(1, 1\)\)$"):
        gecko.ellint_k(m)
    with pytest.raises(ValueError, match=r"ellint_f: m = 2 .*sin\^2\(phi\) <= 1/m.*\(at index 3\)$"):
        gecko.ellint_f(np.array([0.1, 0.2, 0.3, 1.2]), 2.0)
    with pytest.raises(ValueError, match=r"carlson_rf: y = -1 is out of range.*\(at index \(0, 2\)\)$"):
        gecko.carlson_rf(1.0, np.array([[1.0, 2.0, -1.0]]), 1.0)
    with pytest.raises(ValueError, match=r"m = 1.5 is out of range: need m <= 1$"):
        gecko.ellint_k(1.5)
    with pytest.raises(ValueError, match=r"m = 1.5 is out of range.*\(at index \(\)\)$|m = 1.5 is out of range.*need m <= 1$"):
        gecko.ellint_k(np.array(1.5))
    # float32: the message names the float32 value
    with pytest.raises(ValueError, match=r"\(at index 1\)$"):
        gecko.ellint_k(np.float32([0.5, 2.0]))
    # masked-out bad elements are not errors, NaN input is not an error
    out = np.zeros(3)
    gecko.ellint_k(np.array([0.5, 2.0, 0.1]), out=out, where=np.array([True, False, True]))
    assert out[1] == 0.0
    assert np.isnan(gecko.ellint_k(np.array([0.5, np.nan]))[1])


def test_nan_policy_of_ufuncs_and_functions():
    m = np.array([0.5, 1.5, 0.2])
    for res in (ell.ufuncs.ellint_k(m), gecko.ellint_k(m, errors="nan")):
        assert np.isnan(res[1]) and np.isfinite(res[[0, 2]]).all()
    assert math.isnan(gecko.ellint_k(1.5, errors="nan"))
    assert np.isnan(ell.ufuncs.ellint_f(1.2, 2.0))
    assert np.isnan(ell.ufuncs.carlson_rf(0.0, 0.0, 1.0))
    assert np.isnan(ell.ufuncs.ellint_e(np.inf, 0.5))
    assert np.isnan(gecko.carlson_rj(-1.0, 1.0, 1.0, 1.0, errors="nan"))


def test_scalar_calls_agree_with_the_ufuncs():
    assert isinstance(gecko.ellint_f(0.3, 0.2), float)
    assert gecko.ellint_f(0.3, 0.2) == ell.ufuncs.ellint_f(0.3, 0.2)
    assert gecko.ellint_e(1, 0) == ell.ufuncs.ellint_e(1.0, 0.0)
    assert gecko.carlson_rj(1.0, 2.0, 3.0, np.float64(4.0)) == ell.ufuncs.carlson_rj(1.0, 2.0, 3.0, 4.0)


@pytest.mark.parametrize("name,nargs", [("ellint_f", 2), ("ellint_e", 2), ("carlson_rf", 3), ("carlson_rj", 4)])
def test_results_bitwise_identical_for_any_thread_count(name, nargs):
    rng = np.random.default_rng(5)
    n = 70_001
    if name.startswith("ellint"):
        args = [rng.uniform(-4, 4, n), rng.uniform(-3, 1, n)]
    else:
        args = [10.0 ** rng.uniform(-5, 5, n) for _ in range(nargs)]
    u = getattr(ell.ufuncs, name)
    before = ell.set_num_threads(1)
    try:
        ref = u(*args)
        for t in (2, 3, 7, 0):
            ell.set_num_threads(t)
            assert np.array_equal(u(*args).view(np.uint64), ref.view(np.uint64)), t
            # strided input and output through the same loop
            out = np.empty(2 * n)
            u(*(a[::-1] for a in args), out=out[::2])
            assert np.array_equal(out[::2][::-1].view(np.uint64), ref.view(np.uint64)), t
    finally:
        ell.set_num_threads(before)
    with pytest.raises(ValueError):
        ell.set_num_threads(-1)


def test_m_above_one_at_the_edge_against_mpmath_table():
    # exact values at the given double inputs (tests/data/gen_elliptic.py edge), no allowance for
    # the conditioning in sin(phi): F <= 3 eps, E <= 4 eps
    (phi, m), (F, E) = table("elliptic_legendre_edge.csv", ("phi", "m"), ("F", "E"), ref=str)
    f, e = gecko.ellint_f(phi, m), gecko.ellint_e(phi, m)

    def worst(got, want):
        return max(float(abs(mpmath.mpf(float(g)) - mpmath.mpf(w)) / abs(mpmath.mpf(w))) / EPS
                   for g, w in zip(got, want))

    assert worst(f, F) <= 3
    assert worst(e, E) <= 4
    i = int(np.argmin(np.abs(m - 1.46e5)))  # the case of issue 16: m = 1.46e5, m sin^2 phi = 0.9993
    assert m[i] == 1.46e5 and worst([gecko.ellint_f(float(phi[i]), 1.46e5)], [F[i]]) <= 3
