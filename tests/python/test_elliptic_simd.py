"""The SIMD loops of the float64 ufuncs F, E and R_F at every vector level this machine has
(gecko.elliptic.set_simd_level; GECKO_SIMD at import): accuracy against the mpmath tables of
tests/data (F <= 3 eps, E <= 4 eps, R_F <= 3 eps, as for the scalar kernels), the domain edges
whose lanes go back to the scalar kernel inside a vector (m > 1 next to sin^2 phi = 1/m, m -> 1,
large phi, NaN, infinities), tails shorter than a vector, strided and aliased operands, and
bitwise thread independence at each level."""
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import gecko
from gecko import elliptic as ell
from _tables import table as _table

LEVELS = ell.simd_levels()
EPS = np.finfo(float).eps


def _err_eps(got, ref):
    got = np.asarray(got, dtype=np.longdouble)
    ok = np.isfinite(ref) & (ref != 0)
    return np.abs((got[ok] - ref[ok]) / ref[ok]) / EPS


@pytest.fixture(params=LEVELS)
def level(request):
    before = ell.set_simd_level(request.param)
    yield request.param
    ell.set_simd_level(before)


@pytest.mark.parametrize("table", ["elliptic_legendre.csv", "elliptic_legendre_edge.csv",
                                   "elliptic_near_singular.csv"])
def test_legendre_tables_at_every_level(level, table):
    (phi, m), (F, E) = _table(table, ("phi", "m"), ("F", "E"))
    f, e = ell.ufuncs.ellint_f(phi, m), ell.ufuncs.ellint_e(phi, m)
    assert _err_eps(f, F).max() <= 3
    assert _err_eps(e, E).max() <= 4
    # the same elements one by one through the scalar entry points: same accuracy
    assert np.all(np.isfinite(f) == np.isfinite(F.astype(float)))


def test_carlson_rf_table_at_every_level(level):
    (x, y, z), (rf,) = _table("elliptic_rf.csv", ("x", "y", "z"), ("rf",))
    assert _err_eps(ell.ufuncs.carlson_rf(x, y, z), rf).max() <= 3


def test_levels_agree_within_the_accuracy_bound():
    # forcing the scalar fallback (or any other level) keeps the accuracy: every level lies
    # within 3 eps (F, R_F) / 4 eps (E) of the mpmath values, hence within 6 / 8 eps of each other
    (phi, m), _ = _table("elliptic_legendre.csv", ("phi", "m"))
    rng = np.random.default_rng(3)
    x, y, z = (10.0 ** rng.uniform(-6, 6, 4001) for _ in range(3))
    before = ell.simd_level()
    try:
        ell.set_simd_level("scalar")
        ref = (ell.ufuncs.ellint_f(phi, m), ell.ufuncs.ellint_e(phi, m), ell.ufuncs.carlson_rf(x, y, z))
        for lv in LEVELS[1:]:
            ell.set_simd_level(lv)
            got = (ell.ufuncs.ellint_f(phi, m), ell.ufuncs.ellint_e(phi, m), ell.ufuncs.carlson_rf(x, y, z))
            for g, r, bound in zip(got, ref, (6, 8, 6)):
                fin = np.isfinite(r)
                assert np.array_equal(np.isnan(g), np.isnan(r)), lv
                assert np.all(np.abs(g[fin] - r[fin]) <= bound * EPS * np.abs(r[fin])), lv
    finally:
        ell.set_simd_level(before)


def _edge_mix(n, rng):
    """Arguments that exercise every lane kind inside one vector: ordinary first-quadrant
    points, m > 1 next to the edge sin^2 phi = 1/m, m -> 1 with phi -> pi/2, large phi, negative
    phi, huge negative m, NaN, infinities, out-of-domain m > 1."""
    phi = rng.uniform(-np.pi / 2, np.pi / 2, n)
    m = rng.uniform(-3, 1, n)
    kind = rng.integers(0, 9, n)
    mm = 10.0 ** rng.uniform(0.01, 6, n)
    sel = kind == 1
    phi[sel] = np.arcsin(np.sqrt(1 / mm[sel])) * (1 - 10.0 ** -rng.uniform(1, 15, sel.sum()))
    m[sel] = mm[sel]
    sel = kind == 2
    m[sel] = 1 - 10.0 ** -rng.uniform(0, 16, sel.sum())
    phi[sel] = np.pi / 2 - 10.0 ** -rng.uniform(0, 15, sel.sum())
    sel = kind == 3
    phi[sel] = rng.uniform(-50, 50, sel.sum())
    sel = kind == 4
    m[sel] = -(10.0 ** rng.uniform(10, 300, sel.sum()))
    phi[kind == 5] = np.nan
    m[kind == 6] = -np.inf
    phi[kind == 7] = np.inf
    m[kind == 8] = 10.0 ** rng.uniform(1, 3, (kind == 8).sum())  # mostly beyond the edge
    return phi, m


