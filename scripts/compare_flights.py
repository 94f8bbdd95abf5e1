"""Flights before and after a change: every log array of a set of preset flights.

    PYTHONPATH=$PWD .venv/bin/python scripts/compare_flights.py dump OUT.pkl
    PYTHONPATH=$PWD .venv/bin/python scripts/compare_flights.py compare BEFORE.pkl AFTER.pkl

``dump`` flies cruise and take-off with the attitude free (m3, m4; m5 cruise) and the
four presets posed (m3; m4 cruise and take-off) with the shipped tables and pickles
every array of ``fly()``'s result (plus ``projection_max`` and ``root_applied_max``);
run it in a checkout of each version.  ``compare`` prints the largest difference per
flight and the array it is in (posed flights should be 0.0: bit for bit).
"""

from __future__ import annotations

import pickle
import sys
import time

import numpy as np

CASES = [(p, m, "free") for m in ("m3", "m4") for p in ("cruise", "take-off")]
CASES += [("cruise", "m5", "free"), ("cruise", "m4", "posed"), ("take-off", "m4", "posed")]
CASES += [(p, "m3", "posed") for p in ("cruise", "hover", "take-off", "landing")]


def dump(out: str) -> None:
    from birdsim.commands.common import load_bird, load_table_for
    from birdsim.flight.freeflight import fly
    from birdsim.flight.path_file import get_flight
    from birdsim.flight.simulate import SimConfig

    bird = load_bird(None)
    res = {}
    for preset, model, att in CASES:
        ref = get_flight(preset)
        c0 = time.process_time()
        r = fly(ref, load_table_for(bird, model, None), bird, model, config=SimConfig(attitude=att))
        cpu = time.process_time() - c0
        arrays = {k: np.asarray(v) for k, v in r.arrays.items()}
        arrays["projection_max"] = np.array(r.projection_max)
        arrays["root_applied_max"] = np.array(r.meta.get("root_applied_max", 0.0))
        res[(preset, model, att)] = arrays
        print(preset, model, att, f"{ref.duration_beats / cpu:.1f} wingbeats per CPU s", flush=True)
    with open(out, "wb") as f:
        pickle.dump(res, f)


def compare(before: str, after: str) -> None:
    with open(before, "rb") as f:
        a = pickle.load(f)
    with open(after, "rb") as f:
        b = pickle.load(f)
    for key, da in a.items():
        if key not in b:
            print(key, "missing after")
            continue
        worst, where = 0.0, ""
        for k, x in da.items():
            x, y = np.asarray(x, float), np.asarray(b[key][k], float)
            d = np.inf if x.shape != y.shape else (float(np.max(np.abs(x - y))) if x.size else 0.0)
            if d > worst:
                worst, where = d, k
        print(*key, "largest difference", worst, where)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "dump":
        dump(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3])
    else:
        print("usage: compare_flights.py dump OUT.pkl | compare BEFORE.pkl AFTER.pkl")
        sys.exit(2)
