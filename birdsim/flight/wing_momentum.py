"""The wings' wingbeat-mean angular momentum relative to the torso, and the moment its
change asks of the attitude loop (reduced units, seed body axes x fwd / y right / z down,
about the whole bird's centre of mass).

The torso and the wings share one angular momentum: ``I w' = M - h'`` for the torso
(``I`` the loop's inertia, ``M`` the external moment of the air on wings and tail,
``h`` the wings' angular momentum relative to the torso about the centre of mass).
Over a wingbeat of a flapping, twisting wing ``h`` swings about a mean of zero in every
axis (the flap turns about x, the twist about the span, each with a rate odd about
mid-stroke: base to m3, the mean is round-off, 1e-17; m4's lagging wrist leaves a small
one, 4e-4 at the seed bird's m5 wingbeat unfolded).  A wing that folds in its own plane
(m5: the elbow and the wrist's sweep about the panel's normal) while it is flapped has
a mean about the pitch axis, the same in both wings (the fold's rate times the flap's
tilt of the panel's normal; about ``Phi_f F cos(phi_F)`` for small amplitudes): the
pigeon's m5 table's wingbeats carry 0 to 0.04 table units.  When the path loop's demand
moves the table's wingbeat (fold amplitude, its phase, the flap amplitude) that mean
changes within a wingbeat and the torso takes the opposite change of pitch rate: in
the pigeon's free m5 landing 0.035 within half a wingbeat (a pitch rate kick of 0.05
rad per time unit), the free flight's first departure (docs/free-body.md, 2026-12-03).
The loop's demand gains ``h'``, so the air's moment supplies it through wings and tail.
"""

from __future__ import annotations

import mujoco
import numpy as np

from birdsim.flight.attitude_jacobians import JAC_SAMPLES, SEED_AXES, held_prescription
from birdsim.mujoco.model import pitch_quat

#: A change of the mean below this (table units of angular momentum) is round-off of a
#: mean that the wingbeat's time symmetry makes zero (base to m3: 1e-17); it asks nothing.
ROUNDOFF = 1e-12


def mean_wing_momentum(fb, params: np.ndarray, data: mujoco.MjData | None = None) -> np.ndarray:
    """The wingbeat-mean angular momentum (3,) of the wings beating ``params`` relative
    to the torso held at rest (body level, no airspeed), about the whole bird's centre
    of mass, seed body axes, over :data:`birdsim.flight.attitude_jacobians.JAC_SAMPLES`
    phases; ``fb`` a :class:`birdsim.flight.simulate.FreeBird`, ``data`` a scratch
    ``MjData`` of its model (None: a new one).  Only the kinematics are computed (no
    forces): positions, centres of mass, velocities, then the subtree's momentum."""
    m = fb.m
    d = mujoco.MjData(m) if data is None else data
    pres, _ = held_prescription(fb, params, None, JAC_SAMPLES)
    quat = pitch_quat(0.0)
    root = int(m.jnt_bodyid[0])  # the free joint's body: the whole bird's subtree
    h = np.zeros(3)
    for k in range(JAC_SAMPLES):
        d.qpos[:] = pres.qpos[k]
        d.qvel[:] = pres.qvel[k]
        d.qpos[:3] = (0.0, 0.0, 6.0)
        d.qpos[3:7] = quat
        d.qvel[:6] = 0.0  # the torso at rest
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_comVel(m, d)
        mujoco.mj_subtreeVel(m, d)
        h += d.subtree_angmom[root]
    return h / JAC_SAMPLES * SEED_AXES


def has_mean_momentum(names: tuple[str, ...]) -> bool:
    """Whether a wingbeat of a model with parameters ``names`` can have a mean wing
    angular momentum: only with joints beyond the shoulder (m4's wrist, m5's fold).
    The shoulder's flap, twist, sweep and stroke plane are sinusoids whose rates are odd
    about mid-stroke, so their mean is zero (base to m3: below 2e-17, the tests)."""
    return "wrist_amp" in names or "fold_amp" in names


class WingMomentumRate:
    """Per flight: the rate of change of the commanded wingbeat's mean wing angular
    momentum between two control steps (:meth:`step`).  ``active`` None: decided at the
    first step by :func:`has_mean_momentum` (False: every rate zero, nothing computed)."""

    def __init__(self, active: bool | None = None) -> None:
        self.active = active
        self.last: np.ndarray | None = None
        self._data: mujoco.MjData | None = None

    def step(self, fb, params: np.ndarray, dt: float) -> np.ndarray:
        """``dh/dt`` (3,) from the last step's wingbeat to ``params`` over ``dt``
        (reduced time); zero on the first step and on axes whose change is round-off
        (:data:`ROUNDOFF`)."""
        if self.active is None:
            self.active = has_mean_momentum(fb.schedule.names)
        if not self.active:
            return np.zeros(3)
        if self._data is None and fb is not None:
            self._data = mujoco.MjData(fb.m)
        h = mean_wing_momentum(fb, params, self._data)
        last, self.last = self.last, h
        if last is None or dt <= 0.0:
            return np.zeros(3)
        change = h - last
        return np.where(np.abs(change) > ROUNDOFF, change / dt, 0.0)


def with_momentum_rate(
    loop, params: np.ndarray, dt: float, acc_cmd: object, pitch_demand: float | None
) -> tuple[object, float | None]:
    """``(acc_cmd, pitch_demand)`` of :meth:`birdsim.flight.attitude.AttitudeLoop.update`
    with the wings' momentum rate (the loop's ``wing_momentum``, a
    :class:`WingMomentumRate`) added: ``h' / I`` to the commanded acceleration per axis
    (the demand ``I (acc + ...)`` gains ``h'``) and ``h'_y`` to the pitch section's
    moment demand; unchanged where the rate is zero (base to m3: bit for bit)."""
    rate = loop.wing_momentum.step(loop.fb, params, dt)
    if not rate.any():
        return acc_cmd, pitch_demand
    base = np.zeros(3) if acc_cmd is None else np.asarray(acc_cmd, dtype=float)
    acc = base + rate / loop.inertia
    return acc, (None if pitch_demand is None else pitch_demand + float(rate[1]))


__all__ = [
    "ROUNDOFF",
    "WingMomentumRate",
    "has_mean_momentum",
    "mean_wing_momentum",
    "with_momentum_rate",
]
