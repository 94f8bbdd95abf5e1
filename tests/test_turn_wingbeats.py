"""The turning log's per-wingbeat decomposition (`scripts/turn_wingbeats.py`,
docs/turning.md "The pigeon's slow turns, episode by episode"): the path error along the
reference's heading, to its left and up, the saturation counts split by loop, the bank
about the heading against its command."""

from __future__ import annotations

import math

import numpy as np
import pytest
from script_module import load_script


@pytest.fixture(scope="module")
def tw():
    return load_script("turn_wingbeats")


def _log(psi: float, offset_left: float, up: float, bank: float, n: int = 128) -> dict:
    """Two wingbeats (omega 2 pi: one per time unit) along heading ``psi`` at speed 1, the
    bird ``offset_left`` to the left of the reference, ``up`` above it, banked ``bank``
    (rad, right wing down > 0: a rotation about the heading, MuJoCo quaternion)."""
    t = np.linspace(0.0, 2.0, n, endpoint=False)
    c, s = math.cos(psi), math.sin(psi)
    x_ref, y_ref = c * t, s * t
    # the bank about the heading: Rz(psi) Rx(bank) (right wing down: MuJoCo y, the left
    # wing, up)
    half_z, half_x = psi / 2, bank / 2
    qz = np.array([math.cos(half_z), 0, 0, math.sin(half_z)])
    qx = np.array([math.cos(half_x), math.sin(half_x), 0, 0])
    w1, x1, y1, z1 = qz
    w2, x2, y2, z2 = qx
    q = np.array(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ]
    )
    sat = np.zeros(n, dtype=bool)
    sat[n // 2 + 3 : n // 2 + 8] = True  # five in the second wingbeat
    att_sat = np.zeros(n, dtype=bool)
    att_sat[:2] = True
    return {
        "t": t,
        "omega": 2.0 * math.pi,
        "x_ref": x_ref,
        "y_ref": y_ref,
        "z_ref": np.zeros(n),
        "x": x_ref - s * offset_left,
        "y": y_ref + c * offset_left,
        "z": np.full(n, up),
        "quat": np.tile(q, (n, 1)),
        "bank_command": np.full(n, 0.5 * bank),
        "saturated": sat,
        "attitude_saturated": att_sat,
        "Fz_demand": -0.2 - 0.01 * t,
    }


@pytest.mark.parametrize("psi", [0.0, 2.0, -2.5])
def test_errors_are_in_the_heading_frame(tw, psi):
    rows = tw.wingbeat_rows(_log(psi, 0.03, -0.01, 0.4))
    assert len(rows) == 2
    for r in rows:
        assert r["along"] == pytest.approx(0.0, abs=1e-12)
        assert r["lateral"] == pytest.approx(0.03, abs=1e-12)
        assert r["up"] == pytest.approx(-0.01, abs=1e-12)
        assert r["err"] == pytest.approx(math.hypot(0.03, 0.01), abs=1e-12)


def test_bank_and_saturation_counts(tw):
    rows = tw.wingbeat_rows(_log(1.0, 0.0, 0.0, 0.4))
    # the bank about the heading read back (degrees), its command as logged
    assert rows[0]["bank"] == pytest.approx(math.degrees(0.4), abs=1e-9)
    assert rows[0]["cmd"] == pytest.approx(math.degrees(0.2), abs=1e-9)
    assert [r["psat"] for r in rows] == [0.0, 5.0]
    assert [r["asat"] for r in rows] == [2.0, 0.0]
    assert rows[1]["fz_min"] < rows[0]["fz_min"] < -0.2


@pytest.mark.parametrize("psi", [0.0, 2.0, -2.5])
@pytest.mark.parametrize("pitch_deg", [30.0, 80.0, 120.0])
def test_pitch_from_heading_reads_past_the_vertical(tw, psi, pitch_deg):
    """A body pitched nose up by ``pitch_deg`` about its own y axis on heading ``psi``
    reads ``pitch_deg``, 120 past the vertical too (the log's arcsine pitch reads 60)."""
    log = _log(psi, 0.0, 0.0, 0.0)
    # Rz(psi) then nose up: MuJoCo's y is the left wing, nose up is -pitch about it
    a, b = psi / 2, -math.radians(pitch_deg) / 2
    q = np.array(
        [math.cos(a) * math.cos(b), -math.sin(a) * math.sin(b),
         math.cos(a) * math.sin(b), math.sin(a) * math.cos(b)]
    )  # fmt: skip
    log["quat"] = np.tile(q, (len(log["t"]), 1))
    rows = tw.wingbeat_rows(log)
    for r in rows:
        assert r["pitch_max"] == pytest.approx(pitch_deg, abs=1e-9)
