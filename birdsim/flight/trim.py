"""The trimmed start of a free flight: one probe wingbeat measures what the start state
must be moved by so that the first wingbeat flies the reference's mean velocity,
position -- and, with the attitude free, a mean pitch at the command and no mean
rotation rate (reduced units)."""

from __future__ import annotations

from typing import Any

import numpy as np

from birdsim.flight.body_attitude import euler_zyx
from birdsim.flight.flight_arrays import new_samples
from birdsim.flight.simulate import FreeBird, SimConfig


def sample_reference(reference: Any, t: np.ndarray) -> dict[str, np.ndarray]:
    """x, z, vx, vz, ax, az of ``reference`` at reduced times ``t`` (vectorised when the
    reference has ``sample``, as FlightPath does)."""
    t = np.asarray(t, dtype=float)
    fn = getattr(reference, "sample", None)
    if fn is not None:
        s = fn(t)
        out = {}
        for k in ("x", "z", "vx", "vz", "ax", "az"):
            a = s[k]
            ok = type(a) is np.ndarray and a.dtype == np.float64 and a.shape == t.shape
            out[k] = a if ok else np.broadcast_to(np.asarray(a, dtype=float), t.shape)
        return out
    states = [reference.state(float(ti)) for ti in t]
    return {
        k: np.array([getattr(st, k) for st in states], dtype=float)
        for k in ("x", "z", "vx", "vz", "ax", "az")
    }


def trim_start(
    fb: FreeBird,
    reference: Any,
    params: np.ndarray,
    pos0: np.ndarray,
    vel0: np.ndarray,
    config: SimConfig,
    every: int,
) -> tuple[np.ndarray, np.ndarray, list, np.ndarray]:
    """The start state whose first wingbeat (at the starting wingbeat, no feedback)
    has the reference's mean velocity and mean position.

    A wingbeat's force oscillates; started at a phase where it is not at its mean, the
    body would carry a velocity offset of the oscillation's integral for ever.  One probe
    wingbeat measures the mean velocity and position errors; the start is moved by them
    (exact for the oscillating part, which does not depend on the start state to first
    order).  The filter is in steady state, so the probe leaves the schedule unchanged.
    Returns the start position and velocity and the error samples (x, z) of the
    corrected probe, the wingbeat "before" the start for the controller's window, and
    the wingbeat-mean acceleration the reference asks for minus the one flown (x, z).
    """
    n = config.steps_per_beat
    h = fb.h
    times = np.arange(n) * h
    pres = fb.schedule.advance(params, times, 0.0, n * h)
    omega0, d_pitch0 = getattr(fb, "start_rotation", (None, 0.0))
    fb.start(pos0, vel0, pres, pitch=float(pres.pitch[0]) - d_pitch0, omega_body=omega0)
    rec: list = []
    p_start = fb.P.copy()
    fb.step_many(pres, np.zeros(3), rec, every)
    a_flown = (fb.P - p_start) / (fb.total_mass * n * h)
    t, qpos, qvel, moment = _probe_samples(fb, rec)
    pos, vel = np.array(qpos[:, :3]), np.array(qvel[:, :3])
    ref = sample_reference(reference, t)
    zero = np.zeros_like(t)
    ref_pos = np.stack([ref["x"], zero, ref["z"]], axis=1)
    ref_vel = np.stack([ref["vx"], zero, ref["vz"]], axis=1)
    dv = (vel - ref_vel).mean(axis=0)
    # with the start velocity lowered by dv, the positions lose dv * t
    dx = (pos - ref_pos - dv[None, :] * t[:, None]).mean(axis=0)
    dv[1] = dx[1] = 0.0
    fb.time = 0.0
    fb.projection_max = 0.0
    e_pos = ref_pos - (pos - dx[None, :] - dv[None, :] * t[:, None])
    e_vel = ref_vel - (vel - dv[None, :])
    # per sample (x, z) of each error and the airspeed: (e_pos[k, [0, 2]], ...) by rows
    history = list(zip(e_pos[:, [0, 2]], e_vel[:, [0, 2]], (vel[:, 0] - dv[0]).tolist()))
    a_ref = np.array([ref["ax"].mean(), ref["az"].mean()])
    # the same for the free body's rotation: started at the table's pitch with no rate,
    # the within-beat rocking would leave a mean rate and pitch offset (MuJoCo body axes)
    omega = np.array(qvel[:, 3:6]).mean(axis=0)
    pitch = euler_zyx(np.array(qpos[:, 3:7]))[:, 1]
    pitch_rate = -omega[1]  # nose up is about MuJoCo -y
    d_pitch = float((pitch - pres.pitch[0] - pitch_rate * t).mean())
    fb.start_rocking = float(np.ptp(pitch - pitch_rate * t))  # the within-beat pitch swing
    # the wingbeat-mean aerodynamic moment about the centre of mass with every attitude
    # input at zero (seed body axes): what the attitude loop's integral starts from
    fb.start_moment = moment.mean(axis=0)
    old_omega, old_pitch = getattr(fb, "start_rotation", (np.zeros(3), 0.0))
    fb.start_rotation = (
        (np.zeros(3) if old_omega is None else old_omega) - omega,
        old_pitch + d_pitch,
    )
    return pos0 - dx, vel0 - dv, history, a_ref - a_flown[[0, 2]]


def _probe_samples(fb: FreeBird, rec: list) -> tuple[np.ndarray, ...]:
    """(t, qpos, qvel, moment) of a probe's step records ``rec`` (one ``step_many``): the
    compiled step loop's own arrays where it left them (the records' rows are views of
    them: the same numbers), else made of the records."""
    blocks: list = []
    t, qpos, qvel = new_samples(fb, rec, 0, blocks)
    if blocks[0] is not None:
        return t, qpos, qvel, np.array(blocks[0][3][:, 0:3])
    return t, qpos, qvel, np.array([r[3] for r in rec])


#: The free body's trim: probes until the bias they measure changes by less than this
#: fraction of gravity (a twentieth of the path integral's bound,
#: :data:`birdsim.flight.path_integral.INTEGRAL_LIMIT`), at most ROTATION_PROBES probes.
BIAS_TOL = 0.005
ROTATION_PROBES = 6


def trim_rotation(
    fb: FreeBird,
    reference: Any,
    params: np.ndarray,
    pos0: np.ndarray,
    vel0: np.ndarray,
    config: SimConfig,
    every: int,
) -> tuple[np.ndarray, np.ndarray, list, np.ndarray]:
    """The free body's :func:`trim_start` repeated, each probe started from the rotation
    the previous one measured (``fb.start_rotation``: the rate and pitch offset that put
    the body on its periodic orbit), until the bias it returns (the wingbeat-mean
    acceleration the reference asks for minus the one flown, x and z) changes by less
    than :data:`BIAS_TOL` times gravity (at most :data:`ROTATION_PROBES` probes); returns
    the last probe's :func:`trim_start` answer.  A probe whose body still turns tilts the wings' force with it: its
    bias is that rotation's, not the table's mismatch (the pigeon's hover: x 0.0027
    after two probes, 1e-5 converged; docs/free-body.md, "ninth stage")."""
    last = None
    for _ in range(ROTATION_PROBES):
        out = trim_start(fb, reference, params, pos0, vel0, config, every)
        if last is not None and np.abs(out[3] - last).max() < BIAS_TOL * fb.red.gravity:
            break
        last = out[3]
    return out


__all__ = ["BIAS_TOL", "ROTATION_PROBES", "sample_reference", "trim_rotation", "trim_start"]
