"""Flocks (issue 27, item 2; birdsim/flight/flock.py, flock_fly.py): every bird flies its
own (shifted) reference, no two birds come closer than one semispan, a flock of one is the
single bird's flight, the flock log has a leading bird axis, bad input is one line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.flight.flock import MAX_BIRDS, load_birds, load_flock, preset_names
from birdsim.flight.flock_fly import (
    FlockJob,
    bird_log,
    flock_summary,
    fly_bird,
    fly_flock,
    jobs_for,
    stack_logs,
)
from birdsim.flight.path_file import get_flight

SEED = 5.0  # the seed bird's period (its time unit): seconds per wingbeat


def _flock(
    tmp_path: Path, offsets: list[tuple[float, float, float]], extra: str = "", path: str = "cruise"
) -> str:
    text = f'path = "{path}"\n' + extra
    for off in offsets:
        text += f"[[bird]]\noffset = [{off[0]}, {off[1]}, {off[2]}]\n"
    p = tmp_path / "f.toml"
    p.write_text(text)
    return str(p)


def test_each_bird_flies_its_own_reference_and_keeps_apart(tmp_path):
    """Three seed birds (semispan 1) for 3 wingbeats: each bird's path RMS after the
    start within 0.2 semispan of its own (shifted) reference (the issue's target), no
    two birds closer than one semispan at any sample, no saturated sample, and every
    per-sample array carries the bird axis."""
    offsets = [(0.0, 0.0, 0.0), (-2.0, 1.5, 0.3), (-2.0, -1.5, -0.3)]
    src = _flock(tmp_path, offsets)
    flock, jobs = jobs_for(src, "m3", seconds=3 * SEED)
    arrays = fly_flock(jobs)
    n_samples = arrays["t"].shape[1]
    assert int(arrays["n_birds"]) == 3
    for key in ("x", "y", "z", "x_ref", "saturated", "power"):
        assert arrays[key].shape == (3, n_samples), key
    assert arrays["qpos"].shape[:2] == (3, n_samples)
    info = flock_summary(arrays, 1.0)
    for b in info["birds"]:
        assert b["rms_error_after_start_semispans"] < 0.2
    assert info["saturated_samples"] == 0
    assert info["min_separation_semispans"] > 1.0
    # each bird's reference is the leader's shifted by its offset (x, y and z)
    for i, (dx, dy, dz) in enumerate(offsets):
        np.testing.assert_allclose(arrays["x_ref"][i] - arrays["x_ref"][0], dx, atol=1e-9)
        np.testing.assert_allclose(arrays["y_ref"][i] - arrays["y_ref"][0], dy, atol=1e-12)
        np.testing.assert_allclose(arrays["z_ref"][i] - arrays["z_ref"][0], dz, atol=1e-9)


def test_a_flock_of_one_is_the_single_birds_flight(tmp_path):
    """A one-bird flock with offset (1, 0, 0.5) flies the single bird's cruise moved by
    the offset: its path differs from `birdsim fly cruise`'s by the offset to round-off
    (1e-9 semispan over 2 wingbeats: the same arithmetic on coordinates 1 semispan
    further forward, so the last bits of the sums differ), and with offset 0 the logs are
    equal to 1e-12 (the same flight in the same process)."""
    from birdsim.flight.batch import FlightJob, run_job

    single = run_job(FlightJob(0, "cruise", "m3", seconds=2 * SEED))["arrays"]
    zero = fly_bird(FlockJob(_flock(tmp_path, [(0.0, 0.0, 0.0)]), 0, "m3", seconds=2 * SEED))
    for k in ("x", "y", "z", "vx", "vz", "pitch", "power"):
        np.testing.assert_allclose(zero["arrays"][k], single[k], rtol=0, atol=1e-12, err_msg=k)
    moved = fly_bird(FlockJob(_flock(tmp_path, [(1.0, 0.0, 0.5)]), 0, "m3", seconds=2 * SEED))
    a = moved["arrays"]
    np.testing.assert_allclose(a["x"] - 1.0, single["x"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(a["z"] - 0.5, single["z"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(a["vx"], single["vx"], rtol=0, atol=1e-9)


def test_stacking_and_unstacking_keeps_a_birds_log(tmp_path):
    """bird_log(stack_logs(...), i) is bird i's own log (every key, every value)."""
    src = _flock(tmp_path, [(0.0, 0.0, 0.0), (0.0, 2.0, 0.0)])
    flock = load_flock(src)
    logs = [fly_bird(FlockJob(src, i, "m3", seconds=0.2 * SEED))["arrays"] for i in range(2)]
    stacked = stack_logs(logs, flock)
    for i in range(2):
        one = bird_log(stacked, i)
        assert one.keys() == logs[i].keys()
        for k, v in logs[i].items():
            assert np.array_equal(one[k], v), k


def test_the_flock_presets_parse():
    """`flock`: 12 pigeons on a turning path under the rule `offsets` (attitude free, 10
    s); `flock-seed`: 12 seed birds steered on a turning path; `flock-v`: 12 pigeons in a
    straight V (posed)."""
    assert {"flock", "flock-seed", "flock-v"} <= set(preset_names())
    flock = load_flock("flock")
    assert flock.n_birds == 12 and flock.rule == "offsets" and flock.attitude == "free"
    assert flock.seconds == 10.0
    assert {b.name for b in load_birds(flock)} == {"pigeon"}
    assert get_flight(flock.path, turning=True).is_3d
    seed = load_flock("flock-seed")
    assert seed.n_birds == 12 and seed.rule == "steer" and seed.attitude == "free"
    assert {b.name for b in load_birds(seed)} == {"seed"}
    v = load_flock("flock-v")
    assert v.n_birds == 12 and v.rule == "offsets"
    assert {b.name for b in load_birds(v)} == {"pigeon"}


@pytest.mark.parametrize(
    "offsets, extra, words",
    [
        ([(0, 0, 0), (0.5, 0, 0)], "", "birds 0 and 1 start 0.5 apart"),
        ([(0, 0, 0)] + [(float(i), 0.0, 0.0) for i in range(1, MAX_BIRDS + 1)], "", "at most 100 birds"),
        ([(0, 0, 0)], 'seconds = -1\n', "seconds=-1"),
        ([(0, 0, 0)], "", "neither starts nor ends on the perch"),
    ],
)  # fmt: skip
def test_bad_flock_input_is_one_line(tmp_path, capsys, offsets, extra, words):
    src = _flock(tmp_path, offsets, extra, "take-off" if "perch" in words else "cruise")
    out = tmp_path / "log.npz"
    assert main(["fly", src, "--quiet", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0], err
    assert not out.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["f.toml"]


def test_a_bird_file_that_does_not_parse_is_named_with_its_index(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("mass = [\n")
    p = tmp_path / "f.toml"
    p.write_text(
        'path = "cruise"\n[[bird]]\noffset = [0, 0, 0]\n'
        f'[[bird]]\nfile = "{bad.name}"\noffset = [0, 3, 0]\n'
    )
    out = tmp_path / "log.npz"
    assert main(["fly", str(p), "--quiet", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "bird 1" in err[0] and "bad.toml" in err[0], err
    assert not out.exists()


def test_render_and_export_take_a_flock_log_with_every_bird(tmp_path, capsys):
    """A two-bird flock's log: `render --still` draws both birds (the still differs from
    the leader's alone); `export --format bvh` writes one file per bird whose root
    positions are each bird's own; `view` draws it too (tests/test_view_flock.py)."""
    from birdsim.flight.flock_log import load_flock_log

    src = _flock(tmp_path, [(0.0, 0.0, 0.0), (0.0, 2.0, 0.0)])
    out = tmp_path / "flock.npz"
    assert main(["fly", src, "--quiet", "--seconds", str(0.2 * SEED), "--out", str(out)]) == 0
    data, birds = load_flock_log(out)
    assert len(birds) == 2 and birds[1]["bird_obj"].name == birds[0]["bird_obj"].name
    png = tmp_path / "a.png"
    assert main(["render", str(out), "--still", str(png), "--at", "0.1", "--camera", "top"]) == 0
    assert png.stat().st_size > 0
    bvh = tmp_path / "f.bvh"
    assert main(["export", str(out), "--format", "bvh", "--out", str(bvh)]) == 0
    files = sorted(tmp_path.glob("f-bird*.bvh"))
    assert [f.name for f in files] == ["f-bird00.bvh", "f-bird01.bvh"]
    assert not bvh.exists()
    # the second bird's root starts 2 semispans (its offset) to the left of the first's
    # (BVH: X forward, Y up, Z right; to the file's 6 decimals)
    roots = [_first_root(f) for f in files]
    assert roots[1] == pytest.approx([roots[0][0], roots[0][1], roots[0][2] - 2.0], abs=1e-5)
    # every output checked before anything is written: an existing one refuses all
    capsys.readouterr()
    assert main(["export", str(out), "--format", "bvh", "--out", str(bvh)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "f-bird00.bvh" in err[0] and "exists" in err[0], err


def _first_root(path: Path) -> list[float]:
    lines = path.read_text().splitlines()
    i = lines.index("MOTION")
    return [float(v) for v in lines[i + 3].split()[:3]]


def test_a_bird_with_its_own_path_flies_it(tmp_path):
    """A bird's own ``path`` replaces the leader's (shifted by its offset): its
    reference is that path's (z 9 semispans, 3 above the cruise preset's), its start
    there, and the start-separation check sees it."""
    own = tmp_path / "high.toml"
    own.write_text("x0 = -15.707963267948966\n[[keyframe]]\nt = 0\nV = 0.5\nz = 9.0\n")
    p = tmp_path / "f.toml"
    p.write_text(
        'path = "cruise"\n[[bird]]\noffset = [0, 0, 0]\n'
        f'[[bird]]\npath = "{own.name}"\noffset = [0, 0, 0.5]\n'
    )
    flock, jobs = jobs_for(str(p), "m3", seconds=0.2 * SEED)
    arrays = fly_flock(jobs)
    np.testing.assert_allclose(arrays["z_ref"][1], 9.5, atol=1e-9)
    np.testing.assert_allclose(arrays["z_ref"][0], 6.0, atol=1e-9)
    assert abs(arrays["z"][1, 0] - 9.5) < 0.05
    # the same start as bird 0's: refused in one line
    p.write_text(
        'path = "cruise"\n[[bird]]\noffset = [0, 0, 3]\n'
        f'[[bird]]\npath = "{own.name}"\noffset = [0, 0, 0]\n'
    )
    with pytest.raises(Exception, match="birds 0 and 1 start 0 apart"):
        jobs_for(str(p), "m3")


@pytest.mark.slow  # two worker processes start (~14 s at load 6)
def test_a_flock_on_the_pool_flies_the_same_birds(tmp_path):
    """`--jobs 2` (one task per bird in fresh workers) gives the in-process flock's
    arrays to round-off (1e-9 in the bird's units: a fresh process may sum in another
    order, birdsim/flight/batch.py)."""
    from birdsim.flight.batch import local_executor

    src = _flock(tmp_path, [(0.0, 0.0, 0.0), (-2.0, 1.5, 0.0), (-2.0, -1.5, 0.0)])
    _, jobs = jobs_for(src, "m3", seconds=0.4 * SEED)
    here = fly_flock(jobs)
    with local_executor(2) as ex:
        pool = fly_flock(jobs, ex)
    assert here.keys() == pool.keys()
    for k in ("x", "y", "z", "vx", "vz", "qpos", "power"):
        np.testing.assert_allclose(pool[k], here[k], rtol=0, atol=1e-9, err_msg=k)
