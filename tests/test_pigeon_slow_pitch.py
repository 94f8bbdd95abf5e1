"""The pigeon's slow-flight pitch (issue 22, docs/free-body.md, "The pigeon's attitude,
fifth stage"): its error with the bird file's inertia (hover 7.5 degrees RMS, rocking 31
degrees peak to peak) is the rocking's, which scales as 1 / inertia, not the loop's
design, which is per unit inertia: the same loop on the same aerodynamics holds the
pigeon's hover within the issue's targets once the body is four times as heavy in
rotation (measured: 0.38 degrees, 0.0072 m, rocking 4.4 degrees).

Tolerances: the issue's targets (3 degrees RMS wingbeat-mean pitch after two wingbeats,
1.5 x the posed pigeon's hover RMS of 0.0060 m, no saturated sample); the rocking below 8
degrees (measured 4.4; the file's inertia: 31)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest


@pytest.mark.slow
def test_pigeon_hover_pitch_is_held_at_four_times_the_inertia():
    from birdsim.commands.fly import load_table_for
    from birdsim.flight.flightlog import log_arrays, summary
    from birdsim.flight.freeflight import fly
    from birdsim.flight.presets import PATH_PRESETS
    from birdsim.flight.simulate import SimConfig
    from birdsim.physics.bird import Bird

    bird = Bird.from_toml("models/pigeon.toml")
    heavy = dataclasses.replace(bird, body_inertia=tuple(4.0 * v for v in bird.body_inertia))
    table = load_table_for(bird, "m3", None)
    r = fly(PATH_PRESETS["hover"], table, heavy, "m3", config=SimConfig(attitude="free"))
    a = r.arrays
    n = 64
    beats = len(a["t"]) // n
    mean = lambda k: np.array([a[k][b * n : (b + 1) * n].mean() for b in range(beats)])  # noqa: E731
    err = (mean("pitch") - mean("pitch_command"))[2:]
    assert math.degrees(np.sqrt(np.mean(err**2))) < 3.0
    assert summary(log_arrays(r, "hover"))["rms_error_after_start"] <= 1.5 * 0.0060
    assert not np.any(a["attitude_saturated"]) and not np.any(a["saturated"])
    rocking = [np.ptp(a["pitch"][b * n : (b + 1) * n]) for b in range(2, beats)]
    assert math.degrees(float(np.median(rocking))) < 8.0
    assert r.meta["root_applied_max"] == 0.0
