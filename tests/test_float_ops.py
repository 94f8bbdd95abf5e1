"""numpy's operations on one float without the array machinery (the control update's
scalars): the same bits as numpy's, on random values and the special ones."""

from __future__ import annotations

import numpy as np

from birdsim.flight.demand import air_path_angle
from birdsim.flight.float_ops import clip_float

SPECIAL = [0.0, -0.0, 0.2, -0.2, 1e-300, -1e-300, np.inf, -np.inf, np.nan]


def _same(a, b) -> bool:
    return bool(np.array_equal(a, b, equal_nan=True) and np.signbit(a) == np.signbit(b))


def test_clip_float_is_np_clip():
    rng = np.random.default_rng(7)
    xs = rng.normal(0.0, 1.0, 20_000).tolist() + SPECIAL
    for lo, hi in ((-0.5, 0.5), (0.0, 1.0), (-1.0, -0.0), (-np.inf, 0.3), (0.3, -0.3)):
        for x in xs:
            assert _same(clip_float(x, lo, hi), float(np.clip(x, lo, hi))), (x, lo, hi)


def test_air_path_angle_of_floats_is_the_array_path():
    """Below 0.2 forward airspeed the fade's square is the numpy scalar's power (the C
    library's ``pow``), which differs from ``f * f`` in the last bit on some values."""
    rng = np.random.default_rng(5)
    vx = rng.normal(0.0, 0.15, 20_000).tolist() + rng.normal(0.0, 1.0, 5_000).tolist()
    vz = rng.normal(0.0, 0.2, 25_000).tolist()
    for a, b in [*zip(vx, vz), *((s, t) for s in SPECIAL for t in SPECIAL)]:
        assert _same(air_path_angle(a, b), air_path_angle(np.array(a), np.array(b))), (a, b)


def test_demand_of_floats_is_the_array_path():
    """The controller's table demand of floats (numpy scalars, no 0-d arrays): the same
    bits as of 0-d arrays, level and climbing tables."""
    from birdsim.flight.demand import demand_from_acceleration
    from birdsim.physics.bird import Bird
    from birdsim.physics.units import reduced_bird

    bird = reduced_bird(Bird.from_toml("models/seed-bird.toml"))
    rng = np.random.default_rng(9)
    for _ in range(3000):
        ax, az, vz = rng.normal(0.0, 0.01, 3).tolist()
        vx, pitch = float(rng.uniform(-0.2, 1.2)), float(rng.normal(0.2, 0.3))
        for climb in (False, True):
            a = demand_from_acceleration(ax, az, vx, vz, bird, pitch, table_climb=climb)
            args = (np.array(ax), np.array(az), np.array(vx), np.array(vz))
            b = demand_from_acceleration(*args, bird, np.array(pitch), table_climb=climb)
            assert all(_same(x, y) for x, y in zip(a, b)), (ax, az, vx, vz, pitch)
