"""The prescribed part of free flight, step by step: wingbeat parameters -> smoothed
schedule p(t), p'(t), p''(t) -> joint angles, rates and accelerations -> MuJoCo
qpos/qvel/qacc of the wings and of the torso's orientation.

The same chain as :mod:`birdsim.flight.playback`, made incremental so that a controller
can change the target parameters while the simulation runs:

* smoothing: the two cascaded first-order low-pass filters of playback (time constant
  ``smoothing_beats`` each), written in continuous time and integrated exactly for a
  target held constant between controller updates.  The output p is C1 (p'' jumps when
  the target jumps), never leaves the convex hull of the targets (so parameters stay
  within their bounds) and starts in steady state;
* phase: ``phi = omega t`` (the reduced bird: omega = 1), continuous whatever the targets do;
* joints: the model's own ``joint_motion`` sinusoids with time-varying coefficients
  (:func:`birdsim.flight.playback.joint_derivatives`), then the driver's
  :func:`birdsim.mujoco.driver.wing_arrays` (ball joints composed exactly);
* torso: pitch = the ``pitch`` parameter (nose up), roll = yaw = 0 (driver.set_root).

Units: the reduced bird's (time 1/omega, lengths in semispans); ``t`` is reduced time.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.flight.playback import joint_derivatives
from birdsim.mujoco.driver import set_root, wing_arrays
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel


class CascadeFilter:
    """Two cascaded first-order filters ``x1' = (u - x1)/tau``, ``x2' = (x1 - x2)/tau``,
    output ``p = x2``, for vectors of parameters; exact for piecewise-constant input u.

    ``tau = 0`` passes the input straight through (p' = p'' = 0).
    """

    def __init__(self, tau: float, initial: np.ndarray):
        if not (math.isfinite(tau) and tau >= 0):
            raise BirdsimError(f"smoothing time constant={tau!r}; allowed: a number >= 0")
        self.tau = float(tau)
        self.x1 = np.array(initial, dtype=float)
        self.x2 = self.x1.copy()

    def advance(
        self, u: np.ndarray, t_rel: np.ndarray, dt: float
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """p, p', p'' at the instants ``t_rel`` (T,) after now with input ``u`` held, then
        move the state on by ``dt``.  Returns arrays (T, n)."""
        u = np.asarray(u, dtype=float)
        t = np.asarray(t_rel, dtype=float)[:, None]
        if self.tau == 0.0:
            self.x1 = u.copy()
            self.x2 = u.copy()
            z = np.zeros((t.shape[0], u.size))
            return np.broadcast_to(u, z.shape).copy(), z, z.copy()
        tau = self.tau
        e1, e2 = self.x1 - u, self.x2 - u

        def at(tt: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            ex = np.exp(-tt / tau)
            f1 = e1 * ex
            f2 = (e2 + e1 * tt / tau) * ex
            return f1, f2, ex

        f1, f2, _ = at(t)
        p = u + f2
        dp = (f1 - f2) / tau
        ddp = (f2 - 2.0 * f1) / tau**2
        g1, g2, _ = at(np.array([[dt]]))
        self.x1 = u + g1[0]
        self.x2 = u + g2[0]
        return p, dp, ddp

    @property
    def output(self) -> np.ndarray:
        return self.x2.copy()


@dataclass(frozen=True)
class Prescription:
    """Prescribed coordinates over a run of steps: full-size arrays of which only the
    prescribed entries (torso orientation, wings) are meaningful."""

    qpos: np.ndarray  # (T, nq)
    qvel: np.ndarray  # (T, nv)
    qacc: np.ndarray  # (T, nv)
    params: np.ndarray  # (T, nP) smoothed wingbeat parameters
    pitch: np.ndarray  # (T,) nose up (rad)


class WingbeatSchedule:
    """Smoothed wingbeat parameters of ``kin`` and the prescribed motion they imply."""

    def __init__(
        self,
        m: mujoco.MjModel,
        kin: KinematicModel,
        bird: Bird,
        initial: Sequence[float],
        *,
        smoothing: float,
    ):
        self.m = m
        self.kin = kin
        self.bird = bird
        self.names = kin.param_names
        self.filter = CascadeFilter(smoothing, np.asarray(initial, dtype=float))
        self.pitch_index = self.names.index("pitch")

    def advance(
        self, target: Sequence[float], times: np.ndarray, t_now: float, dt: float
    ) -> Prescription:
        """The prescription at absolute reduced ``times`` (T,), for a target held from
        ``t_now`` for ``dt``; the filter state moves on to ``t_now + dt``."""
        times = np.asarray(times, dtype=float)
        p, dp, ddp = self.filter.advance(np.asarray(target, dtype=float), times - t_now, dt)
        return self.prescribe(times, p, dp, ddp)

    def prescribe(
        self, times: np.ndarray, p: np.ndarray, dp: np.ndarray, ddp: np.ndarray
    ) -> Prescription:
        """qpos/qvel/qacc of the wings and torso orientation for parameters p(t) (T, nP)."""
        omega = self.bird.omega
        cols = {n: p[:, i] for i, n in enumerate(self.names)}
        rates = {n: dp[:, i] for i, n in enumerate(self.names)}
        accs = {n: ddp[:, i] for i, n in enumerate(self.names)}
        angles, jrates, jaccs = joint_derivatives(
            self.kin, self.bird, cols, rates, accs, omega * times, omega
        )
        t = len(times)
        qpos, qvel, qacc = wing_arrays(self.m, angles, jrates, jaccs, samples=t)
        k = self.pitch_index
        set_root(self.m, qpos, qvel, pitch=p[:, k], pitch_rate=dp[:, k])
        qacc[:, 3:6] = 0.0
        qacc[:, 4] = -ddp[:, k]  # pitch nose up is a rotation about MuJoCo -y
        return Prescription(qpos, qvel, qacc, p, p[:, k].copy())


__all__ = ["CascadeFilter", "Prescription", "WingbeatSchedule"]
