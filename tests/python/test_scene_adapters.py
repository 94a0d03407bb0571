"""Each scene model is an adapter that owns its planning and kernels: the planner and the runner
hold no model names."""
import ast
import inspect

from gecko.scene import planner, runner
from gecko.scene.adapters import ADAPTERS, Adapter, Step
from gecko.scene.models import MODELS


def test_every_model_has_an_adapter_and_every_planned_kernel_exists():
    assert set(ADAPTERS) == set(MODELS)
    for name, a in ADAPTERS.items():
        assert isinstance(a, Adapter) and name in a.models
        kernels = {k[2:] for k in dir(a) if k.startswith("k_")}
        assert kernels, name
    assert planner.Step is Step


def test_planner_and_runner_do_not_name_models():
    from gecko.scene.schema import PLOT_KINDS
    names = set(MODELS) - set(PLOT_KINDS)  # "steady_sliding" is also a plot kind, which the runner draws
    for mod in (planner, runner):
        literals = {n.value for n in ast.walk(ast.parse(inspect.getsource(mod)))
                    if isinstance(n, ast.Constant) and isinstance(n.value, str)}
        assert not (literals & names), (mod.__name__, literals & names)


def test_planned_kernels_are_the_adapters_methods():
    from gecko.scene import load_scene, plan_scene
    sc = load_scene({"study": [
        {"model": "two_level_seta", "outputs": {"critical_line": True, "characteristics": ["fn0", "small_fn0"]}},
        {"model": "single_fiber", "outputs": {"critical_line": True, "characteristics": True}},
        {"model": "kendall", "outputs": {"critical_line": True, "characteristics": True}},
        {"model": "rivlin", "outputs": {"critical_line": True}}]})
    plan = plan_scene(sc)
    assert [(s.study, s.kernel) for s in plan.steps] == [
        (sc.studies[0].name, "critical_line"), (sc.studies[0].name, "fn0_from_line"),
        (sc.studies[0].name, "small_deformation"),
        (sc.studies[1].name, "critical_line"), (sc.studies[1].name, "fn0_from_line"),
        (sc.studies[2].name, "critical_line"), (sc.studies[2].name, "characteristics"),
        (sc.studies[3].name, "critical_line")]
    for s in plan.steps:
        assert hasattr(ADAPTERS[sc.study(s.study).model.name], "k_" + s.kernel)
