"""The optimiser's variables: a box over the design fields and three derived ratios/sums, scaled
to z in [0, 1] (log between the bounds for positive quantities, linear for angles), and the map
z -> the nine fields with its exact Jacobian."""
from __future__ import annotations

import math

import numpy as np

from ..seta import SetaDesign, TwoLevelSeta
from .objectives import _INDEX, FIELDS

_DERIVED = {"EI2/EI1": "EI2", "l2/l1": "l2", "alpha1+alpha2": "alpha1"}
_ANGLES = {"alpha1", "alpha2", "alpha1+alpha2"}
_HALF_PI = math.pi / 2
_ANGLE_MARGIN = 1e-6
def _interval(lo: float, hi: float, lo_incl: bool) -> str:
    def text(v):
        return "inf" if v == math.inf else "pi/2" if v == _HALF_PI else f"{v:g}"
    return f"{'[' if lo_incl else '('}{text(lo)}, {text(hi)})"


# Allowed ranges of every variable, for the error messages: the design fields' admissible ranges
# from the bound C++ design type (SetaDesign.domain), and the derived variables'.
# name -> (lower, upper, text, lower inclusive, infinity allowed as a fixed value)
_DOMAIN = {name: (lo, hi, _interval(lo, hi, incl), incl, inf_ok)
           for name, (lo, hi, incl, inf_ok, _) in SetaDesign.domain.items()}
_DOMAIN.update({"EI2/EI1": (0.0, math.inf, "(0, inf)", False, False),
                "l2/l1": (0.0, math.inf, "(0, inf)", False, False),
                "alpha1+alpha2": (0.0, _HALF_PI, "(0, pi/2)", False, False)})



# Variables: scaled z in [0, 1] -> variables x -> the nine parameters p (with exact dp/dx).

class _Space:
    def __init__(self, bounds: dict, base: dict):
        if not isinstance(bounds, dict) or not bounds:
            raise ValueError("bounds must be a non-empty dict {parameter: (lower, upper)}; parameters: "
                             f"{FIELDS + tuple(_DERIVED)}")
        self.names = list(bounds)
        self.lo, self.hi, self.log = [], [], []
        for name in self.names:
            if name not in _DOMAIN:
                raise ValueError(f"bounds: unknown parameter {name!r}; allowed: {FIELDS + tuple(_DERIVED)}")
            dlo, dhi, text, lo_incl, _ = _DOMAIN[name]
            try:
                lo, hi = (float(v) for v in bounds[name])
            except (TypeError, ValueError):
                raise ValueError(f"bounds[{name!r}] = {bounds[name]!r}: need (lower, upper) numbers "
                                 f"within {text}") from None
            if not (math.isfinite(lo) and math.isfinite(hi)):
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}): need finite lower < upper within {text}")
            if not lo < hi:
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}): lower must be < upper, within {text}")
            lo_ok = lo >= dlo if lo_incl else lo > dlo
            if not (lo_ok and hi < dhi):
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}) outside the allowed range {text}")
            self.lo.append(lo)
            self.hi.append(hi)
            self.log.append(name not in _ANGLES)
        self.lo, self.hi, self.log = np.array(self.lo), np.array(self.hi), np.array(self.log)
        # conflicts between a derived variable and the field it sets
        derived = {d: dep for d, dep in _DERIVED.items() if d in self.names or d in base}
        for d, dep in derived.items():
            if dep in self.names:
                raise ValueError(f"{d!r} sets {dep!r}: vary/fix one of them, not both")
        # the fixed values must lie in the model's domain too (EA may be inf: inextensible)
        dependent = set(derived.values())
        for k, v in base.items():
            if k in self.names or k in dependent:
                continue
            dlo, dhi, text, lo_incl, inf_ok = _DOMAIN[k]
            ok = (v >= dlo if lo_incl else v > dlo) and (v < dhi or (inf_ok and v == math.inf))
            if not ok or math.isnan(v):
                allowed = text + (" or inf" if inf_ok else "")
                raise ValueError(f"fixed parameter {k} = {v!r} outside the allowed range {allowed}")
        self.base = dict(base)
        self.derived = derived
        self.d = len(self.names)

    def x_of(self, z):
        z = np.clip(np.asarray(z, float), 0.0, 1.0)
        out = self.lo + z * (self.hi - self.lo)
        lg = self.log
        out[lg] = self.lo[lg] * (self.hi[lg] / self.lo[lg]) ** z[lg]
        return out

    def z_of(self, x):
        x = np.asarray(x, float)
        z = (x - self.lo) / (self.hi - self.lo)
        lg = self.log
        with np.errstate(divide="ignore", invalid="ignore"):
            z[lg] = np.log(x[lg] / self.lo[lg]) / np.log(self.hi[lg] / self.lo[lg])
        return z

    def dx_dz(self, z):
        x = self.x_of(z)
        out = self.hi - self.lo
        lg = self.log
        out[lg] = x[lg] * np.log(self.hi[lg] / self.lo[lg])
        return out

    def params(self, z):
        """p (nine fields) and dp/dz (9 x d)."""
        x = self.x_of(z)
        dxdz = self.dx_dz(z)
        val = {}
        grad = {}
        d = self.d
        for f in FIELDS:
            val[f] = float(self.base[f])
            grad[f] = np.zeros(d)
        allv = dict(self.base)
        for i, n in enumerate(self.names):
            allv[n] = x[i]
            if n in _INDEX:
                val[n] = x[i]
                grad[n] = np.zeros(d)
                grad[n][i] = dxdz[i]

        def var_grad(name):
            g = np.zeros(d)
            if name in self.names:
                g[self.names.index(name)] = dxdz[self.names.index(name)]
            return g

        if "EI2/EI1" in self.derived:
            r = allv["EI2/EI1"]
            val["EI2"] = r * val["EI1"]
            grad["EI2"] = r * grad["EI1"] + val["EI1"] * var_grad("EI2/EI1")
        if "l2/l1" in self.derived:
            r = allv["l2/l1"]
            val["l2"] = r * val["l1"]
            grad["l2"] = r * grad["l1"] + val["l1"] * var_grad("l2/l1")
        if "alpha1+alpha2" in self.derived:
            S = allv["alpha1+alpha2"]
            val["alpha1"] = S - val["alpha2"]
            grad["alpha1"] = var_grad("alpha1+alpha2") - grad["alpha2"]
        p = np.array([val[f] for f in FIELDS])
        J = np.array([grad[f] for f in FIELDS])
        return p, J

    def variables(self, z):
        return dict(zip(self.names, map(float, self.x_of(z))))



def _base_dict(base) -> dict:
    if base is None:
        return {f: getattr(TwoLevelSeta(), f) for f in FIELDS}
    if isinstance(base, TwoLevelSeta):
        return {f: getattr(base, f) for f in FIELDS}
    if isinstance(base, dict):
        d = {f: getattr(TwoLevelSeta(), f) for f in FIELDS}
        for k, v in base.items():
            if k not in _INDEX and k not in _DERIVED:
                raise ValueError(f"base: unknown parameter {k!r}; allowed: {FIELDS + tuple(_DERIVED)}")
            d[k] = float(v)
        return d
    raise ValueError(f"base = {base!r}: need None, a TwoLevelSeta or a dict of parameters")
