"""Safe arithmetic in scene files: ``alpha1 = "pi/3 - alpha2"``, ``Ft = [0, "0.9*ft_max"]``.

TOML has no expressions, yet the papers' parameters are ``pi/6`` or one parameter derived from
another (Fig 3c keeps alpha1 + alpha2 fixed). A string value is parsed with :mod:`ast` and only
numbers, names, + - * / ** and a few functions are accepted: no attribute access, no calls of
anything else, so a scene file can never run code.
"""
from __future__ import annotations

import ast
import functools
import math
from typing import Any, Callable, Dict, Iterable, Mapping, Set

import numpy as np

from .errors import SceneError

CONSTANTS: Dict[str, float] = {"pi": math.pi, "inf": math.inf, "e": math.e}

FUNCTIONS: Dict[str, Callable] = {
    "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp,
    "log": math.log, "log10": math.log10, "abs": abs, "min": min, "max": max,
    "deg": math.radians,  # deg(30) = pi/6: angles may be written in degrees
}

#: Bounds on an expression: a scene's expressions are a few dozen characters; without bounds a
#: long chain ("1+1+...+1") or deep nesting ("-(-(-...") made the parser or the recursive
#: evaluator raise RecursionError / MemoryError instead of SceneError (found while writing
#: fuzz/fuzz_scene.py, which now guards it). Powers are evaluated in floating point, so 10**10**10 is an overflow
#: (SceneError), never a huge integer.
MAX_EXPRESSION_CHARS = 1000
MAX_EXPRESSION_DEPTH = 100

_BINOPS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
           ast.Div: lambda a, b: a / b, ast.Pow: lambda a, b: a ** b}
_UNARY = {ast.USub: lambda a: -a, ast.UAdd: lambda a: a}


def _parse(text: str, key: str) -> ast.Expression:
    tree, reason = _checked(text)
    if reason:
        raise SceneError(reason, key=key)
    return tree


@functools.lru_cache(maxsize=1024)
def _checked(text: str, functions: str = "scalar"):
    """(tree, None) for an allowed expression, else (None, why); cached: a sweep re-evaluates the
    same few expressions for every design. ``functions``: "scalar" (FUNCTIONS) or "array"
    (ARRAY_FUNCTIONS, for a law G(V) evaluated on arrays)."""
    try:
        return _check(text, functions=ARRAY_FUNCTIONS if functions == "array" else FUNCTIONS), None
    except SceneError as err:
        return None, err.reason


def _depth(node: ast.AST) -> int:
    """Nesting depth of an expression tree, iteratively (a recursive walk is what overflowed)."""
    deepest = 0
    stack = [(node, 1)]
    while stack:
        n, d = stack.pop()
        deepest = max(deepest, d)
        stack.extend((c, d + 1) for c in ast.iter_child_nodes(n))
    return deepest


def _check(text: str, key: str = "", functions: Mapping[str, Callable] = FUNCTIONS) -> ast.Expression:
    if len(text) > MAX_EXPRESSION_CHARS:
        raise SceneError(f"the expression {text[:40]!r}... is {len(text)} characters long; at most "
                         f"{MAX_EXPRESSION_CHARS} are allowed", key=key)
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        # ValueError: null bytes on older Pythons; RecursionError/MemoryError: parser limits
        raise SceneError(f"cannot read the expression {text!r}: allowed are numbers, names, "
                         "+ - * / ** ( ) and " + ", ".join(sorted(functions)), key=key) from None
    if _depth(tree) > MAX_EXPRESSION_DEPTH:
        raise SceneError(f"the expression {text!r} is nested more than {MAX_EXPRESSION_DEPTH} levels deep",
                         key=key)
    for node in ast.walk(tree):
        ok = isinstance(node, (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Name, ast.Load, ast.Call,
                               ast.operator, ast.unaryop)) or (
            isinstance(node, ast.Constant) and isinstance(node.value, (int, float))
            and not isinstance(node.value, bool))
        if isinstance(node, ast.BinOp) and type(node.op) not in _BINOPS:
            ok = False
        if isinstance(node, ast.UnaryOp) and type(node.op) not in _UNARY:
            ok = False
        if isinstance(node, ast.Call) and not (isinstance(node.func, ast.Name) and node.func.id in functions
                                               and not node.keywords):
            ok = False
        if not ok:
            raise SceneError(f"the expression {text!r} uses something not allowed: only numbers, "
                             "names, + - * / ** ( ) and the functions " + ", ".join(sorted(functions)),
                             key=key)
    return tree


