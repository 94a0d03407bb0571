"""gecko.optimize — gradient-based, multi-start design optimisation of the two-level seta.

docs/theory/two_level_seta.md (critical line of adhesion and its characteristic quantities); the paper's closing
discussion (001, §3.2 "Tunability", last paragraph) on optimising the structural parameters: first
keep the seta non-sticky at rest, (Fn)0 > 0 (eq 22), then make the maximum pull-off force large.

``optimize_seta(objective, bounds, constraints)`` maximises one of three built-in objectives over a
box of design parameters, subject to the built-in constraints and user callables:

* ``"max_pull_off"``: P = -min Fn over the critical line followed from Ft = 0 to its end
  (Ft)max = sqrt(2 EA2 w). (This is ``SetaCharacteristics.max_pull_off`` without the clip at 0, so
  a design with no tensile critical state has a negative value that still has a useful gradient.)
  Gradient by the envelope theorem: at an interior minimiser Ft*, dFn/dFt = 0, so
  dP/dp = -dFn/dp|Ft* (the solver's exact sensitivity at fixed Ft). A minimiser at Ft = 0 is the
  fixed lower end (the same formula holds). Stationarity at Ft* is checked with the exact slope of
  the line, which Euler's theorem gives from the same sensitivities (the equations are homogeneous
  in force units: Ft dFn/dFt = Fn - sum over EI1, EI2, EA1, EA2, w of p dFn/dp); where the trace's
  own refinement stopped short of dFn/dFt = 0, the minimiser is refined here (Brent on the exact
  slope) before the envelope theorem is used. A minimiser at the moving end Ft = (Ft)max would need
  the total derivative of Fn((Ft)max(p); p), whose two parts are each singular there (the edge
  rate vanishes like sqrt((Ft)max - Ft)); it is recorded as a failed evaluation, never fed on. In
  600 random designs (EI1 in [1, 20], EI2/EI1, l2 in [0.05, 0.5], EA2 in [10, 200], all angles)
  the line always rose steeply into its end, so the case was not met.
* ``"area"``: A = integral over the admissible part of the line, Ft in [0, b] with b =
  ``characteristics().admissible_end_ft`` ((Ft)max when the whole line is admissible; status-7
  states, where the seta crosses the substrate, add no area), of max(0, -Fn(Ft)) dFt, the area between the
  critical line and the Ft axis where the line is tensile (Fn < 0): the region of the (Ft, Fn) plane
  (gripping side Ft >= 0) in which a pulled seta stays attached. Computed by Gauss-Legendre on each
  tensile interval, with Ft = b - (b - a) u^2 on the interval that ends at (Ft)max (Fn has a
  sqrt((Ft)max - Ft) term there). Gradient by differentiating under the integral (the integrand's
  design derivative is the solver's exact sensitivity; its (Ft)max - Ft)^(-1/2) singularity is
  integrable and removed by the same substitution) plus the moving-end term
  max(0, -Fn((Ft)max)) d(Ft)max/dp; the ends where the line crosses Fn = 0 add nothing (the
  integrand vanishes there). Lines with a fold (Fn(Ft) not single-valued) are failed evaluations.
  A design with no tensile critical state has A = 0 and a zero gradient (a plateau): starts that
  begin there stay there, which is what the multi-start is for.
* ``"pull_off_at"``: -Fn(Ft) at a given Ft (``ft=``), gradient the direct sensitivity.
* A user ``Objective(name, fun, jac=None)`` or plain callable of the design dict (maximised).

Constraints (all of the form g(p) >= 0): ``"not_sticky"`` ((Fn)0 >= 0), ``("fn0_min", m)``
((Fn)0 >= m), ``Constraint(name, fun, jac=None)`` / a plain callable of the design dict; the bounds;
and, added automatically when the angles vary, alpha1 + alpha2 <= pi/2 - 1e-6 and alpha1 >= 1e-6.

Parameters that may vary (``bounds`` keys): the nine fields of ``TwoLevelSeta`` (EI1, EI2, EA1,
EA2, l1, l2, alpha1, alpha2, w) and three derived ones: ``"EI2/EI1"`` (sets EI2 = r EI1),
``"l2/l1"`` (sets l2 = r l1) and ``"alpha1+alpha2"`` (sets alpha1 = S - alpha2). A derived one may
also be held fixed through ``base`` (e.g. ``base={"alpha1+alpha2": pi/3}`` with ``alpha2`` varying:
the paper's Fig 3c split). The optimiser works in scaled variables z in [0, 1]: log scale between the
bounds for positive quantities (stiffnesses, lengths, ratios, w), linear for angles.

Multi-start: ``starts`` points of a scrambled Sobol sequence (scipy.stats.qmc, deterministic with
``seed``), the first replaced by ``base`` when it lies inside the bounds; SLSQP with exact gradients
(``jac``) from each. A design where the solver fails (line status != 0, fold, minimiser at the line
end, invalid design) is never passed on as a number: it is recorded in ``failures`` and returned to
SLSQP as a penalised value (worse than every successful one, zero gradient) so the line search backs
off; a start that ends on such a design is marked failed. The stopping rule is first-order
optimality, not SLSQP's change in the objective: each start's end point is checked by its KKT residual
(active constraints and bounds, non-negative multipliers by NNLS) and SLSQP is restarted there with a
smaller ftol until the residual is below 1e-9 relative (at most 4 restarts); a start is "converged"
only at a residual <= 1e-4. The optimum is re-evaluated and reports that check.

Layers (imports point down): ``objectives`` (built-in objectives with exact gradients) and
``space`` (the scaled variables) <- ``problem`` (constraints, cached evaluations for SLSQP) and
``kkt`` (the first-order check) <- ``driver`` (multi-start ``optimize_seta``, ``SetaOptimum``,
the scene adapter ``optimize_from_scene``).
"""
from __future__ import annotations

from .driver import SetaOptimum, optimize_from_scene, optimize_seta
from .objectives import FIELDS, OBJECTIVES, Objective, seta_objective
from .problem import Constraint

__all__ = ["optimize_seta", "optimize_from_scene", "SetaOptimum", "Constraint", "Objective",
           "OBJECTIVES", "seta_objective"]
