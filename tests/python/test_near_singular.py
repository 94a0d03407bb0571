"""Near-singular families of the two-level seta through the Python API (issue 6 item 3).

The C++ side (tests/seta/near_singular.cpp) checks the same limits against the RK4 shooting; here
the public Python calls are held to the exact limits and convergence laws:
  * Ft -> (Ft)max: Fn(Ft) - Fn((Ft)max) ~ a sqrt((Ft)max - Ft), exponent 1/2; Fn((Ft)max) of the
    reference scene against the mpmath reference;
  * EA1 = EA2 -> inf (through critical_line_batch, 1 and 2 threads bitwise equal): exponent -1,
    and EA (Fn(EA) - Fn(inf)) -> C = -EA^2 dFn/dEA from TwoLevelSeta.sensitivities;
  * alpha2 -> 0: exponent 1, slope dFn/dalpha2 from the sensitivities;
  * l2 -> 0: the seta tends to gecko.SingleFiber with the beam's EI1, l1, alpha1 (alpha2 = 0,
    inextensible) and w' = w EI2/EI1 (the joint carries the moment EI1 theta1' = EI2 theta2'); with
    EI2 = EI1 it IS the fiber of length l1 + l2.
Tolerances: exponents within 0.01 of the exact ones (measured within 0.001); solver-to-solver
differences within 1e-12 max(1, |Fn|) (the Newton tolerance both solvers are run at).
"""
import math

import numpy as np
import pytest

import gecko

FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")


def slope(x, y):
    return float(np.polyfit(np.log(np.asarray(x, float)), np.log(np.abs(np.asarray(y, float))), 1)[0])


def converged(line):
    # solved: 0, or 7 (solved, but the seta crosses the substrate: the reference design does near
    # (Ft)max; its Fn is kept and is what these tests measure)
    assert np.all(np.isin(line.status, (0, 7))), line.status
    return line.Fn


@pytest.mark.parametrize("design", [{}, dict(EI1=0.883755, EI2=0.0823395, l2=0.196211, alpha1=0.463326,
                                             alpha2=0.638599, EA2=100.03)])
def test_ft_to_ftmax_sqrt_law(design):
    s = gecko.TwoLevelSeta(**design)
    fm = s.ft_max
    end = converged(s.critical_line([fm]))[0]
    if not design:  # reference scene: mpmath (tests/data/gen_seta_reference.py)
        assert abs(end - -0.3624940899618405101778407) <= 1e-13
    d = fm * 10.0 ** -np.arange(4, 13)
    Ft = fm - d
    fn = converged(s.critical_line(Ft))
    assert abs(slope(fm - Ft, fn - end) - 0.5) <= 0.01
    # the approach is monotone and from one side (the line is vertical at its end)
    assert np.all(np.diff(np.abs(fn - end)) < 0)


def batch_both_threads(designs, Ft):
    one = gecko.critical_line_batch(designs, Ft, threads=1)
    two = gecko.critical_line_batch(designs, Ft, threads=2)
    assert one.Fn.tobytes() == two.Fn.tobytes()
    assert one.status.tobytes() == two.status.tobytes()
    return converged(one)


def test_ea_to_infinity_first_order():
    Ft = np.array([-1.0, 2.0, 5.0, 8.0])
    E = 10.0 ** np.arange(3, 10)
    base = gecko.TwoLevelSeta()
    designs = np.array([[getattr(base, f) for f in FIELDS]] * (len(E) + 2))
    designs[:len(E), 2] = designs[:len(E), 3] = E
    designs[len(E), 2:4] = 1e12
    designs[len(E) + 1, 2:4] = math.inf
    fn = batch_both_threads(designs, Ft)
    diff = fn[:len(E)] - fn[-1]
    for j in range(len(Ft)):
        assert abs(slope(E, diff[:, j]) + 1) <= 0.01
    E0 = 1e8
    sens = gecko.TwoLevelSeta(EA1=E0, EA2=E0).sensitivities(Ft)["dFn"]
    C = -E0 ** 2 * (sens[:, 2] + sens[:, 3])
    # EA = 1e12 against infinity: the difference is C/EA to rounding (O(1/EA^2) ~ 1e-25 here)
    np.testing.assert_allclose(fn[len(E)] - fn[-1], C / 1e12, rtol=0, atol=5e-14 * np.maximum(1, np.abs(fn[-1])).max())


def test_alpha2_to_zero_continuous():
    Ft = np.array([-1.0, 0.0, 2.0, 5.0, 8.0])
    s0 = gecko.TwoLevelSeta(alpha2=0.0)
    fn0 = converged(s0.critical_line(Ft))
    S = s0.sensitivities(Ft)["dFn"][:, 7]
    a2 = 10.0 ** -np.arange(1, 13)
    fn = np.array([converged(gecko.TwoLevelSeta(alpha2=a).critical_line(Ft)) for a in a2])
    for j in range(len(Ft)):
        assert abs(slope(a2[1:6], fn[1:6, j] - fn0[j]) - 1) <= 0.01
    # Fn(alpha2) = Fn(0) + S alpha2 + O(alpha2^2): second-order coefficient measured 0.71
    dev = np.abs(fn - fn0 - np.outer(a2, S))
    assert np.all(dev <= (1.0 * a2 ** 2)[:, None] + 3e-14 * np.maximum(1, np.abs(fn0)))


def test_uniform_seta_is_the_fiber_of_length_l1_plus_l2():
    Ft = np.array([-1.0, 0.0, 1.0, 4.0, 8.0, 9.9])
    for EA in (math.inf, 50.0):
        for l2 in (0.3, 1e-2, 1e-6):
            s = gecko.TwoLevelSeta(EI1=5, EI2=5, EA1=EA, EA2=EA, l2=l2, alpha2=0.0)
            f = gecko.SingleFiber(EI=5, EA=EA, l=1 + l2, alpha=s.alpha1)
            a, b = converged(s.critical_line(Ft)), converged(f.critical_line(Ft))
            assert np.all(np.abs(a - b) <= 1e-12 * np.maximum(1, np.abs(b))), (EA, l2, a - b)


@pytest.mark.parametrize("EI2", [5.0, 2.0, 0.5])
def test_l2_to_zero_tends_to_the_single_fiber(EI2):
    Ft = np.array([-1.0, 0.0, 1.0, 2.0, 4.0])
    f = gecko.SingleFiber(EI=5, EA=math.inf, l=1, alpha=math.pi / 6, w=EI2 / 5)
    fib = converged(f.critical_line(Ft))
    l2 = 10.0 ** -np.arange(1, 11)
    fn = np.array([converged(gecko.TwoLevelSeta(EI1=5, EI2=EI2, EA1=math.inf, EA2=math.inf, l2=x,
                                                alpha2=0.0).critical_line(Ft)) for x in l2])
    for j in range(len(Ft)):
        assert abs(slope(l2[2:8], fn[2:8, j] - fib[j]) - 1) <= 0.01
    S = gecko.TwoLevelSeta(EI1=5, EI2=EI2, EA1=math.inf, EA2=math.inf, l2=1e-10,
                           alpha2=0.0).sensitivities(Ft)["dFn"][:, 5]
    dev = np.abs(fn - fib - np.outer(l2, S))
    # second-order coefficient measured <= 31; then the solvers' Newton tolerance
    assert np.all(dev <= (60 * l2 ** 2)[:, None] + 1e-12 * np.maximum(1, np.abs(fib)))
