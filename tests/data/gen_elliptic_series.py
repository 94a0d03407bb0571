#!/usr/bin/env python3
"""Exact Taylor coefficients of the Carlson series used by gecko/elliptic (DLMF 19.19.7).

    R_{-a}(b; z) = A^-a sum_N ((a)_N / (c)_N) T_N(b, Z),
    T_N(b, Z) = sum_{m_1 + ... + m_n = N} prod_j (b_j)_{m_j} / m_j! Z_j^{m_j},
    c = sum b_j, A = sum b_j z_j / c, Z_j = 1 - z_j / A.

R_F = R_{-1/2}(1/2, 1/2, 1/2): printed in Carlson's E2 = XY - Z^2, E3 = XYZ as
    (-1)^m (1/2)_{m+n} / (m! n! (4m + 6n + 1)) E2^m E3^n   (checked here against DLMF 19.19.7),
R_D = R_{-3/2}(1/2, 1/2, 3/2): printed in S = X + Y, P = XY (Z = -(X + Y)/3), with the sums
    C_N of absolute coefficients per degree (X, Y monomials) used by the stopping rule, and the
    C++ Estrin code pasted into gecko/elliptic/carlson_rd.hpp.

Run: python3 tests/data/gen_elliptic_series.py   (needs sympy)
"""
import sympy as sp
from sympy import Rational as R, factorial, rf

X, Y = sp.symbols("X Y")


def T_N(bs, Zs, N):
    """DLMF 19.19.7 T_N for weights bs at deviations Zs."""
    total = 0
    def rec(j, left, term):
        nonlocal total
        if j == len(bs) - 1:
            total += term * rf(bs[j], left) / factorial(left) * Zs[j] ** left
            return
        for m in range(left + 1):
            rec(j + 1, left - m, term * rf(bs[j], m) / factorial(m) * Zs[j] ** m)
    rec(0, N, sp.Integer(1))
    return sp.expand(total)


def rf_check(M=15):
    """R_F: the closed-form coefficients agree with DLMF 19.19.7 up to degree M."""
    Z = -(X + Y)
    E2, E3 = X * Y - Z ** 2, X * Y * Z
    for N in range(M + 1):
        series = rf(R(1, 2), N) / rf(R(3, 2), N) * T_N([R(1, 2)] * 3, [X, Y, Z], N)
        closed = sum((-1) ** m * rf(R(1, 2), m + n) / (factorial(m) * factorial(n) * (4 * m + 6 * n + 1))
                     * E2 ** m * E3 ** n
                     for m in range(N // 2 + 1) for n in range(N // 3 + 1) if 2 * m + 3 * n == N)
        assert sp.expand(series - closed) == 0, N
    print(f"R_F: closed-form coefficients verified to degree {M}")
    for n in range(6):
        row = [(-1) ** m * rf(R(1, 2), m + n) / (factorial(m) * factorial(n) * (4 * m + 6 * n + 1))
               for m in range(8) if 2 * m + 3 * n <= M]
        print(f"  E3^{n}:", ", ".join(str(c) for c in row))


def rd_series(M=11):
    Z = -(X + Y) / 3
    bs = [R(1, 2), R(1, 2), R(3, 2)]
    coef = {}
    for N in range(M + 2):
        term = sp.expand(rf(R(3, 2), N) / rf(R(5, 2), N) * T_N(bs, [X, Y, Z], N))
        C = sum(abs(c) for c in sp.Poly(term, X, Y).coeffs()) if term != 0 else 0
        cand = [(N - 2 * j, j) for j in range(N // 2 + 1)]
        syms = sp.symbols(f"c0:{len(cand)}")
        trial = sum(c * (X + Y) ** i * (X * Y) ** j for c, (i, j) in zip(syms, cand))
        sol = sp.solve(sp.Poly(sp.expand(trial - term), X, Y).coeffs(), syms, dict=True)
        sol = sol[0] if sol else {s: 0 for s in syms}
        coef[N] = {(i, j): sol.get(c, 0) for c, (i, j) in zip(syms, cand)}
        print(f"R_D degree {N}: C_N = {float(C):.6g}  ", {k: str(v) for k, v in coef[N].items() if v != 0})
    return coef


def lit(c):
    c = sp.Rational(c)
    return f"T({c.p})" if c.q == 1 else f"(T({c.p}) / {c.q})"


def estrin(coeffs, var, powers):
    n = max(coeffs) + 1
    cs = [coeffs.get(i, 0) for i in range(n)]
    level = []
    for k in range(0, n, 2):
        a, b = cs[k], (cs[k + 1] if k + 1 < n else 0)
        if b == 0:
            level.append(lit(a) if a != 0 else None)
        elif a == 0:
            level.append(f"{var} * {lit(b)}")
        else:
            level.append(f"({lit(a)} + {var} * {lit(b)})")
    p = 0
    while len(level) > 1:
        nxt = []
        for k in range(0, len(level), 2):
            a, b = level[k], (level[k + 1] if k + 1 < len(level) else None)
            if b is None:
                nxt.append(a)
            elif a is None:
                nxt.append(f"{powers[p]} * {b}")
            else:
                nxt.append(f"({a} + {powers[p]} * {b})")
        level, p = nxt, p + 1
    return level[0]


if __name__ == "__main__":
    rf_check()
    M = 11
    coef = rd_series(M)
    groups = {}
    for N in range(2, M + 1):
        for (i, j), c in coef[N].items():
            if c != 0:
                groups.setdefault(j, {})[i] = c
    print("\nC++ for carlson_rd_series:")
    for j in sorted(groups):
        print(f"  const T q{j} = {estrin(groups[j], 'S', ['S2', 'S4', 'S8'])};")
