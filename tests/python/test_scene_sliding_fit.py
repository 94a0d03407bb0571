"""Scenes with a detachment law as an expression, and the sliding_fit model (CSV data, fit table,
residuals, plot); the fit must agree with gecko.fit_steady_sliding called directly."""
from pathlib import Path

import numpy as np
import pytest

import gecko
from gecko.scene import SceneError, load_scene, run_scene
from gecko.scene import expr

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "more" / "friction_fit_measured_data.toml"
LAW = {"G": "G0 * (1 + (V/V0)**n)", "parameters": {"G0": 3e-14, "V0": 1e-4, "n": 0.45}}


def write_csv(path, rows, head="V,F_par,F_perp"):
    path.write_text(head + "\n" + "\n".join(",".join(map(repr, r)) for r in rows) + "\n")
    return path


def synthetic(tmp_path, sigma=True, n=25, seed=3):
    V = np.logspace(-6, -2, n)
    r = gecko.steady_sliding(V, gecko.FIG6_VISCOELASTIC)
    rng = np.random.default_rng(seed)
    Fp = r.F_par + 5e-4 * rng.standard_normal(n)
    Fq = r.F_perp + 5e-4 * rng.standard_normal(n)
    rows = [(float(a), float(b), float(c)) + ((5e-4, 5e-4) if sigma else ()) for a, b, c in zip(V, Fp, Fq)]
    head = "V,F_par,F_perp" + (",sigma_par,sigma_perp" if sigma else "")
    return write_csv(tmp_path / "d.csv", rows, head), V, Fp, Fq


def scene(data, law=None, fit=True, **params):
    p = {"data": str(data), **params}
    if law is not None:
        p["law"] = law
    return {"title": "t", "study": [{"name": "s", "model": "sliding_fit", "parameters": p,
                                     "outputs": {"fit": fit, "csv": True}}],
            "plot": [{"name": "p", "kind": "sliding_fit"}]}


def test_expression_law_matches_builtin_in_steady_sliding():
    sc = {"title": "t", "study": [
        {"name": "a", "model": "steady_sliding", "outputs": {"forces": {"V": [1e-6, 1e-4, 1e-2]}}},
        {"name": "b", "model": "steady_sliding", "parameters": {"law": LAW},
         "outputs": {"forces": {"V": [1e-6, 1e-4, 1e-2]}}}]}
    r = run_scene(sc, progress=False)
    a, b = r.data["a"][0]["forces"], r.data["b"][0]["forces"]
    np.testing.assert_allclose(b["F_par"], a["F_par"], rtol=1e-14)
    np.testing.assert_allclose(b["F_perp"], a["F_perp"], rtol=1e-14)


def test_fit_scene_agrees_with_the_direct_fit(tmp_path):
    path, V, Fp, Fq = synthetic(tmp_path)
    r = run_scene(scene(path, LAW), tmp_path / "out", progress=False)
    f = r.data["s"][0]["fit"]["result"]
    guess = gecko.FIG6_VISCOELASTIC.replace(law=gecko.ParametricLaw(
        lambda V, G0, V0, n: G0 * (1 + (V / V0) ** n), {"G0": 3e-14, "V0": 1e-4, "n": 0.45}))
    direct = gecko.fit_steady_sliding(V, Fp, Fq, guess, sigma=(5e-4, 5e-4), profile=True)
    assert f.status == direct.status == "converged"
    assert f.names == direct.names == ("G0", "V0", "n", "f_perp1")
    np.testing.assert_allclose(f.values, direct.values, rtol=1e-9)
    np.testing.assert_allclose(f.standard_errors, direct.standard_errors, rtol=1e-7)
    assert f.sigma_known
    # the table: one row per parameter, with value, error, interval and status
    text = (tmp_path / "out" / "s.fit.csv").read_text().splitlines()
    assert text[0].startswith("design,parameter,value,standard_error,profile_lower,profile_upper,status")
    assert [row.split(",")[1] for row in text[1:]] == list(f.names)
    assert all(",converged," in row for row in text[1:])
    res = np.loadtxt(tmp_path / "out" / "s.fit_residuals.csv", delimiter=",", skiprows=1)
    assert res.shape == (25, 6)
    assert np.sqrt(np.mean(res[:, 4] ** 2)) == pytest.approx(5e-4, rel=0.4)  # residuals ~ the noise
    assert (tmp_path / "out" / "p.png").is_file()
    roles = {c.role for c in r.curves["p"]}
    assert roles == {"data_par", "data_perp", "fit_par", "fit_perp", "res_par", "res_perp"}