def names_in(text: str, key: str = "") -> Set[str]:
    """The free names of an expression (constants and functions excluded)."""
    _parse(text, key)
    return set(_names(text))


@functools.lru_cache(maxsize=1024)
def _names(text: str) -> frozenset:
    tree = _checked(text)[0]
    called = {n.func.id for n in ast.walk(tree) if isinstance(n, ast.Call)}
    return frozenset({n.id for n in ast.walk(tree) if isinstance(n, ast.Name)} - called - set(CONSTANTS))


def _evaluator(text: str, key: str, name: Callable, call: Callable) -> Callable:
    """The recursive evaluator of a checked tree: ``name(id)`` gives a name's value,
    ``call(function, args)`` applies an allowed function."""
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.Name):
            return name(node.id)
        if isinstance(node, ast.BinOp):
            return _BINOPS[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp):
            return _UNARY[type(node.op)](ev(node.operand))
        if isinstance(node, ast.Call):
            return call(node.func.id, [ev(a) for a in node.args])
        raise SceneError(f"cannot evaluate {text!r}", key=key)  # unreachable after the check
    return ev


def evaluate(text: str, env: Mapping[str, float] = {}, key: str = "",
             allowed: Iterable[str] = ()) -> float:
    """Value of the expression ``text`` with the names in ``env`` (and pi, inf, e)."""
    tree = _parse(text, key)

    def name(n):
        if n in env:
            return float(env[n])
        if n in CONSTANTS:
            return CONSTANTS[n]
        names = sorted(set(CONSTANTS) | set(allowed) | set(env))
        raise SceneError(f"unknown name {n!r} in {text!r}; allowed names: " + ", ".join(names), key=key)

    ev = _evaluator(text, key, name, lambda f, args: float(FUNCTIONS[f](*args)))

    try:
        return ev(tree)
    except SceneError:
        raise
    except (ArithmeticError, ValueError, TypeError) as exc:
        raise SceneError(f"cannot evaluate {text!r}: {exc}", key=key) from None


# ---- expressions over arrays (a detachment law G(V) in a scene) ---------------------------------

#: numpy counterparts of FUNCTIONS, plus asinh (the Eyring law, paper 000 eq 8), tanh and log1p
ARRAY_FUNCTIONS: Dict[str, Callable] = {
    "sqrt": np.sqrt, "sin": np.sin, "cos": np.cos, "tan": np.tan, "exp": np.exp, "log": np.log,
    "log10": np.log10, "abs": np.abs, "min": np.minimum, "max": np.maximum, "asinh": np.arcsinh,
    "tanh": np.tanh, "log1p": np.log1p,
}


def array_names(text: str, key: str = "") -> Set[str]:
    """The free names of an array expression (checked against ARRAY_FUNCTIONS)."""
    tree, reason = _checked(text, "array")
    if reason:
        raise SceneError(reason, key=key)
    called = {n.func.id for n in ast.walk(tree) if isinstance(n, ast.Call)}
    return {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)} - called - set(CONSTANTS)


def evaluate_array(text: str, env: Mapping[str, Any], key: str = ""):
    """Value of the array expression ``text`` (numpy broadcasting over the arrays in ``env``).
    Only the checked operators and ARRAY_FUNCTIONS run: a scene never executes code."""
    tree, reason = _checked(text, "array")
    if reason:
        raise SceneError(reason, key=key)

    def name(n):
        if n in env:
            return env[n]
        if n in CONSTANTS:
            return CONSTANTS[n]
        raise SceneError(f"unknown name {n!r} in {text!r}; allowed names: "
                         + ", ".join(sorted(set(env) | set(CONSTANTS))), key=key)

    ev = _evaluator(text, key, name, lambda f, args: ARRAY_FUNCTIONS[f](*args))

    with np.errstate(all="ignore"):  # a NaN or inf is reported by the caller, with the key
        return np.asarray(ev(tree), dtype=np.float64)
