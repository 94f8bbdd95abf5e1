"""The numbers of one wing's figures: the thrust coefficient (Fig 9), the wrist's lag
and bias (Figs 26-27), its activity coefficient (Fig 49) and the control points' paths
and chord lines (Figs 41-43, 46-48, 53-55)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from birdsim.physics.aero import Polar
from birdsim.physics.bird import Bird
from birdsim.physics.frames import body_to_earth
from birdsim.physics.kinematics import get_model, joint_states, panel_to_body, points_in_body
from birdsim.report.figgrid import grid_means, mesh

# ---- Fig 9: thrust coefficient over advance angle and twist --------------------------


def thrust_coefficient(polar: Polar, advance_angle: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """Eq. 20/23: ``C_Fx = C_L(a) sin(zeta) - C_D(a) cos(zeta)`` with ``a = zeta - theta_f``.

    A translating section meets the air at the advance angle ``zeta = atan(w_f / V)``;
    twist ``theta_f`` (leading edge down) reduces its incidence to ``zeta - theta_f``.
    Lift is normal and drag parallel to the relative wind, so their components along
    the flight direction give the thrust coefficient.  (The printed eq. 23 drops the
    ``sin(zeta)`` of the lift term -- an OCR/typesetting slip: with it, eq. 23 reduces to
    eq. 15 at zero twist as the text says.)  Arrays broadcast.
    """
    zeta = np.asarray(advance_angle, dtype=float)
    cl, cd = polar.coefficients(zeta - np.asarray(twist, dtype=float))
    return cl * np.sin(zeta) - cd * np.cos(zeta)


# ---- Figs 26-27: wrist lag and bias --------------------------------------------------

#: sec. 3.5.7: cruise-like case, pitch, stroke plane and twist omitted.
WRIST_STUDY = dict(speed=0.5, pitch=0.0, twist_amp=0.0, stroke_plane=0.0)


def wrist_upward_force(
    flap_amp: np.ndarray | float,
    wrist_amp: np.ndarray | float,
    wrist_lag: np.ndarray | float,
    wrist_bias: np.ndarray | float,
    *,
    bird: Bird | None = None,
    n: int = 32,
) -> np.ndarray:
    """Upward mean force ``-Fz`` of m4 (dissertation force) in the sec. 3.5.7 study
    (V = 0.5, pitch = twist = stroke plane = 0), over any broadcastable grid.

    The dissertation's "F_z(max)" is the largest upward force; its amplitudes and bias
    exceed the default bounds (up to pi/2), so bounds are not checked here.
    """
    s = WRIST_STUDY
    params = dict(
        pitch=s["pitch"],
        flap_amp=flap_amp,
        twist_amp=s["twist_amp"],
        stroke_plane=s["stroke_plane"],
        wrist_amp=wrist_amp,
        wrist_bias=wrist_bias,
        wrist_lag=wrist_lag,
    )
    return -grid_means("m4", params, s["speed"], bird=bird, n=n).Fz


@dataclass(frozen=True)
class WristOptimum:
    """Per (flap_amp, wrist_amp): the lag and bias giving the largest upward force."""

    flap_amp: np.ndarray  # I
    wrist_amp: np.ndarray  # J
    lag_star: np.ndarray  # I x J
    bias_star: np.ndarray  # I x J
    upward_max: np.ndarray  # I x J


def wrist_optimum(
    flap_amp: np.ndarray,
    wrist_amp: np.ndarray,
    lag: np.ndarray,
    bias: np.ndarray,
    *,
    bird: Bird | None = None,
    n: int = 32,
) -> WristOptimum:
    """Fig 27: argmax over the (lag, bias) grid of the upward force, for every amplitude pair."""
    up = wrist_upward_force(*mesh([flap_amp, wrist_amp, lag, bias]), bird=bird, n=n)
    i, j = up.shape[:2]
    flat = up.reshape(i, j, -1)
    best = np.argmax(flat, axis=-1)
    li, bi = np.unravel_index(best, (len(lag), len(bias)))
    return WristOptimum(
        np.asarray(flap_amp),
        np.asarray(wrist_amp),
        np.asarray(lag)[li],
        np.asarray(bias)[bi],
        np.take_along_axis(flat, best[..., None], axis=-1)[..., 0],
    )


# ---- Fig 49: wrist activity coefficient K --------------------------------------------


def wrist_activity(k: np.ndarray | float) -> dict[str, np.ndarray]:
    """Eq. 95: wrist amplitude, lag and bias as ``K`` times their upper bounds (m4)."""
    m = get_model("m4")
    k = np.asarray(k, dtype=float)
    return {name: k * m.spec(name).upper for name in ("wrist_amp", "wrist_lag", "wrist_bias")}


# ---- Figs 41-43, 46-48, 53-55: control-point paths and chord lines -------------------


@dataclass(frozen=True)
class ControlPointPaths:
    """Per panel: CP path and chord segments in earth-oriented axes relative to the
    shoulder (seed axes: X forward, Y right, Z down), over one wingbeat.

    ``path`` is K x N x 3; ``leading``/``trailing`` are K x N x 3, the ends of the chord
    line through each CP (leading edge = +x of the panel)."""

    model: str
    panel_names: tuple[str, ...]
    phase: np.ndarray  # N, t/T in [0, 1)
    path: np.ndarray
    leading: np.ndarray
    trailing: np.ndarray


def control_point_paths(
    model: str, params: Mapping[str, float], *, bird: Bird | None = None, n: int = 64
) -> ControlPointPaths:
    """Where each panel's control point goes over one wingbeat, with its chord line.

    Uses the kinematic chain directly (``joint_states``, ``points_in_body``,
    ``panel_to_body``) and the body pitch to turn body axes into earth axes; the body
    stays at the origin (paths relative to the shoulder, as the dissertation draws them).
    """
    bird = bird or Bird()
    m = get_model(model)
    p = {k: np.asarray(float(v)) for k, v in params.items()}
    phases = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    states = joint_states(m, p, bird, phases, trailing=1)
    pitch = float(p["pitch"])
    paths, leads, trails, names = [], [], [], []
    for (chain, span, chord), geom in zip(m.chain_with_geometry(bird), bird.panels(m.name)):
        r = np.array([bird.cp_span_fraction * span])
        pos, _ = points_in_body(chain, states, r)
        x_axis = panel_to_body(chain, states, (np.ones((n, 1)), np.zeros((n, 1)), np.zeros((n, 1))))
        pos = np.stack(
            [np.broadcast_to(c, (n, 1))[:, 0] for c in body_to_earth(pitch, pos)], axis=-1
        )
        ax = np.stack(
            [np.broadcast_to(c, (n, 1))[:, 0] for c in body_to_earth(pitch, x_axis)], axis=-1
        )
        paths.append(pos)
        leads.append(pos + 0.5 * chord * ax)
        trails.append(pos - 0.5 * chord * ax)
        names.append(geom.name)
    return ControlPointPaths(
        m.name,
        tuple(names),
        phases / (2 * math.pi),
        np.stack(paths),
        np.stack(leads),
        np.stack(trails),
    )
