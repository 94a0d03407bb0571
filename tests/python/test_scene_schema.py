"""gecko.scene: the schema — sweeps, expressions, and one clear error for every bad scene."""
import math
import warnings
from pathlib import Path

import pytest

from gecko.scene import SceneError, load_scene, validate_scene, figure_scenes

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def seta_scene(**study):
    s = {"model": "two_level_seta"}
    s.update(study)
    return {"study": [s]}


def test_packaged_figures_are_the_examples():
    packaged = {p.name: p.read_text(encoding="utf-8") for p in figure_scenes()}
    in_repo = {p.name: p.read_text(encoding="utf-8") for p in EXAMPLES.glob("*.toml")}
    assert packaged == in_repo, "examples/*.toml and python/gecko/scene/figures/*.toml must be identical"
    assert len(packaged) == 16  # 9 seta-paper figures, 3 friction-paper figures, the README demo,
    # a design sweep, a design optimisation and the contact-length contours of the forward problem


@pytest.mark.parametrize("path", sorted(EXAMPLES.rglob("*.toml")), ids=lambda p: p.stem)
def test_every_example_validates(path):
    sc = validate_scene(path)
    assert (sc.studies and sc.plots) or sc.sweep is not None or sc.optimize is not None
    assert sc.source == str(path)


def test_defaults_are_the_reference_scene():
    sc = load_scene(seta_scene())
    (p,) = sc.studies[0].points
    assert p.values == {"EI1": 5.0, "EI2": 2.0, "EA1": math.inf, "EA2": 50.0, "l1": 1.0, "l2": 0.1,
                        "alpha1": math.pi / 6, "alpha2": math.pi / 6, "w": 1.0}


def test_sweep_forms_and_combination():
    cross = load_scene(seta_scene(parameters={"l2": [0.1, 0.2], "alpha2": {"range": [0.1, 0.3], "num": 3}}))
    pts = cross.studies[0].points
    assert len(pts) == 6 and cross.studies[0].swept_names == ["l2", "alpha2"]
    assert [p.values["alpha2"] for p in pts[:3]] == pytest.approx([0.1, 0.2, 0.3])
    zipped = load_scene(seta_scene(combine="zip", parameters={"EA2": [math.inf, 50], "EA1": [math.inf, 100]}))
    assert [(p.values["EA2"], p.values["EA1"]) for p in zipped.studies[0].points] == [(math.inf, math.inf), (50, 100)]
    log = load_scene(seta_scene(parameters={"EI2": {"logrange": [0.1, 10], "num": 3}}))
    assert [p.values["EI2"] for p in log.studies[0].points] == pytest.approx([0.1, 1, 10])


def test_resolution_scales_ranges_not_lists():
    sc = load_scene(seta_scene(parameters={"EI2": {"range": [1, 2], "num": 40}, "l2": [0.1, 0.2]}),
                    resolution=0.25)
    assert len(sc.studies[0].points) == 10 * 2


def test_expressions_and_variables():
    sc = load_scene(seta_scene(variables={"ratio": [0.1, 0.4]}, parameters={
        "EI2": "ratio * EI1", "alpha2": ["0", "pi/12"], "alpha1": "pi/3 - alpha2"}))
    pts = sc.studies[0].points
    assert len(pts) == 4
    for p in pts:
        assert p.values["EI2"] == pytest.approx(p.values["ratio"] * 5)
        assert p.values["alpha1"] + p.values["alpha2"] == pytest.approx(math.pi / 3)
    assert load_scene(seta_scene(parameters={"alpha1": "deg(30)"})).studies[0].points[0].values["alpha1"] == \
        pytest.approx(math.pi / 6)


def test_label_templates_and_angles():
    sc = load_scene(seta_scene(label="a2 = {alpha2:pi}, l2 = {l2:g}", parameters={"alpha2": ["pi/9", "5*pi/36"]}))
    st = sc.studies[0]
    assert [st.label_for(p) for p in st.points] == ["a2 = π/9, l2 = 0.1", "a2 = 5π/36, l2 = 0.1"]
    auto = load_scene(seta_scene(parameters={"alpha2": ["pi/12"]})).studies[0]
    assert auto.label_for(auto.points[0]) == "α₂ = π/12"


