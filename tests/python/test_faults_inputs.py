"""Fault injection at the Python API: inputs that a conversion would silently reinterpret (a table
of the wrong width, complex numbers, None, dates, objects, masked arrays) and tolerances or
iteration counts out of range are refused with an error naming the argument and, for one bad
element, its index in the caller's shape."""
import datetime
import math

import numpy as np
import pytest

import gecko
from gecko import _vectorize, elliptic, friction, seta

BAD_ELEMENTS = [
    ([0.1, 0.2 + 1j], TypeError, r"complex numbers are not allowed \(at index 1\)"),
    ([0.1, None], TypeError, r"None \(NoneType\) is not allowed \(at index 1\)"),
    ([[0.1, 0.2], [0.3, datetime.date(2020, 1, 1)]], TypeError, r"\(date\) is not allowed \(at index \(1, 1\)\)"),
    ([0.1, "0.2"], TypeError, r"text|is not allowed"),
    (np.array(["2020-01-01"], dtype="datetime64[D]"), TypeError, r"dates and durations"),
    (np.array([1, 2], dtype="timedelta64[s]"), TypeError, r"dates and durations"),
    (np.array([0.1, object()], dtype=object), TypeError, r"\(object\) is not allowed \(at index 1\)"),
    (np.ma.masked_array([0.1, 0.2], mask=[0, 1]), ValueError, r"a masked array is not accepted"),
    (None, TypeError, r"= None is not allowed"),
    (0.3 + 0j, TypeError, r"complex numbers"),
]


@pytest.mark.parametrize("value, exc, why", BAD_ELEMENTS)
def test_the_one_checker(value, exc, why):
    with pytest.raises(exc, match=r"^m: .*" + why if value is not None else "m = None"):
        _vectorize.real_array(value, "m")


@pytest.mark.parametrize("value, exc, why", BAD_ELEMENTS)
@pytest.mark.parametrize("call, name", [
    (lambda v: elliptic.ellint_f(0.3, v), "m"),
    (lambda v: elliptic.carlson_rf(1.0, v, 2.0), "y"),
    (lambda v: seta.kendall_fn(v, 50.0, 1.0), "Ft"),
    (lambda v: gecko.TwoLevelSeta().critical_line(v), "Ft"),
    (lambda v: gecko.TwoLevelSeta().contact_state(v, 0.0), "Fn"),
    (lambda v: gecko.TwoLevelSeta().small_deformation_fn(v), "Ft"),
    (lambda v: friction.viscoelastic_detachment(v, 1.0, 1.0, 0.5), "V"),
    (lambda v: friction.parabolic_beam_compliance(1.0, v), "EI"),
])
def test_every_wrapper_names_the_argument_and_element(call, name, value, exc, why):
    if value is None and name == "Ft":  # critical_line(None) is the traced line, a documented call
        return
    with pytest.raises(exc) as ei:
        call(value)
    assert str(ei.value).startswith(f"{name}: ") or str(ei.value).startswith(f"{name} = None"), str(ei.value)


def test_real_inputs_still_pass_and_agree():
    assert elliptic.ellint_k(np.array([0.5], dtype=np.float32))[0] == pytest.approx(elliptic.ellint_k(0.5), rel=1e-7)
    assert elliptic.ellint_k(np.array([0, 0], dtype=np.int64)).tolist() == [math.pi / 2] * 2
    assert elliptic.ellint_k(np.array([0.5, 0.2], dtype=object))[1] == elliptic.ellint_k(0.2)


@pytest.mark.parametrize("width", [6, 8, 10, 18])
def test_critical_line_batch_refuses_a_table_of_another_width(width):
    with pytest.raises(ValueError, match=rf"designs: need a table of width 9 .* \(width {width}\)"):
        seta.critical_line_batch(np.ones((3, width)), [0.0, 0.5])


def test_critical_line_batch_one_design_and_bad_elements():
    ref = gecko.TwoLevelSeta()
    one = seta.critical_line_batch(ref._params(), [0.0])
    assert one.Fn.shape == (1, 1) and one.Fn[0, 0] == ref.critical_line([0.0]).Fn[0]
    d = np.tile(ref._params(), (2, 1)).astype(complex)
    d[1, 3] += 1j
    with pytest.raises(TypeError, match=r"designs: complex numbers are not allowed \(at index \(1, 3\)\)"):
        seta.critical_line_batch(d, [0.0])
    with pytest.raises(ValueError, match="threads = 0 is out of range"):
        seta.critical_line_batch(ref._params(), [0.0], threads=0)


@pytest.mark.parametrize("tol", [0, -1e-12, math.nan, math.inf, "1e-9", True])
def test_tolerances_out_of_range_are_refused_everywhere(tol):
    s = gecko.TwoLevelSeta()
    calls = [lambda: s.critical_line([0.0], tolerance=tol), lambda: s.solve(0.0, tolerance=tol),
             lambda: gecko.SingleFiber().critical_line([0.0], tolerance=tol),
             lambda: seta.critical_line_batch(s._params(), [0.0], tolerance=tol)]
    for c in calls:
        with pytest.raises(ValueError, match="tolerance = .* is out of range: need a finite number > 0"):
            c()


