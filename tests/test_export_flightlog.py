"""Exports of real free flights (`birdsim fly --out` logs of the seed bird and the pigeon),
read back with pxr (USD) and the `bvh` library: frame range and rate, the body position at
three frames against the flight log (1e-4 semispan after the unit scale), one wingbeat per
wingbeat period of a wing joint; a manoeuvre exported without --kinematic is the same free
flight as its log."""

import math

import numpy as np
import pytest

from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.export.flightlog import frames_from_log, read_flight_log
from birdsim.physics.bird import Bird

BEATS = 10  # the cruise preset: 10 wingbeats
BIRDS = {"seed": "models/seed-bird.toml", "pigeon": "models/pigeon.toml"}
FROM_BVH = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])  # MuJoCo = FROM_BVH @ BVH
CHECK = (0, 11, -1)  # frames where the body is compared with the log


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    d = tmp_path_factory.mktemp("logs")
    out = {}
    for name, bird in BIRDS.items():
        path = d / f"{name}.npz"
        assert main(["fly", "cruise", "--bird", bird, "--out", str(path), "--quiet"]) == 0
        out[name] = path
    return out


def _export(logs, tmp_path, bird, fmt, *extra):
    out = tmp_path / f"{bird}.{'usdc' if fmt == 'usd' else fmt}"
    assert main(["export", str(logs[bird]), "--format", fmt, "--out", str(out), *extra]) == 0
    return out


def _expected(log_path, fps, per_second):
    """Frame times (bird units) and the log's body position there (MuJoCo world, bird units)."""
    log = np.load(log_path)
    t = log["t"]
    n = int(math.floor((t[-1] - t[0]) / per_second * fps + 1e-9)) + 1
    time = t[0] + np.arange(n) * per_second / fps
    pos = np.column_stack([np.interp(time, t, log["x"]), np.zeros(n), np.interp(time, t, log["z"])])
    return time, pos, Bird.from_toml(BIRDS["seed" if float(log["omega"]) == 1.0 else "pigeon"])


def _wingbeat_frequency(series, fps):
    s = np.asarray(series, dtype=float)
    spec = np.abs(np.fft.rfft(s - s.mean()))
    return np.fft.rfftfreq(len(s), d=1.0 / fps)[np.argmax(spec)], fps / len(s)  # peak, resolution


def _once_per_beat(series, frames_per_beat):
    """Repeats after one wingbeat (within the controller's slow corrections), not after half."""
    k = int(round(frames_per_beat))
    s = np.asarray(series, dtype=float)
    swing = np.ptp(s)
    assert swing > 0.05
    assert np.max(np.abs(s[k:] - s[:-k])) < 0.05 * swing
    assert np.max(np.abs(s[k // 2 :] - s[: -(k // 2)])) > 0.3 * swing


@pytest.mark.parametrize("bird", ["seed", "pigeon"])
def test_usd_of_a_real_log(logs, tmp_path, bird):
    pytest.importorskip("pxr")
    from pxr import Usd, UsdGeom

    from birdsim.export.usd import BODY_PRIM

    beat = ("--beat-rate", "2") if bird == "seed" else ()  # the pigeon in real seconds
    stage = Usd.Stage.Open(str(_export(logs, tmp_path, bird, "usd", *beat)))
    b = Bird.from_toml(BIRDS[bird])
    per_s = 2 * b.period if bird == "seed" else 1.0
    time, pos, _ = _expected(logs[bird], 30, per_s)
    n = len(time)
    # the log's last sample is 1/64 wingbeat before the end of 10: 4.99 s at 2 wingbeats per
    # second (the seed bird) or 1.245 s of real time (the pigeon, 8.02 Hz)
    assert n == (150 if bird == "seed" else 38)
    assert stage.GetTimeCodesPerSecond() == 30 and stage.GetFramesPerSecond() == 30
    assert stage.GetStartTimeCode() == 0 and stage.GetEndTimeCode() == n - 1
    mpu = UsdGeom.GetStageMetersPerUnit(stage)
    assert mpu == 1.0  # the pigeon in metres, the seed bird's semispan drawn as 1 m
    body = UsdGeom.Xformable(stage.GetPrimAtPath(BODY_PRIM))
    for k in CHECK:
        k = k % n
        p = np.array(body.ComputeLocalToWorldTransform(k).ExtractTranslation()) * mpu
        assert np.max(np.abs(p - pos[k])) < 1e-4 * b.semispan, (k, p, pos[k])
    arm = next(
        UsdGeom.Xformable(p)
        for p in stage.Traverse()
        if p.GetName().startswith("Mesh_Xform_r_arm_panel_id")
    )
    angle = []
    for k in range(n):
        m = np.array(arm.ComputeLocalToWorldTransform(k).ExtractRotationMatrix())
        angle.append(np.arctan2(-m[1][2], m[1][1]))  # elevation of the right wing's span
    if bird == "seed":
        _once_per_beat(angle, 15)
    else:
        f, df = _wingbeat_frequency(angle, 30)
        assert abs(f - b.omega / (2 * np.pi)) <= df, (f, df)  # 8.02 Hz in real time


@pytest.mark.parametrize("bird", ["seed", "pigeon"])
def test_bvh_of_a_real_log(logs, tmp_path, bird):
    bvh = pytest.importorskip("bvh")
    pytest.importorskip("pybvh")
    parsed = bvh.Bvh(_export(logs, tmp_path, bird, "bvh", "--beat-rate", "2").read_text())
    b = Bird.from_toml(BIRDS[bird])
    time, pos, _ = _expected(logs[bird], 30, 2 * b.period)
    assert parsed.nframes == len(time) == 150 and parsed.frame_time == pytest.approx(1 / 30)
    for k in CHECK:
        k = k % len(time)
        p = FROM_BVH @ np.array(
            parsed.frame_joint_channels(k, "root", ["Xposition", "Yposition", "Zposition"])
        )
        assert np.max(np.abs(p - pos[k])) < 1e-4 * b.semispan, (k, p, pos[k])
    flap = [parsed.frame_joint_channel(k, "r_shoulder", "Xrotation") for k in range(parsed.nframes)]
    _once_per_beat(np.radians(flap), 15)


def test_manoeuvre_export_is_the_free_flight_of_its_log(logs, tmp_path):
    """`birdsim export cruise` flies as `birdsim fly cruise` (and render) does: same frames."""
    out = tmp_path / "cruise.csv"
    assert (
        main(["export", "cruise", "--bird", BIRDS["pigeon"], "--format", "csv", "--out", str(out)])
        == 0
    )
    direct = frames_from_log(read_flight_log(logs["pigeon"]), fps=30)
    rows = np.genfromtxt(out, delimiter=",", names=True)
    assert len(rows) == direct.frames
    assert np.allclose(rows["x"], direct.body_position[:, 0], atol=1e-6)
    assert np.allclose(rows["z"], direct.body_position[:, 2], atol=1e-6)
    # the achieved force sits beside the demand (table units, right wing + body drag)
    assert np.allclose(rows["Fz_achieved"], rows["Fz_demand"], atol=0.02)


def test_a_log_from_another_program_is_one_line(tmp_path):
    np.savez(tmp_path / "other.npz", t=np.arange(3.0))
    (tmp_path / "text.npz").write_text("hello")
    for name in ("other.npz", "text.npz", "missing.npz"):
        with pytest.raises(BirdsimError) as exc:
            read_flight_log(tmp_path / name)
        assert "\n" not in str(exc.value) and "SOURCE" in str(exc.value)
