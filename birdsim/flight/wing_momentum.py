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

from birdsim.flight.attitude_jacobians import JAC_SAMPLES, SEED_AXES, _hold, held_body
from birdsim.mujoco.model import pitch_quat

#: A change of the mean below this (table units of angular momentum) is round-off of a
#: mean that the wingbeat's time symmetry makes zero (base to m3: 1e-17); it asks nothing.
ROUNDOFF = 1e-12


def mean_wing_momentum(fb, params: np.ndarray) -> np.ndarray:
    """The wingbeat-mean angular momentum (3,) of the wings beating ``params`` relative
    to the torso held at rest (body level, no airspeed), about the whole bird's centre
    of mass, seed body axes, over :data:`birdsim.flight.attitude_jacobians.JAC_SAMPLES`
    phases; ``fb`` a :class:`birdsim.flight.simulate.FreeBird`."""
    h = np.zeros(3)
    quat, still = pitch_quat(0.0), np.zeros(3)
    with held_body(fb, params, None) as (m, d, pres):
        root = int(m.jnt_bodyid[0])  # the free joint's body: the whole bird's subtree
        for k in range(JAC_SAMPLES):
            _hold(m, d, pres.qpos[k], pres.qvel[k], quat, 0.0, still)
            mujoco.mj_subtreeVel(m, d)
            h += d.subtree_angmom[root]
    return h / JAC_SAMPLES * SEED_AXES


class WingMomentumRate:
    """Per flight: the rate of change of the commanded wingbeat's mean wing angular
    momentum between two control steps (:meth:`step`)."""

    def __init__(self) -> None:
        self.last: np.ndarray | None = None

    def step(self, fb, params: np.ndarray, dt: float) -> np.ndarray:
        """``dh/dt`` (3,) from the last step's wingbeat to ``params`` over ``dt``
        (reduced time); zero on the first step and on axes whose change is round-off
        (:data:`ROUNDOFF`)."""
        h = mean_wing_momentum(fb, params)
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


__all__ = ["ROUNDOFF", "WingMomentumRate", "mean_wing_momentum", "with_momentum_rate"]