def test_builtin_law_fit_without_sigma(tmp_path):
    path, V, Fp, Fq = synthetic(tmp_path, sigma=False)
    r = run_scene(scene(path, None, {"fit_f_par1": "auto", "profile": False}, preset="plastic"),
                  progress=False)
    f = r.data["s"][0]["fit"]["result"]
    direct = gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC)
    assert f.status == direct.status
    assert "f_par1" in f.names and not f.sigma_known
    np.testing.assert_allclose(f.values, direct.values, rtol=1e-9)


def test_the_example_recovers_the_truth():
    r = run_scene(EXAMPLE, progress=False)
    for study in ("builtin", "expression"):
        f = r.data[study][0]["fit"]["result"]
        assert f.status == "converged"
        true = np.array([3e-14, 1e-4, 0.45, 2e-7])
        assert np.all(np.abs(f.values - true) <= 3 * f.standard_errors), (study, f.values)
        assert np.all((f.profile_lower < f.values) & (f.values < f.profile_upper))


@pytest.mark.parametrize("law,key,match", [
    ("plastic", "law", "'plastic' is not allowed"),
    ({"G": "G0 * V"}, "law.parameters", "need a table of the law's parameters"),
    ({"G": "__import__('os').system('x')", "parameters": {"a": 1.0}}, "law.G", "not allowed"),
    ({"G": "G0.real * V", "parameters": {"G0": 1.0}}, "law.G", "not allowed"),
    ({"G": "G0 * (1 + (V/V0)**n)", "parameters": {"G0": 1e-14, "V0": 1e-4}}, "law.parameters", "'n' without a value"),
    ({"G": "G0 * 2", "parameters": {"G0": 1e-14}}, "law.G", "does not depend on the velocity V"),
    ({"G": "G0 * V", "parameters": {"G0": 1e-14, "x": 1.0}}, "law.parameters.x", "does not appear"),
    ({"G": "G0 * V", "parameters": {"G0": "big"}}, "law.parameters.G0", "need a finite number"),
    ({"G": "G0 * V", "parameters": {"G0": {"start": -1.0, "positive": True}}}, "law.parameters.G0.start", "start > 0"),
    ({"G": "G0 * V", "parameters": {"G0": {"value": 1.0}}}, "law.parameters.G0.value", "unknown key"),
    ({"G": "G0 * log(V - 1)", "parameters": {"G0": 1.0}}, "law.G", "not finite at its start values"),
    ({"G": "G0 * V", "bounds": 1, "parameters": {"G0": 1.0}}, "law.bounds", "unknown key"),
    ({"G": "G0 * V", "parameters": {"G0": {"start": 1.0, "bounds": [2, 1]}}}, "law.parameters.G0.bounds",
     "need lower < upper"),
    ({"G": "G0 * V", "parameters": {"G0": {"start": 1.0, "bounds": [0]}}}, "law.parameters.G0.bounds",
     r"need \[lower, upper\]"),
    ({"G": "G0 * V", "parameters": {"G0": {"start": 3.0, "bounds": [0, 2]}}}, "law.parameters.G0.start",
     "strictly inside the bounds"),
])
def test_bad_law_names_the_field(tmp_path, law, key, match):
    path, *_ = synthetic(tmp_path)
    with pytest.raises(SceneError, match=match) as e:
        load_scene(scene(path, law))
    assert f"study[0].parameters.{key}" in str(e.value)