@pytest.mark.parametrize("name", ["ellint_f", "ellint_e"])
def test_mixed_lanes_and_tails_match_the_scalar_kernel_at_every_level(level, name):
    # every element equals the scalar entry point's answer for it bit for bit (the vector lanes do
    # the scalar kernel's arithmetic operation for operation, without contraction; the other lanes
    # are the scalar kernel's), for lengths that are not multiples of any vector width (up to two
    # AVX-512 registers, 16 doubles, and one more) and for strided and aliased operands
    rng = np.random.default_rng(11)
    u = getattr(ell.ufuncs, name)
    scalar = getattr(gecko._core, name + "_scalar")
    phi, m = _edge_mix(4003, rng)
    phi[:1000], m[:1000] = rng.uniform(-np.pi / 2, np.pi / 2, 1000), rng.uniform(-5, 1, 1000)  # vector lanes
    want = np.array([scalar(float(p), float(q), 1) for p, q in zip(phi, m)])
    for n in list(range(1, 18)) + [4003]:
        got = u(phi[:n], m[:n])
        assert np.array_equal(got.view(np.uint64), want[:n].view(np.uint64)), n
    ref = u(phi, m)
    out = np.empty(2 * len(phi))
    u(phi[::-1].copy()[::-1], m, out=out[::2])            # strided output
    assert np.array_equal(out[::2].view(np.uint64), ref.view(np.uint64))
    alias = phi.copy()
    u(alias, m, out=alias)                                 # out= one of the inputs
    assert np.array_equal(alias.view(np.uint64), ref.view(np.uint64))


def test_carlson_rf_lanes_outside_the_vector_window(level):
    rng = np.random.default_rng(13)
    n = 1001
    x, y, z = (10.0 ** rng.uniform(-6, 6, n) for _ in range(3))
    x[::7] = 0.0                                           # one zero
    y[::11] = 1e-310                                       # subnormal with normal partners
    z[::13] = 10.0 ** rng.uniform(300, 308, len(z[::13]))  # rescaled by the scalar kernel
    x[::17] = np.inf
    y[::19] = np.nan
    z[::23] = -1.0                                         # out of domain
    x[::29], y[::29] = 0.0, 0.0                            # two zeros
    want = np.array([gecko._core.carlson_rf_scalar(float(a), float(b), float(c), 1) for a, b, c in zip(x, y, z)])
    for k in (1, 2, 3, 5, 7, 9, n):
        got = ell.ufuncs.carlson_rf(x[:k], y[:k], z[:k])
        assert np.array_equal(got.view(np.uint64), want[:k].view(np.uint64)), k  # bit for bit


@pytest.mark.parametrize("name,nargs", [("ellint_f", 2), ("ellint_e", 2), ("carlson_rf", 3)])
def test_bitwise_identical_for_any_thread_count_at_every_level(level, name, nargs):
    rng = np.random.default_rng(5)
    n = 50_003
    if name.startswith("ellint"):
        args = list(_edge_mix(n, rng))
    else:
        args = [10.0 ** rng.uniform(-5, 5, n) for _ in range(nargs)]
    u = getattr(ell.ufuncs, name)
    before = ell.set_num_threads(1)
    try:
        ref = u(*args)
        for t in (2, 3, 7):
            ell.set_num_threads(t)
            assert np.array_equal(u(*args).view(np.uint64), ref.view(np.uint64)), t
    finally:
        ell.set_num_threads(before)


