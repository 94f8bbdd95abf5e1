"""The dissertation's statements about the optimum over speed (sec. 4.1.1; Figs 35, 38,
44, 45, 52), one registered check per model (see :mod:`birdsim.report.claims`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from birdsim.physics.kinematics import get_model
from birdsim.report import figdata as fd
from birdsim.report.claims import ClaimRegistry
from birdsim.report.records import Claim

PI = math.pi

SWEEP = ClaimRegistry("speed-sweep claims")


@dataclass(frozen=True)
class SweepView:
    """A model's forward and backward passes as the statements read them.

    ``col``: each parameter of the forward pass over ``speeds`` (rad); ``up``: the
    parameters' upper bounds (rad); ``ends``: the largest parameter difference between
    the two passes at the first and last speed (rad); ``base_fwd``: the base model's
    forward pass (None until it is computed).
    """

    fwd: fd.SpeedSweep
    bwd: fd.SpeedSweep
    base_fwd: fd.SpeedSweep | None
    col: dict[str, np.ndarray]
    up: dict[str, float]
    speeds: np.ndarray
    ends: float


def sweep_claims(
    model: str, fwd: fd.SpeedSweep, bwd: fd.SpeedSweep, base_fwd: fd.SpeedSweep | None
) -> tuple[str, list[Claim]]:
    """``(said, claims)``: the dissertation's text about ``model``'s sweep and each of its
    statements tested on our passes."""
    view = SweepView(
        fwd,
        bwd,
        base_fwd,
        col={n: fwd.params[:, i] for i, n in enumerate(fwd.param_names)},
        up={p.name: p.upper for p in get_model(model).params},
        speeds=fwd.speeds,
        ends=float(np.abs(fwd.params[[0, -1]] - bwd.params[[0, -1]]).max()),
    )
    return SWEEP.check(model, view)


def _passes_agree(s: SweepView) -> Claim:
    return Claim(
        "forward and backward passes agree at V = 0 and V = 1",
        bool(s.ends < 0.05),
        f"largest difference at the ends: {s.ends:.3f} rad",
    )


@SWEEP.add(
    "base",
    "Figs 35/38: pitch falls with speed (not vertical at V = 0 because of the Fx demand); twist at "
    "its maximum for V up to ~0.3, "
    "then falling to almost none at V = 1; forward and backward passes agree at low and high "
    "speed.",
)
def _base(s: SweepView) -> list[Claim]:
    col, up = s.col, s.up
    low = s.speeds <= 0.3 + 1e-9
    return [
        Claim(
            "pitch falls with speed",
            bool(col["pitch"][-1] < col["pitch"][0]),
            f"pitch {col['pitch'][0]:.2f} at V = 0, {col['pitch'][-1]:.2f} at V = 1",
        ),
        Claim(
            "not pitched vertically at V = 0",
            bool(col["pitch"][0] < PI / 2 - 0.05),
            f"pitch at V = 0: {col['pitch'][0]:.2f}",
        ),
        Claim(
            "twist at its maximum up to V ~ 0.3",
            bool(np.all(col["twist_amp"][low] > up["twist_amp"] - 0.02)),
            f"twist for V <= 0.3: {', '.join(f'{t:.2f}' for t in col['twist_amp'][low])}",
        ),
        Claim(
            "almost no twist at V = 1",
            bool(col["twist_amp"][-1] < 0.1),
            f"twist at V = 1: {col['twist_amp'][-1]:.2f}",
        ),
        _passes_agree(s),
    ]


@SWEEP.add("m1", "Fig 44: model 1 follows the base model closely; in hover it uses maximum values.")
def _m1(s: SweepView) -> list[Claim]:
    if s.base_fwd is None:
        return [_passes_agree(s)]
    col, up = s.col, s.up
    diff = np.abs(s.fwd.params - s.base_fwd.params).max()
    return [
        Claim(
            "follows the base model closely",
            bool(diff < 0.2),
            f"largest parameter difference to the base model: {diff:.3f} rad",
        ),
        Claim(
            "maximum flap and twist in hover",
            bool(
                col["flap_amp"][0] > up["flap_amp"] - 0.02
                and col["twist_amp"][0] > up["twist_amp"] - 0.02
            ),
            f"at V = 0: flap {col['flap_amp'][0]:.2f}, twist {col['twist_amp'][0]:.2f}",
        ),
        _passes_agree(s),
    ]


@SWEEP.add(
    "m3",
    "Fig 45: at low speed the maximum stroke-plane angle plus some body pitch (their sum = the "
    "base model's pitch); "
    "in cruise no body pitch, the stroke plane vectors the force.",
)
def _m3(s: SweepView) -> list[Claim]:
    if s.base_fwd is None:
        return [_passes_agree(s)]
    col, up = s.col, s.up
    total = col["pitch"][0] + col["stroke_plane"][0]
    return [
        Claim(
            "maximum stroke plane at V = 0",
            bool(col["stroke_plane"][0] > up["stroke_plane"] - 0.01),
            f"stroke plane at V = 0: {col['stroke_plane'][0]:.3f}",
        ),
        Claim(
            "pitch + stroke plane at V = 0 equals the base model's pitch",
            bool(abs(total - s.base_fwd.params[0, 0]) < 0.05),
            f"{total:.3f} vs base {s.base_fwd.params[0, 0]:.3f}",
        ),
        Claim(
            "no body pitch in cruise, the stroke plane used",
            bool(col["pitch"][-1] < 0.05 and col["stroke_plane"][-1] > 0.05),
            f"at V = 1: pitch {col['pitch'][-1]:.3f}, stroke plane {col['stroke_plane'][-1]:.3f}",
        ),
        _passes_agree(s),
    ]


@SWEEP.add(
    "m4",
    "Fig 52 (Fx = 0, stroke plane omitted, backward pass): maximum pitch, flap and twist in hover; "
    "wrist amplitude and bias small at low speed, "
    "rising at intermediate speeds; the lag stays at pi/2.",
)
def _m4(s: SweepView) -> list[Claim]:
    col, up = s.col, s.up
    hover = [col[k][0] > up[k] - 0.05 for k in ("pitch", "flap_amp", "twist_amp")]
    moving = col["wrist_amp"] > 0.05
    return [
        Claim(
            "maximum pitch, flap and twist in hover",
            all(hover),
            f"at V = 0: pitch {col['pitch'][0]:.2f}, flap {col['flap_amp'][0]:.2f}, twist "
            f"{col['twist_amp'][0]:.2f}",
        ),
        Claim(
            "wrist amplitude and bias small at V = 0, larger at high speed",
            bool(
                col["wrist_amp"][0] < 0.1
                and col["wrist_bias"][0] < 0.1
                and col["wrist_amp"][-1] > col["wrist_amp"][0]
            ),
            f"wrist amp {col['wrist_amp'][0]:.2f} -> {col['wrist_amp'][-1]:.2f}, "
            f"bias {col['wrist_bias'][0]:.2f} -> {col['wrist_bias'][-1]:.2f}",
        ),
        Claim(
            "lag at pi/2 where the wrist moves",
            bool(np.all(np.abs(col["wrist_lag"][moving] - PI / 2) < 0.1)),
            "lag where wrist amp > 0.05: "
            f"{', '.join(f'{x:.2f}' for x in col['wrist_lag'][moving]) or 'none'}",
        ),
    ]
