"""The pitch row's slow-to-fast allocation (birdsim.flight.attitude_pitch): the shoulders'
offsets deliver the low-passed demand, the tail elevation the rest, the shoulders what
the tail cannot.  Tolerances: the allocation's regularisation (LAMBDA = 1e-4 on the
inputs scaled by their bounds) costs each least-squares stage up to about 1e-4 of its
moment, so delivered moments are checked to 1e-4 relative; the tail's share, a plain
division, to round-off where the shoulders' stage is exact."""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.attitude import INPUTS, LAMBDA
from birdsim.flight.attitude_pitch import pitch_allocation

NAMES = [i[0] for i in INPUTS]
SWEEP, TAIL, DIH = NAMES.index("sweep"), NAMES.index("tail_elevation"), NAMES.index("dihedral")
# the pigeon's cruise pitch row (table units per rad) and the inputs' bounds
ROW = np.zeros(len(INPUTS))
ROW[[SWEEP, TAIL, DIH]] = (-0.1498, 0.0206, -0.06)
HI = np.array([0.15, 0.15, 0.3, math.radians(30), math.radians(30), 0.15, 0.3])


def test_wings_take_the_slow_part_and_the_tail_the_rest():
    u, miss, active = pitch_allocation(ROW, 0.008, 0.005, -HI, HI, LAMBDA)
    wings = ROW[SWEEP] * u[SWEEP] + ROW[DIH] * u[DIH]
    assert abs(wings - 0.005) < 1e-4 * 0.005  # the slow part, by the shoulders
    assert abs(float(ROW @ u) - 0.008) < 1e-12  # the tail takes exactly the rest
    assert miss < 1e-12 and not active and u[TAIL] > 0
    others = [i for i in range(len(INPUTS)) if i not in (SWEEP, TAIL, DIH)]
    assert np.all(u[others] == 0.0)


def test_what_the_tail_cannot_deliver_goes_back_to_the_wings():
    # the tail's most: 0.0206 x 30 deg = 0.0108; asked 0.02 beyond the slow part
    u, miss, active = pitch_allocation(ROW, 0.025, 0.005, -HI, HI, LAMBDA)
    assert u[TAIL] == HI[TAIL] and active
    assert abs(float(ROW @ u) - 0.025) < 1e-4 * 0.025 and miss < 1e-4 * 0.025
    # no tail authority (hover: no air at the tail): the wings deliver everything
    still = ROW.copy()
    still[TAIL] = 0.0
    u, miss, _ = pitch_allocation(still, 0.01, 0.004, -HI, HI, LAMBDA)
    assert u[TAIL] == 0.0 and abs(float(still @ u) - 0.01) < 1e-4 * 0.01


def test_beyond_every_bound_the_miss_is_reported():
    most = abs(ROW[SWEEP]) * HI[SWEEP] + ROW[TAIL] * HI[TAIL] + abs(ROW[DIH]) * HI[DIH]
    u, miss, active = pitch_allocation(ROW, 2 * most, most, -HI, HI, LAMBDA)
    assert active
    assert abs(miss - most) < 1e-3 * most
    assert np.all(np.abs(u) <= HI + 1e-12)
