"""The common frame source of every export format: a per-frame state sequence.

A :class:`FrameSequence` is what a consumer (USD, BVH, CSV) needs of a flight, sampled at
the export's frame rate:

* ``time`` (F,): the bird's time at each frame, in the bird's time units (seconds for an
  SI bird such as the pigeon; 1/omega for the non-dimensional seed bird);
* ``qpos`` (F, nq): MuJoCo generalised positions of the MJCF that
  :func:`birdsim.mujoco.model.build_model` builds for ``model`` and ``bird`` (free root
  in the MuJoCo world: x forward, y left, z up, the bird's length units; per wing a heave
  slide, a shoulder ball, two wrist hinges; docs/mujoco.md);
* ``params``: each wingbeat parameter per frame (radians), by its table name;
* ``forces``: per-frame force columns when known (``Fx_demand``, ``Fz_demand``,
  ``Fx_achieved``, ``Fz_achieved``: the dissertation's force, the right wing plus body
  drag, seed earth axes, Fz < 0 up, in table force units rho omega^2 s^3 c) and speeds
  (``V_demand``, ``V_air``, in omega s).

Two sources fill it: :func:`from_playback` (a preset or manoeuvre file flown by the
kinematic playback, exactly as ``birdsim render`` flies it) and
:func:`birdsim.export.flightlog.frames_from_log` (a free-flight log ``.npz``).

Animation time.  Frame ``k`` is shown at ``k / fps`` seconds of animation. An SI bird
plays in real time (one time unit of the bird per second); the non-dimensional seed bird
(omega = 1) plays like ``birdsim render``, ``beat_rate`` wingbeats per second (default 2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird

#: Wingbeats per second of animation for the non-dimensional seed bird (as ``birdsim render``).
DEFAULT_BEAT_RATE = 2.0
#: Longest export (seconds of animation) and largest frame rate accepted.
MAX_SECONDS = 3600.0
MAX_FPS = 240


class ExportError(BirdsimError):
    """A bad export option or source."""


@dataclass(frozen=True)
class FrameSequence:
    """A flight sampled at the export frames (see the module docstring for units)."""

    model: str
    bird: Bird
    fps: float
    time: np.ndarray  # (F,) bird time units
    qpos: np.ndarray  # (F, nq) MuJoCo qpos of build_model(model, bird)
    params: dict[str, np.ndarray] = field(default_factory=dict)
    forces: dict[str, np.ndarray] = field(default_factory=dict)
    source: str = ""
    metres_per_unit: float = 1.0

    def __post_init__(self) -> None:
        n = len(self.time)
        if n < 1 or self.qpos.shape[0] != n:
            raise ExportError(
                f"frame source: {n} times but qpos has {self.qpos.shape[0]} rows; allowed: one row per frame"
            )
        if not (np.all(np.isfinite(self.time)) and np.all(np.isfinite(self.qpos))):
            raise ExportError(
                f"frame source {self.source!r} holds NaN or infinite values; allowed: finite states"
            )
        for name, col in {**self.params, **self.forces}.items():
            if np.shape(col) != (n,):
                raise ExportError(
                    f"frame source column {name!r} has shape {np.shape(col)}; allowed: ({n},)"
                )

    @property
    def frames(self) -> int:
        return len(self.time)

    @property
    def time_per_second(self) -> float:
        """Bird time units per second of animation."""
        if self.frames < 2:
            return 1.0
        return float((self.time[-1] - self.time[0]) / ((self.frames - 1) / self.fps))

    @property
    def body_position(self) -> np.ndarray:
        """(F, 3) torso origin in the MuJoCo world (x forward, y left, z up), bird length units."""
        return self.qpos[:, 0:3]

    @property
    def body_quat(self) -> np.ndarray:
        """(F, 4) torso orientation (w, x, y, z) in the MuJoCo world."""
        return self.qpos[:, 3:7]


def check_fps(fps: object) -> float:
    """``fps`` as a float in [1, MAX_FPS]; one line naming --fps otherwise."""
    try:
        v = float(fps)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ExportError(
            f"--fps {fps!r} is not a number; allowed: frames per second in [1, {MAX_FPS}]"
        ) from None
    if not (math.isfinite(v) and 1 <= v <= MAX_FPS):
        raise ExportError(f"--fps {fps!r} is invalid; allowed: frames per second in [1, {MAX_FPS}]")
    return v


def is_non_dimensional(bird: Bird) -> bool:
    """Whether ``bird`` is in the seed bird's non-dimensional units (omega = 1)."""
    return bird.omega == 1.0 and bird.rho == 1.0


def time_per_second(bird: Bird, beat_rate: float | None = None) -> float:
    """Bird time units shown per second of animation: real time for an SI bird (unless
    ``beat_rate`` wingbeats per second is asked), ``beat_rate`` (default 2) wingbeats per
    second for the non-dimensional seed bird."""
    if beat_rate is None:
        if not is_non_dimensional(bird):
            return 1.0
        beat_rate = DEFAULT_BEAT_RATE
    if not (
        isinstance(beat_rate, (int, float)) and math.isfinite(beat_rate) and 0 < beat_rate <= 100
    ):
        raise ExportError(
            f"--beat-rate {beat_rate!r} is invalid; allowed: wingbeats per second in (0, 100]"
        )
    return float(beat_rate) * bird.period


