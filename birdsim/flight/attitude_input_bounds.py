"""The attitude inputs' bounds at a wingbeat (:meth:`birdsim.flight.attitude.AttitudeLoop.bounds`;
radians, per input of :data:`birdsim.flight.attitude_jacobians.INPUTS`)."""

from __future__ import annotations

import numpy as np


def bounds_plan(kin, inputs: tuple) -> list[tuple[int, float, float, float]]:
    """Per input of ``inputs`` (name, kind, bound): (the wingbeat parameter's index in
    ``kin.param_names`` or -1, its lower and upper bounds, the input's bound).  A
    differential amplitude stays within the parameter's bounds on both wings (>= 0); an
    angle (the stroke plane) only by the input's bound (the table's bound the search only);
    a differential input of a parameter the wingbeat has not: 0."""
    names, spec = kin.param_names, {p.name: p for p in kin.params}
    plan = []
    for name, kind, bound in inputs:
        if kind == "diff" and name in names and name.endswith("_amp"):
            plan.append((names.index(name), spec[name].lower, spec[name].upper, bound))
        else:
            b = 0.0 if kind == "diff" and name not in names else bound
            plan.append((-1, 0.0, 0.0, b))
    return plan


def plan_bounds(plan: list, params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) of the inputs at the wingbeat ``params`` (:func:`bounds_plan`'s ``plan``)."""
    hi = []
    for i, lower, upper, bound in plan:
        if i >= 0:
            p = float(params[i])
            bound = min(bound, max(0.0, 2.0 * min(p - lower, upper - p)))
        hi.append(bound)
    return np.array([-b for b in hi]), np.array(hi)


__all__ = ["bounds_plan", "plan_bounds"]
