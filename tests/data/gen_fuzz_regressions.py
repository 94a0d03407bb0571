#!/usr/bin/env python3
"""mpmath references for tests/elliptic/fuzz_regressions.cpp: the inputs the fuzzers
(fuzz/fuzz_carlson.cpp, fuzz/fuzz_legendre.cpp) found, exact as hex floats.

    python3 tests/data/gen_fuzz_regressions.py > tests/data/fuzz_regressions.csv

Columns: id, function, the arguments (hex), the reference (25 significant digits) and, for the
R_J principal values, the cancellation factor sum|terms| / |sum| of DLMF 19.20.14 (the test's
bound is 8 eps times it, as in tests/elliptic/carlson_rj.cpp); 1 elsewhere. ``status`` is
``fixed`` (must pass) or ``open`` (known finding, checked as [!mayfail]).
The principal value is evaluated with DLMF 19.20.14 itself at 200 digits (mpmath's elliprj
returns the complex value for p < 0, not the Cauchy principal value).
"""
import mpmath as mp

mp.mp.dps = 200

H = float.fromhex

# (id, status, function, args)
CASES = [
    # R_C: (sqrt(x) - sqrt(y) + sqrt(x - y)) / sqrt(y) overflowed to inf for x/y > DBL_MAX
    ("rc_ratio_overflow", "fixed", "rc", ["0x1.7e43c8800759cp+996", "0x0.0000000000001p-1022"]),
    # R_C principal value: sqrt(x / (x - y)) underflowed to 0 for subnormal x
    ("rc_pv_subnormal_x", "fixed", "rc", ["0x0.0000000000001p-1022", "-0x1.921fb54442d1cp+5"]),
    # R_C principal value: x - y overflowed to inf (NaN result)
    ("rc_pv_difference_overflow", "fixed", "rc", ["0x1.ffffffffffff9p+1023", "-0x1.7e43c88007599p+996"]),
    # R_D: A sqrt(A) overflowed / sum terms went subnormal, result just above DBL_MIN (3% off)
    ("rd_result_near_dbl_min", "fixed", "rd", ["0x1.858eb79a20bb1p+67", "0x1.858eb79a20bb6p+67", "0x1.ffff55066c999p+686"]),
    # R_D: A sqrt(A) underflowed for small arguments, result near DBL_MAX (18 eps)
    ("rd_small_arguments", "fixed", "rd", ["0x1p-1022", "0x1p-1000", "0x1.b4b4b4b4b4b4bp-676"]),
    # R_D: huge and small arguments together (the rescaling must not flush the small ones)
    ("rd_wide_spread", "fixed", "rd", ["0x1.2828282828282p+814", "0x1.8282828282828p-381", "0x1.82828286ep-381"]),
    # E(phi|m), m > 1 near the edge arcsin(1/sqrt m): 1 - m s^2 inconsistent with s and c
    ("e_edge_m_1.008", "fixed", "e", ["0x1.7b4967a67c30dp+0", "0x1.020c5046p+0"]),
    ("e_edge_m_1+1e-7", "fixed", "e", ["0x1.920afbd8648bap+0", "0x1.000001ad7f29bp+0"]),
    ("e_edge_m_1+1e-5", "fixed", "e", ["0x1.9150773a66ff0p+0", "0x1.0000a7c5ac472p+0"]),
    ("e_edge_m_1.001", "fixed", "e", ["0x1.8a07f7dabbf07p+0", "0x1.004189374bc6ap+0"]),
    # E(phi|m), phi beyond the edge by rounding (accepted): clamping Delta^2 alone gave E > 1
    ("e_beyond_edge_clamped", "fixed", "e", ["0x1.921fb49aeed45p+0", "0x1.0000000000007p+0"]),
    # ---- findings F2-F5 (fuzz/README.md), fixed by the extreme-argument work ----
    # F2: rescaling by the largest argument flushed two small ones to zero -> NaN
    ("F2_rf_two_flushed", "fixed", "rf", [(1e-300).hex(), (1e-310).hex(), (1e308).hex()]),
    ("F2_rf_zero_and_flushed", "fixed", "rf", ["0x0p+0", (1e-300).hex(), (1e308).hex()]),
    ("F2_rf_subnormal_and_max", "fixed", "rf", ["0x0.0000000000001p-1022", "0x1.8p+0", "0x1.fffffffffffffp+1023"]),
    ("F2_rd_flushed", "fixed", "rd", [(1e-300).hex(), "0x0.0p+0", (1e308).hex()]),
    ("F2_rd_small_last", "fixed", "rd", [(1e300).hex(), (1e-310).hex(), (1e-300).hex()]),
    # F2 (R_J): arguments near the bottom of the exponent range, intermediates underflow (2150 eps)
    ("F2_rj_low_arguments", "fixed", "rj", ["0x1.858eb79a20baap+5", "0x0p+0", "0x1.3010000050a44p-928", "0x1p-1000"]),
    # F2 (R_J): x, y, z all flushed by the rescaling to |p|: ilogb(0) and -INT_MIN (UB)
    ("F2_rj_all_flushed", "fixed", "rj", ["0x1p-1070", "0x1p-1069", "0x1p-1068", "0x1p+1000"]),
    ("F2_rj_p_subnormal", "fixed", "rj", ["0x1.8p+1000", "0x1p-3", "0x1.4p+2", "0x0.0000000000003p-1022"]),
    # (found while fixing F2) spread step with a result near DBL_MAX: R_J(x', ...)/4 overflowed
    ("F2_rj_spread_result_near_max", "fixed", "rj", ["0x0.0000000000001p-1022", "0x0p+0", "0x1.f000000090009p-592", "0x1.0139f841656p-719"]),
    # F3: R_J's large-p route overflowed p / z for p/z > 2^1023 -> 0
    ("F3_rj_large_p", "fixed", "rj", ["0x1p-1000", "0x1.56e1fc2f8f359p-997", "0x1.ffffffffffffap-1001", "0x1p+63"]),
    ("F3_rj_p_max", "fixed", "rj", ["0x1p-3", "0x1p-2", "0x1p-1", "0x1.fffffffffffffp+1023"]),
    # F4: principal value with |p| far above x, y, z: inf * 0 -> NaN
    ("F4_rj_pv_huge_q", "fixed", "rj", ["0x0p+0", "0x1.46b9c347764abp+5", "0x1.858eb79a20bb2p+5", "-0x1p+1009"]),
    ("F4_rj_pv_tiny_xyz", "fixed", "rj", ["0x1p-1000", "0x1p-999", "0x1p-998", "-0x1p+1000"]),
    # F4b: principal value, x y (or p' q) underflows: the R_C term was lost
    ("F4b_rj_pv_xy_underflow", "fixed", "rj", ["0x1.9p+6", "0x1.fffffffffffffp+1023", "0x1.002005800007cp+0", "-0x1.921fb54442d2p+5"]),
    ("F4b_rj_pv_pq_underflow", "fixed", "rj", ["0x1.2323232323232p-471", "0x1.2323c83c3e3bp-471", "0x1.858eb79a20ba8p+5", "-0x1.3efffffffffffp-577"]),
    # (found while fixing F4) principal value whose terms overflow before the division by z + q
    ("F4_rj_pv_terms_overflow", "fixed", "rj", ["0x1p+619", "0x0.00000e301e313p-1022", "0x1.e3e3e3e3e302p-591", "-0x0.0000000000008p-1022"]),
    # (found while fixing F2) R_J spread step with a subnormal p: p/p' lost its bits (245 eps)
    ("F2_rj_spread_subnormal_p", "fixed", "rj", ["0x1.ffffffffffff8p+1023", "0x1.bp-1012", "0x0.000001b0015ffp-1022", "0x0.000001b0015ffp-1022"]),
    # (found while fixing F4) principal value overflowing with terms of both signs: inf - inf = NaN
    ("F4_rj_pv_overflow_both_signs", "fixed", "rj", ["0x1.5b5b0c0000005p-829", "0x1.0000002301p-765", "0x0.000ff01020112p-1022", "-0x1p-831"]),
    # (found while fixing F4) principal value: z (x + q)/(z + q) underflowed in p' (1.8e5 eps)
    ("F4_rj_pv_pp_underflow", "fixed", "rj", ["0x1.0077p+619", "0x0.1000000e301e3p-1022", "0x1.56e1fc2f8f359p-997", "-0x0.0000000000001p-1022"]),
    ("F4_rj_pv_overflow_both_signs_z_1", "fixed", "rj", ["0x0.0000000000001p-1022", "0x1.a000000000004p+0", "0x0.064646464ab4cp-1022", "-0x0.0000000000008p-1022"]),
    ("F4_rj_pv_result_near_max", "fixed", "rj", ["0x1.858eb79a20bb6p+5", "0x1.f089210112911p-1021", "0x1p-1022", "-0x0.0000000000001p-1022"]),
    # (found while fixing F4) z + q overflowing: quartering all arguments flushed y -> domain error
    ("F4_rj_pv_zq_overflow_subnormal_y", "fixed", "rj", ["0x0.0000000000001p-1022", "0x0p+0", "0x1.fffffffffffffp+1023", "-0x1.7e43c8800759cp+996"]),
    # (found while fixing F4) p' rounded above z = DBL_MAX to inf
    ("F4_rj_pv_pp_rounds_to_inf", "fixed", "rj", ["0x1.fffffffffffffp+1023", "0x1.ffffffffffffap+1023", "0x1.fffffffffffffp+1023", "-0x1.7e43c8800759cp+996"]),
    # (found while fixing F4) all arguments subnormal: p' rounded to 0 -> domain error
    ("F4_rj_pv_all_subnormal", "fixed", "rj", ["0x0.0000000000001p-1022", "0x0.0000000000001p-1022", "0x0p+0", "-0x0.0000000000001p-1022"]),
    # R_J principal value at a near-zero of 19.20.14's sum (cancellation factor 8.9e15) whose value
    # lies beyond DBL_MAX: the bound (8 eps times the factor) exceeds the value, and the double
    # result (0) meets it without overflowing (the next double below p nearly doubles the value)
    ("rj_pv_cancellation_beyond_max", "fixed", "rj", ["0x1.49057e0109fffp-1016", "0x0.0000000000004p-1022", "0x0.0000000000001p-1022", "-0x0.0000000000002p-1022"]),
    # F5: |phi| > pi/2 and m -> -inf: the odd-quadrant tail overflowed (NaN) or its R_D underflowed
    ("F5_e_tail_overflow", "fixed", "e", ["0x1.858eb79a20bb5p+5", "-0x1.ffffffffffffep+1023"]),
    ("F5_e_tail_rd_underflow", "fixed", "e", ["0x1.1604020a080a4p+1", "-0x1p+698"]),
    ("F5_f_tail_overflow", "fixed", "f", ["0x1.858eb79a20bb5p+5", "-0x1.ffffffffffffep+1023"]),
    ("F5_f_tail_large", "fixed", "f", ["0x1.1604020a080a4p+1", "-0x1p+698"]),
    # carlson_rf_gradient rescaled with R_F's window: its partials (R_D, ~ A^(-3/2)) lost 18 eps
    ("rfg_dz_small_arguments", "fixed", "rfg_dz", ["0x1p-1022", "0x1p-1000", "0x1.b4b4b4b4b4b4bp-676"]),
    ("rfg_dx_large_arguments", "fixed", "rfg_dx", ["0x1.ffff55066c999p+682", "0x1.858eb79a20bb1p+63", "0x1.858eb79a20bb6p+63"]),
]