@pytest.mark.parametrize("text,match", [
    ("V,F_par\n1,2\n", "missing column 'F_perp'"),
    ("V,F_par,F_perp,F\n1,2,3,4\n", "unknown column 'F'"),
    ("V,F_par,F_perp\n1e-6,0.03,x\n1e-5,0.03,0.01\n1e-4,0.04,0.0\n", r"row 2, column F_perp: 'x' is not a number"),
    ("V,F_par,F_perp\n-1e-6,0.03,0.01\n1e-5,0.03,0.01\n1e-4,0.04,0.0\n", r"row 2, column V: -1e-06 is out of range"),
    ("V,F_par,F_perp,sigma_par\n1e-6,0.03,0.01,0\n", "column sigma_par: 0.0 is out of range"),
    ("V,F_par,F_perp\n1e-6,0.03,nan\n", "column F_perp: nan is out of range"),
    ("V,F_par,F_perp\n1e-6,0.03\n", "row 2: 2 values for 3 columns"),
    ("V,F_par,F_perp\n1e-6,0.03,0.01\n", "1 data rows; need at least 3"),
    ("", "empty"),
])
def test_bad_csv_names_the_field_row_and_column(tmp_path, text, match):
    (tmp_path / "bad.csv").write_text(text)
    with pytest.raises(SceneError, match=match) as e:
        load_scene(scene(tmp_path / "bad.csv", LAW))
    assert "study[0].parameters.data" in str(e.value)


def test_missing_csv_and_bad_fit_options(tmp_path):
    with pytest.raises(SceneError, match="cannot read") as e:
        load_scene(scene(tmp_path / "nope.csv", LAW))
    assert "parameters.data" in str(e.value)
    path, *_ = synthetic(tmp_path)
    with pytest.raises(SceneError, match="need true, false or \"auto\""):
        load_scene(scene(path, LAW, {"fit_f_par1": "yes"}))
    with pytest.raises(SceneError, match="0 < level < 1") as e:
        load_scene(scene(path, LAW, {"profile_level": 1.5}))
    assert "outputs.fit.profile_level" in str(e.value)


def test_relative_csv_path_is_relative_to_the_scene(tmp_path):
    synthetic(tmp_path)
    (tmp_path / "s.toml").write_text('title = "t"\n[[study]]\nname = "s"\nmodel = "sliding_fit"\n'
                                     'parameters = { data = "d.csv" }\noutputs = { fit = true }\n')
    sc = load_scene(tmp_path / "s.toml")
    assert sc.studies[0].points[0].values["data"].V.size == 25


def test_array_expressions_are_safe_and_vectorised():
    V = np.array([0.0, 1e-4, 1e-2])
    g = expr.evaluate_array("G0 * asinh(V / V0)", {"V": V, "G0": 2.0, "V0": 1e-4})
    np.testing.assert_allclose(g, 2.0 * np.arcsinh(V / 1e-4), rtol=1e-15)
    for bad in ("().__class__", "open('x')", "[V]", "V if V else 1", "lambda: 1", "G0[0]"):
        with pytest.raises(SceneError):
            expr.array_names(bad, "k")
    # the scalar expressions keep their functions (asinh is for arrays only)
    with pytest.raises(SceneError, match="not allowed"):
        expr.names_in("asinh(1)", "k")


def test_bounded_expression_law_in_a_fit(tmp_path):
    path, V, Fp, Fq = synthetic(tmp_path)
    law = {"G": "G0 * (1 + (V/V0)**n)",
           "parameters": {"G0": 3e-14, "V0": {"start": 1e-4, "bounds": [1e-6, 1e-2]},
                          "n": {"start": 0.45, "bounds": [0, 2]}}}
    r = run_scene(scene(path, law), progress=False)
    f = r.data["s"][0]["fit"]["result"]
    free = run_scene(scene(path, LAW), progress=False).data["s"][0]["fit"]["result"]
    assert f.status == free.status == "converged"
    np.testing.assert_allclose(f.values, free.values, rtol=1e-6)
    np.testing.assert_allclose(f.standard_errors, free.standard_errors, rtol=1e-3)
    assert f.model.law.bounds == {"V0": (1e-6, 1e-2), "n": (0.0, 2.0)}