def test_plots_request_what_they_draw():
    sc = load_scene({"study": [{"model": "two_level_seta", "parameters": {"EI2": [1, 2]}}],
                     "plot": [{"kind": "characteristic", "x": "EI2", "y": "fn0"}]})
    assert sc.studies[0].outputs["characteristics"].options["which"] == ["fn0"]
    sc = load_scene({"study": [{"model": "kendall"}], "plot": [{"kind": "critical_line"}]})
    assert "critical_line" in sc.studies[0].outputs


def _deprecations(fn):
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        out = fn()
    return out, [str(w.message) for w in seen if issubclass(w.category, DeprecationWarning)]


def test_deprecated_slope_names_warn_once_per_key_naming_the_replacement():
    # issue 13: "slope_k" does not say which slope; the scene still runs, with the same values
    scene = {"study": [{"model": "two_level_seta", "parameters": {"EI2": [1, 2]},
                        "outputs": {"characteristics": ["slope_k", "abs_slope_k", "slope_k", "paper_k"]}}],
             "plot": [{"kind": "characteristic", "x": "EI2", "y": ["inv_abs_k", "abs_paper_k"]}]}
    sc, dep = _deprecations(lambda: load_scene(scene))
    assert dep == ["scene study[0].outputs.characteristics: 'slope_k' is deprecated, use 'slope_at_zero' (the "
                   "same values); 'abs_slope_k' is deprecated, use 'abs_slope_at_zero' (the same values)",
                   "scene plot[0].y: 'inv_abs_k' is deprecated, use 'inv_abs_slope_at_zero' (the same values)"]
    assert sc.studies[0].outputs["characteristics"].options["which"] == ["slope_k", "abs_slope_k", "paper_k",
                                                                          "inv_abs_k", "abs_paper_k"]
    _, dep = _deprecations(lambda: load_scene(seta_scene(outputs={"characteristics": True})))
    assert dep == []  # true: the current names only
    _, dep = _deprecations(lambda: load_scene(seta_scene(outputs={"characteristics": ["slope_at_zero", "paper_k"]})))
    assert dep == []


# ---- bad scenes: one clear error naming the file, the key path and what is allowed -------------

