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
    assert worst_e <= 8, worst_e


def test_complete_integrals_match_mpmath(points):
    _, m = points
    k = gecko.ellint_k(m)
    ek = gecko.ellint_ek(m)
    for i in range(len(m)):
        K = mpmath.ellipk(mpmath.mpf(m[i]))
        E = mpmath.ellipe(mpmath.mpf(m[i]))
        assert rel_err_eps(k[i], K) <= 3
        assert rel_err_eps(ek.K[i], K) <= 3
        assert rel_err_eps(ek.E[i], E) <= 8


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