def _cpu_vendor():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("vendor_id"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return ""


def _auto_level():
    """The level import picks: the highest, except that AVX-512 machines get the schedule of
    their vendor (avx512-sqrt-unit on AMD, avx512 elsewhere; src/bindings/elliptic_simd_avx512.cpp)."""
    if "avx512" not in LEVELS:
        return LEVELS[-1]
    return "avx512-sqrt-unit" if _cpu_vendor() == "AuthenticAMD" else "avx512"


def test_both_avx512_schedules_are_offered_together():
    assert ("avx512" in LEVELS) == ("avx512-sqrt-unit" in LEVELS)
    assert LEVELS[0] == "scalar"


def test_level_errors_and_environment_variable():
    with pytest.raises(ValueError, match="not available"):
        ell.set_simd_level("avx1024")
    assert ell.set_simd_level("auto") == ell.simd_level()
    assert ell.simd_level() == _auto_level()
    code = "import gecko.elliptic as e; print(e.simd_level())"
    env = dict(os.environ, GECKO_SIMD="scalar")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "scalar"
    env["GECKO_SIMD"] = "nonsense"
    out = subprocess.run([sys.executable, "-W", "always", "-c", code], env=env, capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == _auto_level() and "GECKO_SIMD=nonsense" in out.stderr
    if "avx512" in LEVELS:
        for name in ("avx512", "avx512-sqrt-unit"):
            env["GECKO_SIMD"] = name
            out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
            assert out.stdout.strip() == name


@pytest.mark.parametrize("name", ["ellint_f", "ellint_e", "carlson_rf"])
def test_vector_levels_raise_no_floating_point_warnings_the_scalar_loop_does_not(name):
    # NaN lanes must not signal invalid in the vector compares (numpy turns the flags into
    # RuntimeWarnings after the loop)
    rng = np.random.default_rng(17)
    if name == "carlson_rf":
        args = [10.0 ** rng.uniform(-5, 5, 999) for _ in range(3)]
        args[0][::3], args[1][::5], args[2][::7] = np.nan, np.inf, -1.0
    else:
        args = list(_edge_mix(999, rng))
    u = getattr(ell.ufuncs, name)

    def flags(lv):
        before = ell.set_simd_level(lv)
        try:
            with warnings.catch_warnings(record=True) as w:
                warnings.simplefilter("always")
                u(*args)
            return sorted({str(x.message) for x in w})
        finally:
            ell.set_simd_level(before)

    want = flags("scalar")
    for lv in LEVELS[1:]:
        assert flags(lv) == want, lv


def test_zero_d_and_scalar_calls_take_the_scalar_kernel_with_the_ufuncs_types():
    # 0-d float64 arrays (alone or with Python scalars) skip the ufunc machinery but return what
    # the ufunc returns, a numpy float64; other dtypes still go through the ufunc
    for fn, args in ((gecko.ellint_f, (0.7, 0.4)), (gecko.ellint_e, (0.7, 0.4)), (gecko.ellint_k, (0.4,)),
                     (gecko.carlson_rf, (1.0, 2.0, 3.0)), (gecko.carlson_rj, (1.0, 2.0, 3.0, 4.0))):
        u = getattr(ell.ufuncs, fn.__name__)
        want = u(*args)
        got = fn(*(np.array(a) for a in args))
        assert type(got) is np.float64 and got == want
        mixed = fn(np.array(args[0]), *args[1:])
        assert type(mixed) is np.float64 and mixed == want
        assert type(fn(*args)) is float and fn(*args) == want
        f32 = fn(*(np.array(a, dtype=np.float32) for a in args))
        assert f32.dtype == np.float32 and f32 == u(*(np.float32(a) for a in args))
    with pytest.raises(ValueError, match="m = 5"):
        gecko.ellint_f(np.array(1.0), np.array(5.0))
    assert np.isnan(gecko.ellint_f(np.array(1.0), np.array(5.0), errors="nan"))
    with pytest.raises(ValueError):
        gecko.ellint_f(np.array(1.0), 0.5, errors="bogus")


def test_ellint_ek_ufunc_gives_e_and_k_together():
    # the same values as the complete-integral table (mpmath), and as gecko.ellint_ek; NaN for m > 1
    (m,), (E, K) = _table("elliptic_complete.csv", ("m",), ("E", "K"))
    e, k = ell.ufuncs.ellint_ek(m)
    assert _err_eps(e, E).max() <= 4 and _err_eps(k, K).max() <= 3
    ek = gecko.ellint_ek(m[np.isfinite(E.astype(float))])
    assert np.array_equal(ek.E, e[np.isfinite(E.astype(float))])
    e32, k32 = ell.ufuncs.ellint_ek(np.float32(0.5))
    assert e32.dtype == np.float32 and abs(k32 - 1.8540747) < 1e-6
    assert np.all(np.isnan(ell.ufuncs.ellint_ek([1.5, np.nan])))


def test_no_spurious_overflow_warning_for_m_to_minus_infinity(level):
    # valid arguments at the far end of the range: numpy turned the overflow flag raised inside
    # the R_D sum (m -> -inf) and R_J's spread test into a RuntimeWarning, though the values
    # were right. Vector lanes with Delta^2 >= 2^500 go back to the scalar kernel: same bits.
    m = np.array([-1e160, -1e250, -1e300, -1e305, -np.finfo(float).max] * 3)
    phi = np.repeat([1e-80, 1.0, 1.6], 5)
    x = np.zeros(3)
    y = np.array([1e200, 1e300, np.finfo(float).max])
    with np.errstate(over="raise", divide="raise", invalid="raise"):  # (s^3 at phi = 1e-80 underflows: real)
        e = ell.ufuncs.ellint_e(phi, m)
        ek = ell.ufuncs.ellint_ek(m)
        rj = ell.ufuncs.carlson_rj(x, y, np.ones(3), np.full(3, 2.0))
    assert np.all(np.isfinite(e)) and np.all(np.isfinite(ek[0])) and np.all(np.isfinite(rj))
    want = np.array([gecko._core.ellint_e_scalar(float(p), float(q), 1) for p, q in zip(phi, m)])
    assert np.array_equal(e.view(np.uint64), want.view(np.uint64))
