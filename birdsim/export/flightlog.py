"""Reading a free-flight log (``birdsim fly --out LOG.npz``) into export frames.

The log format (issue 9, item 6; docs/export.md): per sample (at least 32 per wingbeat)
arrays ``t`` (the bird's time units), ``x``, ``z``, ``vx``, ``vz`` (body origin; x forward,
z UP, the bird's length units), ``x_ref``, ``z_ref``, ``pitch`` (rad, nose up), each
wingbeat parameter by its table name, ``Fx_demand``, ``Fz_demand`` (table units, right
wing + body drag), ``V_air``, ``saturated``, ``pitch_moment``; scalars ``mass``,
``gravity``, ``model``, ``bird`` (the bird's TOML text) and ``omega`` (rad per time unit).
An optional ``phase`` array (the wingbeat phase, rad) is used when present; otherwise the
phase is ``omega t`` (the playback's phase-continuous clock).

The export samples the log at its own frame rate: positions, pitch and parameters are
interpolated linearly between log samples, and the wings are re-posed from the
interpolated parameters at the exact phase, so the flap is not flattened by a coarse
log.  Achieved force: the wingbeat mean of the logged parameters at ``V_air`` (table units).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.export.frames import ExportError, FrameSequence, achieved_forces, check_fps, frame_count, time_per_second
from birdsim.physics.bird import Bird

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

#: Arrays and scalars every birdsim flight log has (what the reader relies on).
REQUIRED_ARRAYS = ("t", "x", "z", "pitch")
REQUIRED_SCALARS = ("model", "bird", "omega")
OPTIONAL_COLUMNS = ("Fx_demand", "Fz_demand", "V_air", "vx", "vz", "x_ref", "z_ref", "saturated", "pitch_moment")


@dataclass(frozen=True)
class FlightLog:
    """A flight log as read: the model, the bird and every per-sample array."""

    path: Path
    model: str
    bird: Bird
    arrays: dict[str, np.ndarray]

    @property
    def t(self) -> np.ndarray:
        return self.arrays["t"]


def _not_a_log(path: Path, why: str) -> ExportError:
    return ExportError(f"SOURCE {str(path)!r} is not a birdsim flight log ({why}); allowed: a .npz written by `birdsim fly --out`")


def read_flight_log(path: str | Path) -> FlightLog:
    """Read and check a flight log.

    Args:
        path: the ``.npz`` file.

    Returns:
        The log.

    Raises:
        ExportError: a missing file, a file that is not an npz, or a log from another
            program (a required array or scalar missing, lengths that disagree, times
            that do not increase, NaN).
    """
    from birdsim.physics.kinematics import get_model

    path = Path(path)
    if not path.is_file():
        raise ExportError(f"SOURCE {str(path)!r} does not exist; allowed: a preset, a manoeuvre .toml or a flight log .npz")
    try:
        with np.load(path, allow_pickle=False) as z:
            data = {k: z[k] for k in z.files}
    except (OSError, ValueError) as exc:
        raise _not_a_log(path, f"not a readable npz: {exc}") from None
    for key in REQUIRED_ARRAYS + REQUIRED_SCALARS:
        if key not in data:
            raise _not_a_log(path, f"no {key!r}")
    try:
        model = get_model(str(data["model"])).name
    except BirdsimError:
        raise _not_a_log(path, f"model {str(data['model'])!r} is unknown") from None
    try:
        bird = Bird.from_dict(tomllib.loads(str(data["bird"])))
    except (tomllib.TOMLDecodeError, BirdsimError, TypeError) as exc:
        raise _not_a_log(path, f"its 'bird' is not a bird TOML: {exc}") from None
    km = get_model(model)
    arrays: dict[str, np.ndarray] = {}
    n = np.shape(data["t"])[0] if np.ndim(data["t"]) == 1 else -1
    if n < 2:
        raise _not_a_log(path, "'t' is not a 1-D array of at least two samples")
    for key in REQUIRED_ARRAYS + km.param_names + tuple(k for k in OPTIONAL_COLUMNS if k in data) + (("phase",) if "phase" in data else ()):
        if key not in data:
            raise _not_a_log(path, f"no {key!r} (a parameter of model {model})")
        a = np.asarray(data[key], dtype=float)
        if a.shape != (n,):
            raise _not_a_log(path, f"{key!r} has shape {a.shape}, 't' has ({n},)")
        if key != "saturated" and not np.all(np.isfinite(a)):
            raise _not_a_log(path, f"{key!r} holds NaN or infinity")
        arrays[key] = a
    if np.any(np.diff(arrays["t"]) <= 0):
        raise _not_a_log(path, "'t' does not increase")
    if not np.isclose(float(data["omega"]), bird.omega, rtol=1e-9):
        raise _not_a_log(path, f"omega {float(data['omega']):g} is not its bird's {bird.omega:g}")
    return FlightLog(path, model, bird, arrays)


def frames_from_log(
    log: FlightLog,
    *,
    fps: float = 30.0,
    beat_rate: float | None = None,
    metres_per_unit: float = 1.0,
) -> FrameSequence:
    """Export frames of a flight log at ``fps`` (see the module docstring).

    Args:
        log: the log (:func:`read_flight_log`).
        fps: frames per second of animation.
        beat_rate: wingbeats per second of animation (default: real time for an SI bird,
            2 for the seed bird).
        metres_per_unit: metres per bird length unit.

    Returns:
        The frames; frame 0 is the log's first sample.
    """
    from birdsim.flight.playback import joint_series
    from birdsim.mujoco.driver import set_root, wing_arrays
    from birdsim.mujoco.model import build_model
    from birdsim.physics.kinematics import get_model

    fps = check_fps(fps)
    bird, km, a = log.bird, get_model(log.model), log.arrays
    per_s = time_per_second(bird, beat_rate)
    t0, t1 = float(a["t"][0]), float(a["t"][-1])
    n = frame_count(t1 - t0, fps, per_s)
    time = t0 + np.arange(n) * (per_s / fps)
    time = time[time <= t1 + 1e-12]
    at = {k: np.interp(time, a["t"], v) for k, v in a.items() if k != "t"}
    params = {p: at[p] for p in km.param_names}
    rates = {p: np.interp(time, a["t"], np.gradient(a[p], a["t"])) for p in km.param_names}
    phase = at["phase"] if "phase" in at else bird.omega * time
    angles, ang_rates = joint_series(km, bird, params, rates, phase, bird.omega)
    m = build_model(km.name, bird)
    qpos, qvel, _ = wing_arrays(m, angles, ang_rates, samples=len(time))
    pos_seed = np.stack([at["x"], np.zeros_like(time), -at["z"]], axis=1)  # z up -> seed Z down
    set_root(m, qpos, qvel, pitch=at["pitch"], position_seed=pos_seed)
    forces = {k: at[k] for k in ("Fx_demand", "Fz_demand", "V_air") if k in at}
    if "V_air" in at:
        forces.update(achieved_forces(km.name, bird, params, at["V_air"]))
    return FrameSequence(
        model=km.name,
        bird=bird,
        fps=fps,
        time=time,
        qpos=qpos,
        params=params,
        forces=forces,
        source=f"flight log {log.path.name}",
        metres_per_unit=metres_per_unit,
    )


__all__ = ["FlightLog", "OPTIONAL_COLUMNS", "REQUIRED_ARRAYS", "REQUIRED_SCALARS", "frames_from_log", "read_flight_log"]
