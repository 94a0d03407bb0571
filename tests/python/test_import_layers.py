"""The Python package's imports only point down (the README's layout section): no import circle,
and no lower layer imports a higher one.

The graph is read from the source with ``ast`` (every ``import`` / ``from ... import``, also those
inside functions: a lazy import that closes a circle is still a circle), so the test needs no
compiled module and sees the package as committed.
"""
import ast
import functools
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[2] / "python" / "gecko"

# Lowest first; a module may import its own layer's helpers and anything below, never above.
LAYERS = [
    {"gecko._core", "gecko._optional", "gecko._vectorize", "gecko.progress", "gecko._integrity",
     "gecko._locking", "gecko._dask_probe", "gecko._population"},
    {"gecko.elliptic", "gecko.seta", "gecko.friction", "gecko.friction_hierarchy"},
    {"gecko.designs"},
    {"gecko.design_sweep", "gecko._sweep_store", "gecko.optimize", "gecko.design_optimize"},
    {"gecko.scene"},
    {"gecko.cli", "gecko.__main__"},
]


def _module_name(path):
    rel = path.relative_to(PKG.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _modules():
    mods = {_module_name(p): p for p in PKG.rglob("*.py") if "__pycache__" not in p.parts}
    mods["gecko._core"] = None            # the compiled module: imports nothing of the package
    return mods


def _resolve(current, is_package, node, mods):
    """Absolute gecko module names an import node refers to."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    base = current.split(".") if is_package else current.split(".")[:-1]
    if node.level:
        base = base[: len(base) - (node.level - 1)]
        prefix = ".".join(base + ([node.module] if node.module else []))
    else:
        prefix = node.module or ""
    # "from . import _core" names the submodule gecko._core (the package itself is already being
    # initialised); "from .seta import X" or "from gecko import name" names the module holding X.
    subs = [f"{prefix}.{a.name}" for a in node.names]
    return [s for s in subs if s in mods] + ([prefix] if any(s not in mods for s in subs) else [])


@functools.lru_cache(maxsize=None)
def _graph():
    mods = _modules()
    graph = {}
    for name, path in mods.items():
        if path is None:
            graph[name] = set()
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        is_package = path.name == "__init__.py"
        deps = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                for target in _resolve(name, is_package, node, mods):
                    # the longest known module prefix of the target
                    parts = target.split(".")
                    while parts and ".".join(parts) not in mods:
                        parts.pop()
                    if parts and ".".join(parts) != name:
                        deps.add(".".join(parts))
        graph[name] = deps
    return graph


def _cycles(graph):
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def _layer(name):
    for i, layer in enumerate(LAYERS):
        for top in layer:
            if name == top or name.startswith(top + "."):
                return i
    return None


def test_the_graph_is_read_from_the_package():
    graph = _graph()
    assert {"gecko.seta", "gecko.scene.runner", "gecko.optimize.driver", "gecko.cli"} <= set(graph)
    assert "gecko._core" in graph["gecko.seta"]          # the reader resolves "from . import _core"


def test_no_import_circle():
    assert _cycles(_graph()) == []


def test_a_planted_circle_is_found():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycles(graph) == [["a", "b", "c"]]


def _upward(graph, name):
    return sorted(d for d in graph[name] if _layer(d) is not None and _layer(d) > _layer(name))


def test_a_planted_upward_import_is_found():
    graph = {"gecko.seta": {"gecko._core", "gecko.scene.runner"}, "gecko._core": set()}
    assert _upward(graph, "gecko.seta") == ["gecko.scene.runner"]
    assert _upward(graph, "gecko._core") == []


@pytest.mark.parametrize("name", sorted(n for n in _modules() if _layer(n) is not None))
def test_imports_point_down(name):
    up = _upward(_graph(), name)
    assert up == [], f"{name} (layer {_layer(name)}) imports a higher layer: {up}"
