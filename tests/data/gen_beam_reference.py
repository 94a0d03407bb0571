#!/usr/bin/env python3
"""Reference values for the curved-beam compliance (docs/theory/frictional_adhesion.md, Appendix 1 of paper 000).

Independent of the C++ code: the Castigliano integrals are evaluated here with mpmath at 30
significant digits by mpmath's tanh-sinh quadrature after x = L u^2 (with its own error estimate
checked below 1e-34), and the Appendix-1 closed form is evaluated at
the same precision, so a test can check both the closed form and the C++ quadrature.

Conventions (see include/gecko/beam/castigliano.hpp): tip at x = 0, clamp at x = L, moment
M = -(z - z(0)) F_par - x F_perp, axial force N = F_par t_x - F_perp t_z with t the unit tangent.
Compliance with L = EI = EA = 1:
    bending  B_ij = int_0^L m_i m_j ds,            m = (z - z(0), x)
    axial    A_ij = int_0^L a_i a_j / sqrt(1+z'^2) dx, a = (1, -z')

Output: beam_reference.csv with columns  name,quantity,value  (30 significant digits).
Run:  python3 tests/data/gen_beam_reference.py  (writes next to this script)
"""
import csv
import pathlib

import mpmath as mp

mp.mp.dps = 45  # work with 15 guard digits, print 30


def compliance(z, dz, L):
    z0 = z(mp.mpf(0))

    def ds(x):
        return mp.sqrt(1 + dz(x) ** 2)

    def q(f):
        # x = L u^2 makes every integrand here smooth in u (the x^-1/2 of ds/dx cancels against
        # dx = 2 L u du); mpmath's own tanh-sinh then converges far below the printed digits.
        val, err = mp.quad(lambda u: f(L * u * u) * 2 * L * u, [0, 0.5, 1], error=True,
                           maxdegree=12)
        assert err < mp.mpf(10) ** -34, (val, err)
        return val

    B11 = q(lambda x: (z(x) - z0) ** 2 * ds(x))
    B12 = q(lambda x: (z(x) - z0) * x * ds(x))
    B22 = q(lambda x: x * x * ds(x))
    A11 = q(lambda x: 1 / ds(x))
    A12 = q(lambda x: -dz(x) / ds(x))
    A22 = q(lambda x: dz(x) ** 2 / ds(x))
    return (B11, B12, B22), (A11, A12, A22)


def main():
    rows = []
    s17 = mp.sqrt(17)
    lg = mp.log(4 + s17)
    # Appendix 1 closed form, with the sign of a11 as corrected in docs/theory/frictional_adhesion.md.
    a11 = 33 * s17 / 512 - lg / 2048
    a12 = (391 * s17 + 1) / 3840
    a22 = 2077 * s17 / 12288 + lg / 16384
    rows += [("parabola_closed_form", "a11", a11), ("parabola_closed_form", "a12", a12),
             ("parabola_closed_form", "a22", a22)]
    # C = (L^3 / 2EI) a  ->  K = (2EI / L^3) a^-1; normalised so that K_par_par = 5.
    det = a11 * a22 - a12 ** 2
    rows += [("parabola_closed_form", "K11_unit", 2 * a22 / det),
             ("parabola_closed_form", "K12_unit", -2 * a12 / det),
             ("parabola_closed_form", "K22_unit", 2 * a11 / det),
             ("parabola_closed_form", "K12_norm5", -5 * a12 / a22),
             ("parabola_closed_form", "K22_norm5", 5 * a11 / a22)]

    shapes = {
        # Appendix 1 parabola z = sqrt(L x)/2, L = 1: ds/dx ~ x^-1/2 at the tip.
        "parabola": (lambda x: mp.sqrt(x) / 2, lambda x: 1 / (4 * mp.sqrt(x)), mp.mpf(1)),
        # Quarter circle of radius 1, vertical tangent at the tip: z = sqrt(2x - x^2).
        "quarter_circle": (lambda x: mp.sqrt(2 * x - x * x),
                           lambda x: (1 - x) / mp.sqrt(2 * x - x * x), mp.mpf(1)),
        # A smooth shape with z(0) != 0 and no singularity: z = 0.3 + x/2 + x^3, L = 1.
        "cubic": (lambda x: mp.mpf("0.3") + x / 2 + x ** 3, lambda x: mp.mpf(1) / 2 + 3 * x * x,
                  mp.mpf(1)),
    }
    for name, (z, dz, L) in shapes.items():
        (B11, B12, B22), (A11, A12, A22) = compliance(z, dz, L)
        rows += [(name, "B11", B11), (name, "B12", B12), (name, "B22", B22),
                 (name, "A11", A11), (name, "A12", A12), (name, "A22", A22)]

    out = pathlib.Path(__file__).with_name("beam_reference.csv")
    with out.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "quantity", "value"])
        for name, qty, val in rows:
            w.writerow([name, qty, mp.nstr(val, 30, min_fixed=-1, max_fixed=-1)])
    print(f"wrote {out} ({len(rows)} rows)")


if __name__ == "__main__":
    main()