@pytest.mark.parametrize("n", [0, -3, 2.5, True, None])
def test_iteration_counts_out_of_range_are_refused(n):
    with pytest.raises(ValueError, match="max_iterations = .* is out of range"):
        gecko.TwoLevelSeta().solve(0.0, max_iterations=n)
    V = np.logspace(-6, -3, 8)
    with pytest.raises(ValueError, match="max_iterations = .* is out of range"):
        friction.fit_steady_sliding(V, np.ones(8), np.ones(8), max_iterations=n)


@pytest.mark.parametrize("kw, name", [({"tol": 0.0}, "tol"), ({"tol": math.nan}, "tol"),
                                      ({"feasibility_tol": -1.0}, "feasibility_tol"),
                                      ({"maxiter": 0}, "maxiter")])
def test_optimiser_options_out_of_range_are_refused(kw, name):
    pytest.importorskip("scipy")
    from gecko.optimize import optimize_seta
    with pytest.raises(ValueError, match=rf"{name} = "):
        optimize_seta("max_pull_off", {"alpha2": (0.1, 0.5)}, starts=1, **kw)


def test_friction_matrices_and_paths_refuse_complex():
    with pytest.raises(TypeError, match=r"C: complex numbers are not allowed \(at index \(0, 0\)\)"):
        friction.rigidity(np.eye(2) * (1 + 1j))
    with pytest.raises(TypeError, match=r"K: complex"):
        friction.force_trace(np.eye(2) + 0j * np.eye(2) + 1j)
    with pytest.raises(TypeError, match=r"times: None \(NoneType\) is not allowed \(at index 1\)"):
        friction.force_trace(times=[0.0, None])


@pytest.mark.parametrize("table, why", [
    ({"EI1": [1.0, 2.0 + 1j]}, r"designs\['EI1'\]: complex numbers are not allowed \(at index 1\)"),
    ({"EI1": [1.0, None]}, r"designs\['EI1'\]: None \(NoneType\) is not allowed \(at index 1\)"),
    ({"EI1": [1.0, "x"]}, r"designs\['EI1'\]: (text|'x' \(str\) is not allowed \(at index 1\))"),
    (np.full((2, 9), 1.0 + 1j), r"designs: complex numbers are not allowed \(at index \(0, 0\)\)"),
])
def test_sweep_refuses_design_tables_a_conversion_would_reinterpret(table, why):
    pytest.importorskip("pandas")
    with pytest.raises(TypeError, match=why):
        gecko.sweep(table, outputs=["ft_max"], progress=False)
    if isinstance(table, dict):
        import pandas as pd
        df = pd.DataFrame(table)
        if df["EI1"].dtype == np.float64:  # pandas itself made None a NaN: refused as an invalid row
            with pytest.raises(ValueError, match="designs: row 1 is invalid"):
                gecko.sweep(df, outputs=["ft_max"], progress=False)
        else:
            with pytest.raises(TypeError, match=why):
                gecko.sweep(df, outputs=["ft_max"], progress=False)


def test_refused_types_are_value_errors_too(tmp_path):
    with pytest.raises(ValueError, match="Ft: complex"):
        seta.kendall_fn(1j, 50.0, 1.0)
    pytest.importorskip("pandas")
    from gecko.scene import SceneError, run_scene
    table = tmp_path / "designs.csv"
    table.write_text("EI1,EI2\n5,2\nfive,2\n")
    scene = {"sweep": {"designs": "table", "table": str(table), "outputs": ["ft_max"]}}
    with pytest.raises(SceneError, match=r"sweep: designs\['EI1'\]: '5' \(str\) is not allowed \(at index 0\)"):
        run_scene(scene, progress=False)


@pytest.mark.parametrize("call, where", [
    (lambda: seta.kendall_fn([[1.0, 2.0], [3.0, 1e3]], 50.0, 1.0), r"Ft = 1000 .*\(at index \(1, 1\)\)$"),
    (lambda: seta.rivlin_fn([1.0, 2.0, -3.0], 1.0), r"Ft = -3 .*\(at index 2\)$"),
    (lambda: friction.viscoelastic_detachment([1.0, 2.0], [[1.0], [-1.0]], 1.0, 0.5), r"\(at index \(1, 0\)\)$"),
    (lambda: friction.eyring_detachment([1.0, -2.0], 1.0, 1.0), r"\(at index 1\)$"),
    (lambda: friction.detachment_stretch(1.0, 1.0, [1.0, 1.0, -1.0]), r"\(at index 2\)$"),
    (lambda: friction.resonant_frequency([1.0, 0.0], 1.0, 1.0, 1.0), r"\(at index 1\)$"),
])
def test_the_elementwise_laws_name_the_bad_elements_index(call, where):
    # the same element loop as every other elementwise call: the index in the caller's broadcast shape
    with pytest.raises(ValueError, match=where):
        call()
