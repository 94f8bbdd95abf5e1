import csv

import numpy as np
from export_helpers import cruise_frames, reference_body_position

from birdsim.export.csv import write_csv


def test_csv_rows_and_columns(tmp_path):
    fr = cruise_frames()
    path = write_csv(fr, tmp_path / "c.csv")
    rows = list(csv.DictReader(path.open()))
    assert len(rows) == fr.frames
    names = rows[0].keys()
    for col in (
        "time",
        "x",
        "y",
        "z",
        "qw",
        "qx",
        "qy",
        "qz",
        "r_shoulder_qw",
        "r_wrist_flap",
        "l_wrist_twist",
        "r_heave",
        "pitch",
        "flap_amp",
        "wrist_lag",
        "Fx_demand",
        "Fz_demand",
        "Fx_achieved",
        "Fz_achieved",
        "V_air",
    ):
        assert col in names
    ref = reference_body_position()
    for k in (0, 30, 60):
        assert np.allclose([float(rows[k][c]) for c in "xyz"], ref[k], atol=1e-8)
    q = np.array([[float(r[f"r_shoulder_q{c}"]) for c in "wxyz"] for r in rows])
    assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-8)
