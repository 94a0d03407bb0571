"""The package itself: version from the build, the public names of the design contract, stubs."""
import pathlib
import re

import gecko

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_version_comes_from_the_cmake_project():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    assert gecko.__version__ == re.search(r"project\(gecko VERSION ([0-9.]+)", cmake).group(1)


def test_all_lists_only_existing_public_names():
    assert len(gecko.__all__) == len(set(gecko.__all__))
    for name in gecko.__all__:
        assert hasattr(gecko, name), name


def test_contract_names_of_design_md():
    for name in ["ellint_f", "ellint_e", "ellint_k", "ellint_ek",
                 "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc"]:
        assert name in gecko.__all__, name


def test_compiled_module_ships_its_stub():
    pkg = pathlib.Path(gecko.__file__).parent
    stub = (pkg / "_core.pyi").read_text()
    for name in dir(gecko._core):
        if not name.startswith("_"):
            assert f"def {name}(" in stub or f"class {name}" in stub or f"{name}:" in stub, name


def _split_top_level(text):
    """Split at commas outside brackets (pybind11 signatures nest numpy.ndarray[...])."""
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch in "[(":
            depth += 1
        elif ch in "])":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur)
    return [p.strip() for p in parts]


def _bound_signature(fn):
    """(parameter names, number without a default) from a pybind11 function's docstring, whose
    first line is ``name(a: T, b: T = v, ...) -> R``; None for an overloaded function."""
    first = (fn.__doc__ or "").lstrip().splitlines()[0] if fn.__doc__ else ""
    m = re.match(r"^\w+\((.*)\)\s*->", first)
    if not m:
        return None
    names, required = [], 0
    for p in _split_top_level(m.group(1)):
        if p in ("*", "/"):
            continue
        names.append(p.split(":", 1)[0].split("=", 1)[0].strip().lstrip("*"))
        required += "=" not in p
    return names, required


def test_stub_signatures_match_the_bound_functions():
    """Every module-level function of the stub has the bound function's parameter names, in
    order, and the same number of parameters without a default (a stale stub fails here)."""
    import ast

    stub = ast.parse((pathlib.Path(gecko.__file__).parent / "_core.pyi").read_text())
    checked = 0
    for node in stub.body:
        if not isinstance(node, ast.FunctionDef):
            continue
        fn = getattr(gecko._core, node.name, None)
        assert fn is not None, f"the stub declares {node.name}, which _core does not have"
        bound = _bound_signature(fn)
        if bound is None:
            # Only the scalar kernels of the ufuncs (<name>_scalar, <name>_fast) are plain C
            # functions without a signature.
            assert node.name.endswith(("_scalar", "_fast")), f"{node.name}: no signature in its __doc__"
            continue
        a = node.args
        names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
        required = len(a.posonlyargs + a.args) - len(a.defaults) + sum(d is None for d in a.kw_defaults)
        assert names == bound[0], f"{node.name}: stub {names} against bound {bound[0]}"
        assert required == bound[1], f"{node.name}: stub has {required} required parameters, bound {bound[1]}"
        checked += 1
    assert checked >= 30  # the elliptic, friction and seta functions
