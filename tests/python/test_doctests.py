"""The Examples sections of the public docstrings run as doctests, so every example in the API
reference is checked against the code it documents.

Modules whose optional dependency is missing are skipped (the examples of gecko.plot draw with
matplotlib; those of the sweep need pandas)."""
import doctest
import importlib
import os

import numpy as np
import pytest

# Public modules of the package (python/gecko), in the order of the API reference.
MODULES = [
    ("gecko._optional", None),
    ("gecko.elliptic", None),
    ("gecko.seta", None),
    ("gecko.friction", None),
    ("gecko.friction_hierarchy", None),
    ("gecko.plot_hierarchy", "matplotlib"),
    ("gecko.design_sweep", "pandas"),
    ("gecko.designs", "pandas"),
    ("gecko.optimize", "scipy"),
    ("gecko.optimize.driver", "scipy"),
    ("gecko.optimize.objectives", "scipy"),
    ("gecko.optimize.problem", "scipy"),
    ("gecko.progress", None),
    ("gecko.plot", "matplotlib"),
    ("gecko.cli", None),
    ("gecko.scene", None),
    ("gecko.scene.schema", None),
    ("gecko.scene.planner", None),
    ("gecko.scene.runner", None),
    ("gecko.scene.render", "matplotlib"),
    ("gecko.scene.models", None),
    ("gecko.scene.expr", None),
    ("gecko.scene.errors", None),
    ("gecko.scene.toml", None),
    ("gecko.scene.design_sections", None),
]


@pytest.mark.parametrize("name, needs", MODULES, ids=[m for m, _ in MODULES])
def test_docstring_examples(name, needs, tmp_path, monkeypatch):
    if needs is not None:
        pytest.importorskip(needs)
    os.environ.setdefault("MPLBACKEND", "Agg")
    monkeypatch.chdir(tmp_path)                    # examples that write files write them here
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    tests = [t for t in finder.find(module, name, extraglobs={"np": np}) if t.examples]
    # only the module's own objects (re-exported names are tested in their home module)
    tests = [t for t in tests if t.name == name or t.name.startswith(name + ".")]
    for t in tests:
        runner.run(t)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"


def test_every_public_function_and_class_has_an_example():
    """The API reference promises Parameters/Attributes and Examples for every public name defined
    in Python (names bound from C++, such as the status enums, document themselves there)."""
    import inspect

    import gecko
    missing = []
    for name in gecko.__all__:
        obj = getattr(gecko, name)
        if not (inspect.isfunction(obj) or inspect.isclass(obj)):
            continue                                   # constants
        if not getattr(obj, "__module__", "").startswith("gecko.") or obj.__module__ == "gecko._core":
            continue
        if isinstance(obj, type) and issubclass(obj, __import__("enum").Enum):
            continue                                   # enums list their members
        doc = inspect.getdoc(obj) or ""
        takes_args = inspect.isfunction(obj) and bool(inspect.signature(obj).parameters)
        wanted = ["Examples", "Parameters" if takes_args else None,
                  "Returns" if inspect.isfunction(obj) else None]
        lacking = [s for s in wanted if s and s not in doc]
        if inspect.isclass(obj) and "Parameters" not in doc and "Attributes" not in doc:
            lacking.append("Parameters or Attributes")
        if lacking:
            missing.append(f"{name}: {', '.join(lacking)}")
    assert missing == []