BAD = [
    ({"studdy": []}, "studdy", "allowed keys: title, description, resolution, study, plot"),
    ({"study": [{"model": "seta"}]}, "study[0].model", "allowed models: two_level_seta, single_fiber"),
    (seta_scene(parameters={"EI3": 1}), "study[0].parameters.EI3", "allowed: EI1, EI2, EA1, EA2"),
    (seta_scene(parameters={"EI1": -5}), "study[0].parameters.EI1", "need 0 < value < inf"),
    (seta_scene(parameters={"EI1": True}), "study[0].parameters.EI1", "got a boolean"),
    (seta_scene(parameters={"alpha1": "pi/2"}), "study[0].parameters.alpha1", "need 0 < value < pi/2"),
    (seta_scene(parameters={"alpha1": "pi/3", "alpha2": ["pi/12", "pi/6"]}), "study[0].parameters",
     "alpha1 + alpha2 = π/2 is out of range: need alpha1 + alpha2 < pi/2 (design alpha2 = π/6)"),
    (seta_scene(parameters={"EA2": 0}), "study[0].parameters.EA2", "need 0 < value <= inf"),
    (seta_scene(parameters={"alpha1": "__import__('os')"}), "study[0].parameters.alpha1", "not allowed"),
    (seta_scene(parameters={"alpha1": "beta/2"}), "study[0].parameters.alpha1", "unknown name 'beta'"),
    (seta_scene(parameters={"alpha1": "pi/"}), "study[0].parameters.alpha1", "cannot read the expression"),
    (seta_scene(combine="zip", parameters={"EA2": [1, 2], "EA1": [1]}), "study[0].combine", "EA2: 2, EA1: 1"),
    (seta_scene(combine="both"), "study[0].combine", "'cross'"),
    (seta_scene(parameters={"EI2": {"range": [1, 2]}}), "study[0].parameters.EI2", "missing key 'num'"),
    (seta_scene(parameters={"EI2": {"logrange": [0, 2], "num": 3}}), "study[0].parameters.EI2.logrange",
     "logrange bounds must be > 0"),
    (seta_scene(outputs={"critical_lines": True}), "study[0].outputs.critical_lines",
     "allowed: critical_line, characteristics, shapes"),
    (seta_scene(outputs={"characteristics": ["fn1"]}), "study[0].outputs.characteristics[0]", "allowed: fn0,"),
    (seta_scene(outputs={"critical_line": {"Ft": {"range": [0, 11], "num": 5}}}), "study[0].outputs.critical_line.Ft",
     "Ft = 11 is out of range: need |Ft| <= (Ft)max"),
    (seta_scene(outputs={"critical_line": {"Ft": {"range": [0, "ft_mx"], "num": 5}}}),
     "study[0].outputs.critical_line.Ft.range[1]", "allowed names: EA1, EA2"),
    (seta_scene(outputs={"shapes": {"points": 2}}), "study[0].outputs.shapes.points", "[3, 100000]"),
    ({"study": [{"model": "spatula", "parameters": {"K": [[5, -3], [-2, 2]]}}]}, "study[0].parameters.K",
     "symmetric positive definite"),
    ({"study": [{"model": "spatula", "parameters": {"path": "fig5"}}]}, "study[0].parameters.path", "'fig4', 'fig8'"),
    ({"study": [{"model": "steady_sliding", "parameters": {"preset": "elastic"}}]}, "study[0].parameters.preset",
     "'viscoelastic', 'plastic'"),
    ({"study": [{"model": "steady_sliding", "outputs": {"forces": {"V": [-1e-6, 1e-6]}}}]},
     "study[0].outputs.forces.V", "need V >= 0"),
    ({"study": [{"model": "kendall"}], "plot": [{"kind": "pie"}]}, "plot[0].kind", "allowed kinds: critical_line"),
    ({"study": [{"model": "kendall"}], "plot": [{"kind": "force_trace"}]}, "plot[0]", "models that can: spatula"),
    ({"study": [{"model": "kendall"}], "plot": [{"kind": "critical_line", "studies": ["seta"]}]},
     "plot[0].studies[0]", "studies in this scene: kendall"),
    ({"study": [{"model": "two_level_seta"}], "plot": [{"kind": "characteristic", "x": "EI2", "y": "fn0"}]},
     "plot[0].x", "swept there: nothing"),
    ({"study": [{"model": "kendall"}], "plot": [{"kind": "critical_line", "xlim": [2, 1]}]}, "plot[0].xlim",
     "need finite min < max"),
    ({"study": [{"model": "kendall"}], "plot": [{"kind": "critical_line", "formats": ["jpg"]}]}, "plot[0].formats",
     "png, svg, pdf"),
    ({"study": [{"model": "kendall"}, {"model": "kendall"}]}, "study[1].name", "duplicate study name"),
    ({"study": [{"model": "kendall"}], "resolution": 0}, "resolution", "need a number in (0, 100]"),
    ({"study": [{"model": "kendall", "label": "K_{seta}"}]}, "study[0].label",
     "unknown name 'seta' in the label 'K_{seta}'; names: EA, w (write {{ and }} for literal braces)"),
]


@pytest.mark.parametrize("scene,key,allowed", BAD, ids=[b[1] + ":" + b[2][:20] for b in BAD])
def test_bad_scene_names_key_and_allowed(scene, key, allowed):
    with pytest.raises(SceneError) as info:
        load_scene(scene)
    err = info.value
    assert err.key == key
    assert allowed in err.reason
    assert str(err).startswith(f"<dict>: {key}: ")


def test_bad_file_named(tmp_path):
    missing = tmp_path / "nope.toml"
    with pytest.raises(SceneError, match=r"nope\.toml: cannot read the file"):
        load_scene(missing)
    bad = tmp_path / "bad.toml"
    bad.write_text("[[study]]\nmodel = \n")
    with pytest.raises(SceneError, match=r"bad\.toml: not valid TOML"):
        load_scene(bad)
    wrong = tmp_path / "wrong.toml"
    wrong.write_text('[[study]]\nmodel = "two_level_seta"\nparameters = { EI1 = "five" }\n')
    with pytest.raises(SceneError) as info:
        load_scene(wrong)
    assert str(info.value).startswith(f"{wrong}: study[0].parameters.EI1: unknown name 'five'")
    binary = tmp_path / "bin.toml"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(SceneError, match="not UTF-8"):
        load_scene(binary)