def rj_pv(x, y, z, p):
    x, y, z = sorted([x, y, z])
    q = -p
    zq = z + q
    pp = (z * (x + y + q) - x * y) / zq
    t1 = (pp - z) * mp.elliprj(x, y, z, pp)
    t2 = -3 * mp.elliprf(x, y, z)
    t3 = 3 * mp.sqrt(x * y * z / (x * y + pp * q)) * mp.elliprc(x * y + pp * q, pp * q) if x * y != 0 else mp.mpf(0)
    value = (t1 + t2 + t3) / zq
    return value, (abs(t1) + abs(t2) + abs(t3)) / abs(t1 + t2 + t3)


def reference(fn, args):
    a = [mp.mpf(H(s)) for s in args]
    if fn == "rf":
        return mp.elliprf(*a), 1
    if fn == "rd":
        return mp.elliprd(*a), 1
    if fn == "rc":
        x, y = a
        if y > 0:
            return mp.elliprc(x, y), 1
        # DLMF 19.2.20: R_C(x, y) = sqrt(x/(x - y)) R_C(x - y, -y)
        return mp.sqrt(x / (x - y)) * mp.elliprc(x - y, -y), 1
    if fn == "rj":
        if a[3] > 0:
            return mp.elliprj(*a), 1
        return rj_pv(*a)
    if fn == "e":
        return mp.ellipe(a[0], a[1]), 1
    if fn == "f":
        return mp.ellipf(a[0], a[1]), 1
    # partial derivatives of R_F (DLMF 19.18.1): dR_F/dz = -R_D(x, y, z)/6, dR_F/dx = -R_D(y, z, x)/6
    if fn == "rfg_dz":
        return -mp.elliprd(a[0], a[1], a[2]) / 6, 1
    if fn == "rfg_dx":
        return -mp.elliprd(a[1], a[2], a[0]) / 6, 1
    raise ValueError(fn)


def main():
    print("id,status,function,a0,a1,a2,a3,reference,cancellation")
    for cid, status, fn, args in CASES:
        value, cancel = reference(fn, args)
        value = mp.re(value)
        cols = args + ["0x0p+0"] * (4 - len(args))
        print(f"{cid},{status},{fn},{','.join(cols)},{mp.nstr(value, 25)},{mp.nstr(cancel, 6)}")


if __name__ == "__main__":
    main()
