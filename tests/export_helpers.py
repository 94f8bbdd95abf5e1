"""Shared pieces of the export tests: a short cruise flown by the kinematic playback and
independent references (the playback itself, MuJoCo's forward kinematics)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

FPS = 30
BEAT_RATE = 2.0  # wingbeats per second of animation: 15 frames per wingbeat
FRAMES_PER_BEAT = FPS / BEAT_RATE
SECONDS = 2.0
CHECK_FRAMES = (0, 17, 60)  # three frames where body positions are compared


@lru_cache(maxsize=None)
def cruise_frames(metres_per_unit: float = 1.0):
    from birdsim.export.frames import from_playback
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.tables.lookup import load_table

    return from_playback(
        get_manoeuvre("cruise"),
        load_table("tables/m4.npz"),
        model="m4",
        fps=FPS,
        beat_rate=BEAT_RATE,
        seconds=SECONDS,
        metres_per_unit=metres_per_unit,
    )


@lru_cache(maxsize=None)
def reference_body_position() -> np.ndarray:
    """(F, 3) torso position in the MuJoCo world straight from the playback (not via qpos)."""
    from birdsim.flight.manoeuvre import get_manoeuvre
    from birdsim.flight.playback import play
    from birdsim.physics.bird import Bird
    from birdsim.tables.lookup import load_table

    bird = Bird()
    n = int(SECONDS * FPS) + 1
    t_beats = np.arange(n) / FRAMES_PER_BEAT
    pb = play(get_manoeuvre("cruise"), load_table("tables/m4.npz"), t_beats, bird=bird, model="m4")
    return pb.position_seed * np.array([1.0, -1.0, -1.0])


def one_beat_per_period(series: np.ndarray, frames_per_beat: float) -> None:
    """Assert that ``series`` (one angle per frame) repeats every wingbeat and does not
    repeat sooner: period-shifted copies agree, half-period ones differ, and the strongest
    Fourier component is the wingbeat frequency."""
    k = int(round(frames_per_beat))
    assert abs(k - frames_per_beat) < 1e-9
    s = np.asarray(series, dtype=float)
    swing = s.max() - s.min()
    assert swing > 0.05, f"the joint hardly moves (swing {swing})"
    assert np.max(np.abs(s[k:] - s[:-k])) < 1e-3 * swing  # repeats after one wingbeat
    half = k // 2
    assert np.max(np.abs(s[half:] - s[:-half])) > 0.3 * swing  # not after half of one
    spec = np.abs(np.fft.rfft(s - s.mean()))
    freqs = np.fft.rfftfreq(len(s), d=1.0)
    assert abs(freqs[np.argmax(spec)] - 1.0 / frames_per_beat) <= 1.0 / len(s)