def frame_count(duration_time: float, fps: float, per_second: float) -> int:
    """Frames covering ``duration_time`` bird time units (both ends included)."""
    seconds = duration_time / per_second
    if not (math.isfinite(seconds) and 0 < seconds <= MAX_SECONDS):
        raise ExportError(
            f"the export would last {seconds:g} s of animation; allowed: (0, {MAX_SECONDS:g}] s (give --seconds or --beat-rate)"
        )
    return int(math.floor(seconds * fps + 1e-9)) + 1


def achieved_forces(
    model: str, bird: Bird, params: dict[str, np.ndarray], speed: np.ndarray
) -> dict[str, np.ndarray]:
    """Wingbeat-mean force of each frame's parameters at ``speed`` (quasi-steady), in table
    units (the reduced bird): the dissertation's right wing plus body drag, Fz < 0 up."""
    from birdsim.physics.cycle import evaluate_cycle
    from birdsim.physics.units import reduced_bird

    cyc = evaluate_cycle(
        model, params, np.clip(speed, 0.0, None), bird=reduced_bird(bird), n=32, check_bounds=False
    )
    return {
        "Fx_achieved": np.asarray(cyc.mean.Fx, dtype=float),
        "Fz_achieved": np.asarray(cyc.mean.Fz, dtype=float),
    }


def from_playback(
    manoeuvre: object,
    table: object,
    *,
    bird: Bird | None = None,
    model: str | None = None,
    fps: float = 30.0,
    beat_rate: float | None = None,
    seconds: float | None = None,
    metres_per_unit: float = 1.0,
) -> FrameSequence:
    """A manoeuvre flown by the kinematic playback (as ``birdsim render`` flies it).

    Args:
        manoeuvre: a :class:`birdsim.flight.manoeuvre.Manoeuvre`.
        table: its lookup table (model checked against ``model``).
        bird: the bird (default: the table's, else the seed bird).
        model: kinematic model name (default: the table's).
        fps: frames per second of animation.
        beat_rate: wingbeats per second of animation (default: real time for an SI bird,
            2 for the seed bird).
        seconds: animation length (default: the whole manoeuvre).
        metres_per_unit: metres per bird length unit (written into USD; 1 for both
            shipped birds: the seed bird's semispan is drawn as 1 m).

    Returns:
        The frames, times in the bird's time units.

    Raises:
        ExportError: a bad fps, beat rate or length.
    """
    from birdsim.flight.playback import play
    from birdsim.mujoco.driver import set_root, wing_arrays
    from birdsim.mujoco.model import build_model
    from birdsim.render.renderer import perch_seed_position

    fps = check_fps(fps)
    bird = bird or getattr(table, "bird", None) or Bird()
    per_s = time_per_second(bird, beat_rate)
    if seconds is not None:
        if not (
            isinstance(seconds, (int, float))
            and math.isfinite(seconds)
            and 0 < seconds <= MAX_SECONDS
        ):
            raise ExportError(
                f"--seconds {seconds!r} is invalid; allowed: a number in (0, {MAX_SECONDS:g}]"
            )
        duration = seconds * per_s
    else:
        duration = float(manoeuvre.duration) * bird.period  # type: ignore[attr-defined]
    n = frame_count(duration, fps, per_s)
    time = np.arange(n) * (per_s / fps)
    t_beats = time / bird.period
    kin = play(manoeuvre, table, t_beats[:1], bird=bird, model=model).model  # type: ignore[arg-type]
    pb = play(
        manoeuvre,
        table,
        t_beats,
        bird=bird,
        model=model,
        perch_seed=perch_seed_position(kin.name, bird),
    )  # type: ignore[arg-type]
    m = build_model(kin.name, bird)
    qpos, qvel, _ = wing_arrays(m, pb.angles, pb.rates, samples=n)
    set_root(
        m,
        qpos,
        qvel,
        pitch=pb.pitch,
        position_seed=pb.position_seed,
        velocity_seed=pb.velocity_seed,
        pitch_rate=pb.pitch_rate,
    )
    forces = {
        "Fx_demand": pb.demand["Fx"],
        "Fz_demand": pb.demand["Fz"],
        "V_demand": pb.demand["V"],
        "V_air": pb.demand_used["V"],
    }
    forces.update(achieved_forces(kin.name, bird, pb.params, pb.demand_used["V"]))
    name = getattr(manoeuvre, "name", "manoeuvre")
    return FrameSequence(
        model=kin.name,
        bird=bird,
        fps=fps,
        time=time,
        qpos=qpos,
        params={k: np.asarray(v, dtype=float) for k, v in pb.params.items()},
        forces={k: np.asarray(v, dtype=float) for k, v in forces.items()},
        source=f"manoeuvre {name} (kinematic playback)",
        metres_per_unit=metres_per_unit,
    )


__all__ = [
    "DEFAULT_BEAT_RATE",
    "ExportError",
    "FrameSequence",
    "achieved_forces",
    "check_fps",
    "from_playback",
    "is_non_dimensional",
    "time_per_second",
]
