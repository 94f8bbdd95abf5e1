"""The pigeon's free cruise through a one-wingbeat gust, as ``scripts/free_targets.py
--gusts`` flies it (shared by the gust tests of the flown-pitch gate and the path loop's
switch)."""

from __future__ import annotations

import math

import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight import freeflight
from birdsim.flight.gust import parse_gust
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS
from birdsim.flight.simulate import SimConfig
from birdsim.physics.bird import Bird


def gust_errors(wind: tuple[float, float, float]) -> np.ndarray:
    """The pigeon's cruise with a one-wingbeat gust of ``wind`` (fractions of the cruise
    speed 0.5 omega s; x forward, y left, z up) from wingbeat 3: the largest path error
    (semispans) per wingbeat, 16 wingbeats."""
    bird = Bird.from_toml("models/pigeon.toml")
    v = 0.5 * bird.semispan * 2.0 * math.pi / bird.period
    table = load_table_for(bird, DEMO_MODEL, None)
    g = parse_gust("3:1:" + ":".join(f"{w * v:g}" for w in wind))
    r = freeflight.fly(PATH_PRESETS["cruise"], table, bird, DEMO_MODEL, beats=16.0,
                       gusts=[g], config=SimConfig(attitude="free"))  # fmt: skip
    a = r.arrays
    n = int(round(len(a["t"]) / (a["t"][-1] / (2 * math.pi))))
    err = np.sqrt((a["x_ref"] - a["x"]) ** 2 + a["y"] ** 2 + (a["z_ref"] - a["z"]) ** 2)
    return np.array([err[b * n : (b + 1) * n].max() for b in range(len(a["t"]) // n)])
