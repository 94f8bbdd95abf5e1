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
from birdsim.flight import fast_prescription, fast_schedule, fast_wingbeat
from birdsim.flight.playback import joint_derivatives
from birdsim.mujoco.driver import set_root, wing_arrays
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import KinematicModel

#: Time constant (wingbeats) of the attitude inputs' smoothing: fast enough for the
#: attitude loop, slow enough that the wings' accelerations stay of the wingbeat's order.
INPUT_SMOOTHING_BEATS = 0.125
#: The symmetric shoulder offsets of the attitude loop: (joint, sign) of the sweep
#: (positive: tips back) and the dihedral (positive: tips up; a positive flap angle puts
#: the tip down, docs/conventions.md).
SHOULDER_OFFSETS = (("sweep", 1.0), ("flap", -1.0))


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
    prescribed entries (wings; the torso orientation only in the posed mode) are
    meaningful."""

    qpos: np.ndarray  # (T, nq)
    qvel: np.ndarray  # (T, nv)
    qacc: np.ndarray  # (T, nv)
    params: np.ndarray  # (T, nP) smoothed wingbeat parameters (the right wing's)
    pitch: np.ndarray  # (T,) nose up (rad): the table's (commanded) body pitch
    params_left: np.ndarray | None = None  # (T, nP) the left wing's, when it differs


class WingbeatSchedule:
    """Smoothed wingbeat parameters of ``kin`` and the prescribed motion they imply.

    The filter runs on the right wing's and the left wing's parameters side by side
    (2 nP entries), so a differential wingbeat is smoothed like the symmetric one.
    """

    def __init__(
        self,
        m: mujoco.MjModel,
        kin: KinematicModel,
        bird: Bird,
        initial: Sequence[float],
        *,
        smoothing: float,
        initial_left: Sequence[float] | None = None,
        input_smoothing: float | None = None,
    ):
        self.m = m
        self.kin = kin
        self.bird = bird
        self.names = kin.param_names
        right = np.asarray(initial, dtype=float)
        left = right if initial_left is None else np.asarray(initial_left, dtype=float)
        #: the table's wingbeat (the mean of both wings), smoothed like playback's
        self.filter = CascadeFilter(smoothing, 0.5 * (right + left))
        #: the attitude inputs: half the right-left difference of every parameter and
        #: the shoulder offsets (right sweep, dihedral, left sweep, dihedral), smoothed
        #: faster (INPUT_SMOOTHING_BEATS)
        tau_in = INPUT_SMOOTHING_BEATS * bird.period if input_smoothing is None else input_smoothing
        n = len(self.names)
        self.input_filter = CascadeFilter(
            min(tau_in, smoothing),
            np.concatenate([0.5 * (right - left), np.zeros(n), np.zeros(4)]),
        )
        self.pitch_index = self.names.index("pitch")
        #: symmetric shoulder offsets (rad) of both wings' targets, attitude inputs that
        #: move the force line (any model): (sweep, dihedral), :data:`SHOULDER_OFFSETS`
        self.shoulder_target = np.zeros(2)

    def advance(
        self,
        target: Sequence[float],
        times: np.ndarray,
        t_now: float,
        dt: float,
        target_left: Sequence[float] | None = None,
        offset: Sequence[float] | None = None,
    ) -> Prescription:
        """The prescription at absolute reduced ``times`` (T,), for a target held from
        ``t_now`` for ``dt``; the filter state moves on to ``t_now + dt``.
        ``target_left``: the left wing's target (None: the same as the right's);
        ``offset``: a correction added to both wings' parameters, smoothed like the
        attitude inputs (the stroke plane's compensation of a pitch error)."""
        times = np.asarray(times, dtype=float)
        right, left, u, v = self.inputs(target, target_left, offset)
        rel = times - t_now
        n = len(self.names)
        fused = fast_wingbeat.advance(self, u, v, times, rel, dt)
        if fused is not None:  # the filters and the rows in one call (fast_wingbeat)
            right3, left3, shoulder3, qpos, qvel, qacc, flags = fused
            r, lft = tuple(right3), tuple(left3)
            if flags & 4:  # finite: prescribe's rows (left None where it equals the right)
                return self._finish(qpos, qvel, qacc, *r, None if flags & 2 else lft)
            return self.prescribe(times, *r, left=lft, shoulder=tuple(shoulder3))
        fast = fast_schedule.advance(self.filter, self.input_filter, u, v, rel, dt, n)
        if fast is not None:  # the same numbers, compiled (birdsim.flight.fast_schedule)
            r, lft, shoulder = fast
            return self.prescribe(times, *r, left=lft, shoulder=shoulder)
        mean = self.filter.advance(u, rel, dt)
        inputs = self.input_filter.advance(v, rel, dt)
        r = tuple(a + b[:, :n] + b[:, n : 2 * n] for a, b in zip(mean, inputs))
        lft = tuple(a - b[:, :n] + b[:, n : 2 * n] for a, b in zip(mean, inputs))
        return self.prescribe(times, *r, left=lft, shoulder=tuple(b[:, 2 * n :] for b in inputs))

    def inputs(
        self,
        target: Sequence[float],
        target_left: Sequence[float] | None = None,
        offset: Sequence[float] | None = None,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(right, left, u, v) of :meth:`advance`'s arguments: both wings' targets, the
        mean filter's input u (their mean) and the input filter's v (half their
        difference, the offset, the shoulder targets of both sides)."""
        right = np.asarray(target, dtype=float)
        left = right if target_left is None else np.asarray(target_left, dtype=float)
        sh = np.asarray(self.shoulder_target, dtype=float)
        off = np.zeros(len(self.names)) if offset is None else np.asarray(offset, dtype=float)
        u = 0.5 * (right + left)
        v = np.concatenate([0.5 * (right - left), off, sh, sh])
        return right, left, u, v

    @property
    def output(self) -> np.ndarray:
        """The table's smoothed wingbeat parameters now (the mean of both wings)."""
        return self.filter.output

    @property
    def shoulder_now(self) -> np.ndarray:
        """The smoothed symmetric shoulder offsets (sweep, dihedral) now (rad)."""
        return self.input_filter.output[-4:-2].copy()

    def _joints(self, times, p, dp, ddp, shoulder=None):
        omega = self.bird.omega
        cols = {n: p[:, i] for i, n in enumerate(self.names)}
        rates = {n: dp[:, i] for i, n in enumerate(self.names)}
        accs = {n: ddp[:, i] for i, n in enumerate(self.names)}
        out = joint_derivatives(self.kin, self.bird, cols, rates, accs, omega * times, omega)
        if shoulder is not None:
            for d, v in zip(out, shoulder):
                for j, (joint, sign) in enumerate(SHOULDER_OFFSETS):
                    d[joint] = np.asarray(d.get(joint, 0.0)) + sign * v[:, j]
        return out

    def prescribe(
        self,
        times: np.ndarray,
        p: np.ndarray,
        dp: np.ndarray,
        ddp: np.ndarray,
        *,
        left: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
        shoulder: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    ) -> Prescription:
        """qpos/qvel/qacc of the wings (and, for the posed mode, the torso orientation at
        the table's pitch) for parameters p(t) (T, nP); ``left`` the left wing's p, p',
        p'' when they differ."""
        t = len(times)
        sw_r = sw_l = None
        if shoulder is not None and any(a.any() for a in shoulder):  # np.any's answer
            sw_r = tuple(a[:, :2] for a in shoulder)
            sw_l = tuple(a[:, 2:] for a in shoulder)
        if left is not None and sw_r is None:
            # np.array_equal's answer (same shape, every entry ==), without its wrapper
            if all(x.shape == y.shape and (x == y).all() for x, y in zip(left, (p, dp, ddp))):
                left = None
        same = left is None and sw_r is None
        if not same and left is None:
            left = (p, dp, ddp)
        rows = fast_prescription.wing_rows(
            self.m, self.kin, self.bird, times, p, dp, ddp, left, None if sw_r is None else shoulder
        )
        if rows is not None:  # the same rows, compiled (birdsim.flight.fast_prescription)
            return self._finish(*rows, p, dp, ddp, left)
        if same:
            right_joints, left_joints = self._joints(times, p, dp, ddp, sw_r), None
        else:
            # both wings in one pass (every operation is per sample: the same numbers as
            # two passes, at half the per-call cost)
            both = self._joints(
                np.concatenate([times, times]),
                *(np.concatenate([a, b]) for a, b in zip((p, dp, ddp), left)),
                None if sw_r is None else tuple(np.concatenate(ab) for ab in zip(sw_r, sw_l)),
            )
            right_joints = tuple({k: v[:t] for k, v in d.items()} for d in both)
            left_joints = tuple({k: v[t:] for k, v in d.items()} for d in both)
        qpos, qvel, qacc = wing_arrays(self.m, *right_joints, samples=t, left=left_joints)
        return self._finish(qpos, qvel, qacc, p, dp, ddp, left)

    def _finish(self, qpos, qvel, qacc, p, dp, ddp, left) -> Prescription:
        """The torso's rows (posed: the table's pitch) and the Prescription."""
        k = self.pitch_index
        set_root(self.m, qpos, qvel, pitch=p[:, k], pitch_rate=dp[:, k])
        qacc[:, 3:6] = 0.0
        qacc[:, 4] = -ddp[:, k]  # pitch nose up is a rotation about MuJoCo -y
        return Prescription(
            qpos, qvel, qacc, p, p[:, k].copy(), None if left is None else np.array(left[0])
        )


__all__ = ["SHOULDER_OFFSETS", "CascadeFilter", "Prescription", "WingbeatSchedule"]
