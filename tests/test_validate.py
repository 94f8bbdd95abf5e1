"""Validation against measured pigeons: data file, trimmed level flight, scorecard, CLI.

The scorecard pin uses the shipped models/pigeon.toml. The other tests use a pigeon
written inline (the values of models/pigeon.toml's sources): mass and
span from Usherwood et al. 2005 Table 2 (0.483 kg, 0.660 m), wingbeat 8.02 Hz (same
table), mean chord 0.13 m = mass / wing loading 5.65 kg m^-2 (Spedding et al. 1984 via
Hedrick et al. 2002) / span, sea-level air 1.225 kg m^-3, body drag area s*c (the seed
bird's reduced value 1: no measured pigeon value was found).
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import pytest

from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import evaluate_cycle
from birdsim.validation.measurements import (
    COLUMNS,
    Measurement,
    MeasurementsError,
    default_path,
    load_measurements,
)
from birdsim.validation.run import DEFAULT_BIRD, load_flying_bird, validate
from birdsim.validation.scorecard import NOT_SIMULATED, score, verdict_for
from birdsim.validation.trim import angle_of_attack_deg, trim_sweep

PIGEON_TOML = """
name = "pigeon"
semispan = 0.33
chord = 0.13
hand_chord = 0.13
rho = 1.225
omega = 50.39114616
body_drag_area = 0.0429
disc_area = 0.342119
mass = 0.483
gravity = 9.81
"""


@pytest.fixture(scope="module")
def pigeon(tmp_path_factory: pytest.TempPathFactory) -> Path:
    p = tmp_path_factory.mktemp("bird") / "pigeon.toml"
    p.write_text(PIGEON_TOML)
    return p


@pytest.fixture(scope="module")
def result():  # noqa: ANN201
    """The shipped pigeon's scorecard (no variants: the pin is of the base physics)."""
    if not DEFAULT_BIRD.exists():
        pytest.skip("models/pigeon.toml not in this checkout")
    return validate(load_flying_bird(None), "m3", variants=False)


# ---- data file ----------------------------------------------------------------------


def test_shipped_data_has_enough_cited_scored_rows() -> None:
    rows = load_measurements()
    scored = [m for m in rows if m.scored]
    sources = {(m.author, m.year) for m in scored}
    assert len(scored) >= 8 and len(sources) >= 3
    assert all(m.author and m.journal and m.where and m.year > 1900 for m in rows)
    keys = {m.compare for m in rows}
    assert {"min_power_speed", "power", "amplitude_slope"} <= keys
    assert any(m.compare == "power" and m.speed_m_s == 4.46 for m in rows)  # Usherwood's conditions


def _write_csv(tmp_path: Path, rows: list[dict[str, str]]) -> Path:
    import csv

    p = tmp_path / "m.csv"
    with p.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
    return p


GOOD = dict(
    id="X1",
    quantity="minimum-power speed",
    compare="min_power_speed",
    kind="value",
    speed_m_s="",
    speed_to_m_s="",
    value="8.5",
    uncertainty="0.5",
    uncertainty_kind="SD",
    unit="m/s",
    n_birds="",
    author="A",
    year="1968",
    journal="J",
    volume="1",
    pages="1-2",
    where="Table 1",
    url="",
    note="",
)


@pytest.mark.parametrize(
    "change, words",
    [
        ({"value": "fast"}, ["row 'X1'", "value='fast'"]),
        ({"kind": "guess"}, ["row 'X1'", "kind='guess'"]),
        ({"compare": "joy"}, ["row 'X1'", "compare='joy'"]),
        ({"author": ""}, ["row 'X1'", "author=''"]),
        ({"value": "nan"}, ["row 'X1'", "value='nan'"]),
        (
            {"kind": "trend", "value": "-1", "speed_m_s": "6", "speed_to_m_s": "4"},
            ["row 'X1'", "speed_to_m_s"],
        ),
        ({"compare": "power"}, ["row 'X1'", "speed_m_s"]),
        (  # a value over a window of speeds needs the window's high end above its low end
            {"compare": "power", "speed_m_s": "3", "speed_to_m_s": "3"},
            ["row 'X1'", "speed_to_m_s='3'", "a speed above speed_m_s"],
        ),
        ({"id": ""}, ["line 2", "id=''"]),
    ],
)
def test_malformed_row_is_named(tmp_path: Path, change: dict[str, str], words: list[str]) -> None:
    p = _write_csv(tmp_path, [{**GOOD, **change}])
    with pytest.raises(MeasurementsError) as e:
        load_measurements(p)
    msg = str(e.value)
    assert "\n" not in msg and all(w in msg for w in words), msg


def test_extra_field_and_duplicate_id_are_named(tmp_path: Path) -> None:
    p = _write_csv(tmp_path, [GOOD, GOOD])
    with pytest.raises(MeasurementsError, match="row 'X1' \\(line 3\\).*not used by another row"):
        load_measurements(p)
    p.write_text(p.read_text().splitlines()[0] + "\n" + ",".join(GOOD.values()) + ",extra\n")
    with pytest.raises(MeasurementsError, match="row 'X1' \\(line 2\\): has 20 fields"):
        load_measurements(p)


# ---- verdicts -----------------------------------------------------------------------


def _m(kind: str = "value", value: float = 10.0, unc: float | None = None) -> Measurement:
    return Measurement(
        "r",
        "q",
        "power",
        kind,
        value,
        "W",
        "A",
        2000,
        "J",
        "1",
        "1",
        "T",
        uncertainty=unc,
        speed_m_s=1.0,
        speed_to_m_s=2.0,
    )


def test_verdict_tolerances() -> None:
    assert verdict_for(_m(), 14.9)[1].startswith("agrees") and verdict_for(_m(), 6.7)[1].startswith(
        "agrees"
    )
    assert verdict_for(_m(), 15.1)[1].startswith("rough") and verdict_for(_m(), 5.1)[1].startswith(
        "rough"
    )
    assert verdict_for(_m(), 20.1)[1].startswith("off") and verdict_for(_m(), 4.9)[1].startswith(
        "off"
    )
    assert verdict_for(_m(unc=11.0), 20.5)[1].startswith("agrees (within ±")
    assert verdict_for(_m("at_least"), 10.0)[1] == "agrees (bound met)"
    assert verdict_for(_m("at_most"), 25.0)[1].startswith("off")
    assert verdict_for(_m("trend", -1.0), -0.1)[1].startswith("same sign")
    assert verdict_for(_m("trend", -1.0), 0.1)[1].startswith("opposite sign")
    assert verdict_for(_m(), None)[1].startswith("off: birdsim cannot trim")
    assert verdict_for(_m("shown"), 3.0) == (None, "not scored (shown only)")


# ---- trimmed level flight -----------------------------------------------------------


def test_trimmed_wingbeat_carries_the_weight_with_zero_net_fx(pigeon: Path) -> None:
    """Independent check with the cycle: whole-bird mean force = (0, -m g) to 1e-3 m g,
    and the reported power is both wings' mean power in W."""
    bird = load_flying_bird(pigeon)
    sweep = trim_sweep("m3", bird, [0.0, 4.46, 10.0])
    weight = bird.mass * bird.gravity
    for p in sweep.points:
        assert p.trimmed
        whole = evaluate_cycle(
            "m3", p.params, p.speed, bird=bird, n=64, check_bounds=False
        ).whole_bird_mean
        assert abs(float(whole.Fx)) <= 1e-3 * weight
        assert abs(float(whole.Fz) + weight) <= 1e-3 * weight
        assert p.power == pytest.approx(float(whole.P), rel=1e-9)


def test_gravityless_bird_is_refused() -> None:
    with pytest.raises(BirdsimError, match="bird.gravity=0"):
        trim_sweep("m3", Bird(), [1.0])


# ---- the pinned scorecard of the shipped pigeon (models/pigeon.toml, m3, seed polar) --

#: id -> (birdsim value, relative tolerance). A physics change that moves a row fails here;
#: 2 % on optimiser outputs (SLSQP end points move ~1e-4 with BLAS / scipy versions).
PINNED = {
    "P68b_vmp": (9.826, 0.02),
    "U05_wing_power": (14.12, 0.02),
    "P68b_pcont_3": (14.10, 0.02),
    "P68b_pcont_16": (13.97, 0.02),
    "P68b_LD": (6.843, 0.02),
    "P68b_psprint": (14.07, 0.02),
    "TD96_speed_max": (22.0, 1e-9),
    "U05_wing_ws": (100.0, 1e-3),
    # Crandell & Tobalske's slow flight: the mean over 0, 1, 2 m/s (at 4.46 m/s: 39.95 and
    # 31.02, off); the upstroke's ratio 0.672 is 0.8 % inside x1.5
    "CT11_aoa_down": (44.57, 0.02),
    "CT11_aoa_up": (44.38, 0.005),
    "U05_strokeplane": (15.31, 0.05),
    "B10_amplitude_trend": (-4.506, 0.05),
    "TD96_body_angle_trend": (-1.883, 0.05),
    "TD96_strokeplane_trend": (3.208, 0.05),
    "PA15_hover": (1.0, 0),
    # issue 24's rows: m3's rigid wing keeps its span (ratio 1 at every speed)
    "TD96_span_ratio_trend": (0.0, 0),
    "PA15_fold_cruise": (0.0, 0),
    "PA15_extend_hover": (0.0, 0),
    "H07_roll_damping": (-0.318, 0.03),  # docs/moments.md: a factor 4.7 short of -1.5
    "H07_roll_damping_airplane": (-0.318, 0.03),
    "HCD09_fct": (1.0, 0),
    # issue 25's rows: the pigeon's take-off and landing with legs (fly --legs); the wings
    # beat only from lift-off (share about 100 %) and stop at the touchdown (ratio 0.92)
    "P12_leg_share_finch": (100.1, 0.01),
    "P12_leg_share_dove": (100.1, 0.01),
    "E00_leg_share": (100.1, 0.01),
    "E00_peak_force_starling": (4.056, 0.02),
    "E00_peak_force_quail": (4.056, 0.02),
    "P14_touchdown_speed": (0.997, 0.03),
    "P14_landing_force_ratio": (0.920, 0.03),
}
VERDICTS = {
    "E00_peak_force_quail": "not",
    "P14_landing_force_ratio": "rough",
    "U05_wing_power": "rough",
    "TD96_strokeplane_trend": "opposite",
    "U05_strokeplane": "not",
    "B10_amplitude_trend": "same",
    "H07_roll_damping": "off",
    "H07_roll_damping_airplane": "not",
    "TD96_body_angle_trend": "same",
    "TD96_span_ratio_trend": "opposite",
    "PA15_fold_cruise": "off",
}


#: The turning rows (issue 23 item 5): from the pigeon's own turn-90 since it meets the
#: issue's target (0.0292 m = 0.089 semispan RMS, none saturated: docs/turning.md, p23x;
#: before, from the seed bird's scaled to the pigeon, whose force turned by 4.4 deg:
#: "agrees"), verdicts pinned (birdsim.validation.turning).
TURNING_VERDICTS = {
    "R11_force_in_body": "off",  # the pigeon's force turns by 12.8 deg in the body (criterion 5)
    "R11_force_cone": "not",  # shown only
    "HB07_turn_radius": "rough",  # 1.80 m against 0.92 (the preset: R = 1.65 m)
    "HB07_heading_roll": "agrees",  # r^2 0.99
    "WD98_bank_in_downstroke": "off",  # the attitude loop acts on wingbeat means
}
TURNING_ROWS = {
    "R11_force_in_body",
    "R11_force_cone",
    "HB07_turn_radius",
    "HB07_heading_roll",
    "WD98_bank_in_downstroke",
}


def test_pinned_scorecard(result) -> None:  # noqa: ANN001
    rows = {r.measurement.id: r for r in result.rows}
    assert set(rows) == set(PINNED) | TURNING_ROWS
    for rid in TURNING_ROWS:
        assert rows[rid].birdsim is not None and rows[rid].variants == {}
        assert rows[rid].verdict.split(" ")[0] == TURNING_VERDICTS[rid], (rid, rows[rid].verdict)
    assert result.obj["turning_flight"].startswith("pigeon turn-90;")
    for rid, (value, tol) in PINNED.items():
        assert rows[rid].birdsim == pytest.approx(value, rel=tol, abs=1e-9), rid
        assert rows[rid].verdict.split(" ")[0] == VERDICTS.get(rid, "agrees"), (
            rid,
            rows[rid].verdict,
        )
    assert result.obj["hover"] is True and result.obj["trim_range"] == [0.0, 22.0]


def test_json_object_lets_a_reader_recompute_a_point(result) -> None:  # noqa: ANN001
    obj = json.loads(json.dumps(result.obj))
    assert {"model", "rows", "power_curve", "min_power_speed"} <= set(obj)
    assert {"quantity", "measured", "source", "birdsim", "ratio", "verdict"} <= set(obj["rows"][0])
    pt = next(p for p in obj["power_curve"] if p["speed"] == 4.46)
    bird = load_flying_bird(None)
    whole = evaluate_cycle(
        obj["model"], pt["params"], pt["speed"], bird=bird, n=64, check_bounds=False
    ).whole_bird_mean
    assert float(whole.P) == pytest.approx(pt["power"], rel=1e-9)
    assert min(p["power"] for p in obj["power_curve"] if p["trimmed"]) <= obj["min_power"] + 0.5


#: How far the shipped table's level-flight power may sit above / below the direct solve,
#: as a fraction of the direct power (docs/validation.md, "The table check").
TABLE_ABOVE, TABLE_BELOW = 0.10, 0.02


def test_shipped_table_agrees_with_the_direct_solve(result) -> None:  # noqa: ANN001
    """The table's interpolated level-flight power is within TABLE_ABOVE (10 %) above and
    TABLE_BELOW (2 %) below the direct solve wherever its grid reaches.

    Measured every 0.25 m/s from 0 to 13.25 m/s (``scripts/table_vs_direct.py``; the test
    sees only the scorecard's speeds, about one in four of these): the shipped table is
    above the solve by at most 6.2 % (10.75 m/s; 5.2 % at 11 m/s) and below it by at most
    0.46 % (5.5 m/s); the previous build of the table, 4.1 % (12.5 m/s) and 0.46 %.  Two
    causes, both by design: multilinear interpolation across a branch change (from 9 m/s
    the demand, just below Fx = 0, lies between flapping cells at Fx = 0 and gliding ones
    at Fx = -0.025, flap amplitude 0; from 7 m/s the 8 cells around it differ by 0.5-0.7
    rad), and
    the regularising pass, which may keep a wingbeat that costs up to smooth_tol = 5e-3
    more than the best found: up to 0.01 in one wing's power in table units, 4.4 W for the
    pigeon, 30-60 % of its level-flight power (two cells at 10.8 m/s hold wingbeats
    needing 10 % and 5 % more power than the previous build's: all of the rise).  So no few-percent bound follows from the construction; 10 %
    is 1.6x the worst measured anywhere on the fine grid, and leaves room for a rebuild
    whose pass chooses differently (the code change from the previous build moved the
    worst speed from 4.1 to 6.2 %), while a wrong check is far outside it (a factor 2 in
    power: +100 %; the whole weight asked of one wing: +104 to +481 %).  Below: the direct solve is
    an optimum and the table interpolates optima, whose chord dips under a concave kink
    (two branches meeting) by 0.46 % at most: 2 % is 4x that."""
    assert result.obj["table"] == "pigeon-m3.npz"
    pairs = [
        (p["speed"], p["power"], p["table_power"])
        for p in result.obj["power_curve"]
        if p["table_power"] is not None
    ]
    assert len(pairs) >= 15
    for speed, direct, table in pairs:
        assert table <= (1 + TABLE_ABOVE) * direct, (speed, direct, table)
        assert table >= (1 - TABLE_BELOW) * direct, (speed, direct, table)


def test_off_row_gets_the_other_physics(pigeon: Path) -> None:
    bird = load_flying_bird(pigeon)
    ms = tuple(m for m in load_measurements() if m.id == "H07_roll_damping")
    sweep = trim_sweep("m3", bird, [4.0])
    rows, vsweeps = score(ms, sweep, bird)
    assert rows[0].verdict.startswith("off")
    assert set(rows[0].variants) == {"robofly polar", "induced velocity on"} == set(vsweeps)
    assert all(
        v is not None and v != pytest.approx(rows[0].birdsim, rel=1e-3)
        for v in rows[0].variants.values()
    )


def test_slow_flight_rows_are_the_mean_below_three_metres_per_second(pigeon: Path) -> None:
    """Crandell & Tobalske 2011's in vivo angles are of slow flight, "<3 m s-1" in the same
    authors' words (2015): the rows take birdsim's mean over the sweep's speeds from 0 up to,
    not including, 3 m/s (the old rows read 4.46 m/s only; on the old code a row with
    speed 0 read the hover point alone, 45.0 deg)."""
    bird = load_flying_bird(pigeon)
    ms = {m.id: m for m in load_measurements()}
    for rid in ("CT11_aoa_up", "CT11_aoa_down"):
        assert ms[rid].window == (0.0, 3.0) and "(0 to <3 m/s)" in ms[rid].measured_text()
    assert "Slow flight (<3 m s-1)" in ms["CT11_aoa_down"].note
    assert "Not verified" in ms["CT11_aoa_down"].note
    sweep = trim_sweep("m3", bird, [0.0, 1.0, 2.0, 3.0, 4.46])
    rows, _ = score((ms["CT11_aoa_up"], ms["CT11_aoa_down"]), sweep, bird, variants=False)
    for row, phase in zip(rows, (math.pi, 0.0)):
        each = [abs(angle_of_attack_deg("m3", bird, sweep.at(v), phase)) for v in (0.0, 1.0, 2.0)]
        assert row.birdsim == pytest.approx(sum(each) / 3, abs=1e-12)  # 3 m/s left out
        assert row.birdsim != pytest.approx(each[0], abs=0.1)  # not the hover point alone
    assert rows[0].birdsim == pytest.approx(44.38, rel=0.005)
    # a window row that is off gets its other-physics values over the whole window too
    far = replace(ms["CT11_aoa_up"], value=200.0)
    rows, vsweeps = score((far,), sweep, bird)
    assert rows[0].verdict.startswith("off") and set(rows[0].variants) == set(vsweeps)
    for vs in vsweeps.values():
        assert [p.speed for p in vs.points] == [0.0, 1.0, 2.0]


# ---- command line -------------------------------------------------------------------


def _small_data(tmp_path: Path) -> Path:
    src = default_path().read_text().splitlines()
    keep = [src[0]] + [
        line
        for line in src[1:]
        if line.startswith(("P68b_vmp", "U05_wing_power", "TD96_speed_max"))
    ]
    p = tmp_path / "small.csv"
    p.write_text("\n".join(keep) + "\n")
    return p


def test_cli_json_and_page(
    tmp_path: Path, pigeon: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    data = _small_data(tmp_path)
    out = tmp_path / "page"
    assert (
        main(["validate", "--bird", str(pigeon), "--data", str(data), "--json", "--out", str(out)])
        == 0
    )
    obj = json.loads(capsys.readouterr().out)
    assert [r["id"] for r in obj["rows"]] == ["P68b_vmp", "U05_wing_power", "TD96_speed_max"]
    assert obj["min_power_speed"] == pytest.approx(
        9.42, rel=0.02
    )  # the inline pigeon (chord 0.13, drag area s c)
    assert {f.name for f in out.iterdir()} == {
        "index.html",
        "power_curve.png",
        "kinematics.png",
        "scorecard.json",
    }
    assert "Usherwood" in (out / "index.html").read_text()
    before = (out / "index.html").stat().st_mtime_ns
    assert main(["validate", "--bird", str(pigeon), "--data", str(data), "--out", str(out)]) == 2
    assert (
        "--force" in capsys.readouterr().err and (out / "index.html").stat().st_mtime_ns == before
    )


@pytest.mark.parametrize(
    "args, toml, words",
    [
        (["--polar", "flat"], None, ["--polar", "flat"]),
        ([], PIGEON_TOML.replace("gravity = 9.81", ""), ["has no gravity"]),
        ([], PIGEON_TOML.replace("mass = 0.483", ""), ["has no mass"]),
        ([], PIGEON_TOML.replace("gravity = 9.81", "gravity = 0.0"), ["gravity=0.0"]),
        (["--model", "m9"], None, ["m9"]),
    ],
)
def test_cli_bad_input_is_one_line_and_writes_nothing(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    args: list[str],
    toml: str | None,
    words: list[str],
) -> None:
    bird = tmp_path / "b.toml"
    bird.write_text(toml or PIGEON_TOML)
    out = tmp_path / "page"
    with pytest.raises(SystemExit) if args[:1] == ["--polar"] else _no_raise():
        code = main(["validate", "--bird", str(bird), "--out", str(out), *args])
        assert code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and all(w in err for w in words), err
    assert not out.exists()


def test_cli_malformed_data_row_is_named(
    tmp_path: Path, pigeon: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    src = default_path().read_text().replace(",5.9,", ",five point nine,", 1)
    data = tmp_path / "bad.csv"
    data.write_text(src)
    out = tmp_path / "page"
    assert main(["validate", "--bird", str(pigeon), "--data", str(data), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "row 'P68b_LD'" in err and "five point nine" in err
    assert not out.exists()


class _no_raise:
    def __enter__(self) -> None:
        return None

    def __exit__(self, *exc: object) -> bool:
        return False


@pytest.mark.skipif(not DEFAULT_BIRD.exists(), reason="models/pigeon.toml not in this checkout yet")
def test_shipped_pigeon_trims_level_flight() -> None:
    bird = load_flying_bird(None)
    sweep = trim_sweep("m3", bird, [4.46, 10.0])
    assert all(p.trimmed and math.isfinite(p.power) and p.power > 0 for p in sweep.points)


def test_angle_of_attack_is_the_analytic_one_for_the_base_model() -> None:
    """base model at mid-downstroke: element velocity in body axes (V cos th, V sin th + r w Phi)
    (z down), twisted leading edge down by Theta: alpha = atan2(V sin th + r w Phi, V cos th) - Theta;
    at mid-upstroke the heave velocity reverses and the twist is +Theta."""
    from birdsim.validation.trim import TrimPoint, angle_of_attack_deg

    bird = Bird(semispan=0.33, chord=0.12, omega=50.0, gravity=9.81)
    th, phi, tw, v = 0.2, 0.6, 0.3, 7.0
    pt = TrimPoint(
        v, 0.0, {"pitch": th, "flap_amp": phi, "twist_amp": tw}, True, 0.0, 0.0, 0.0, 1.0
    )
    r_omega_phi = 0.5 * 0.33 * 50.0 * phi
    down = math.degrees(math.atan2(v * math.sin(th) + r_omega_phi, v * math.cos(th)) - tw)
    up = math.degrees(math.atan2(v * math.sin(th) - r_omega_phi, v * math.cos(th)) + tw)
    assert angle_of_attack_deg("base", bird, pt, 0.0) == pytest.approx(down, abs=1e-9)
    assert angle_of_attack_deg("base", bird, pt, math.pi) == pytest.approx(up, abs=1e-9)


def test_diagnosis_says_which_physics_closes_the_gap() -> None:
    from birdsim.validation.page import diagnose
    from birdsim.validation.scorecard import Row

    ms = {m.id: m for m in load_measurements()}
    far = diagnose(
        Row(
            ms["CT11_aoa_up"],
            31.0,
            0.47,
            "off",
            {"robofly polar": 24.4, "induced velocity on": 20.7},
        )
    )
    assert far.count("(further)") == 2 and "Neither" in far
    near = diagnose(
        Row(
            ms["U05_wing_power"],
            10.0,
            0.39,
            "off",
            {"robofly polar": 60.0, "induced velocity on": 20.0},
        )
    )
    assert (
        near.endswith("induced velocity on closes the gap.") and near.count("(closer)") == 2
    )  # 60 W: closer, still > x2
    trend = diagnose(
        Row(
            ms["TD96_strokeplane_trend"],
            3.2,
            None,
            "opposite",
            {"robofly polar": 5.9, "induced velocity on": -0.3},
        )
    )
    assert "still the wrong sign" in trend and "induced velocity on closes" in trend


# ---- turning rows (issue 23 item 5) -------------------------------------------------


def test_turning_rows_are_cited_and_from_two_sources_at_least() -> None:
    rows = [m for m in load_measurements() if m.id in TURNING_ROWS]
    assert len(rows) == len(TURNING_ROWS)
    assert len({(m.author, m.year) for m in rows}) >= 2
    for m in rows:
        assert m.compare.startswith("turn_") and m.url and "'" in m.note, m.id  # a quoted passage
        assert "Not verified" in m.note, m.id  # what could not be read is said


def test_turning_rows_print_not_yet_simulated_and_score_once_flown(
    tmp_path: Path, pigeon: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without a turning flight (here: made to fly none) the rows say "not yet
    simulated"; given values they are scored like the others."""
    import birdsim.validation.turning as turning
    from birdsim.validation.page import render_html
    from birdsim.validation.run import scorecard_text

    monkeypatch.setattr(turning, "turn_values", lambda bird: ({}, "no turning flight"))

    src = default_path().read_text().splitlines()
    keep = [src[0]] + [
        line for line in src[1:] if line.startswith(("TD96_speed_max", *sorted(TURNING_ROWS)))
    ]
    data = tmp_path / "turning.csv"
    data.write_text("\n".join(keep) + "\n")
    bird = load_flying_bird(pigeon)
    v = validate(bird, "m3", load_measurements(data), variants=False)  # as `birdsim validate`
    obj = json.loads(json.dumps(v.obj))
    by_id = {r["id"]: r for r in obj["rows"]}
    assert set(by_id) == TURNING_ROWS | {"TD96_speed_max"}
    for rid in TURNING_ROWS:
        assert by_id[rid]["verdict"] == NOT_SIMULATED and by_id[rid]["birdsim"] is None
    speeds = [p["speed"] for p in obj["power_curve"]]
    assert speeds == [float(i) for i in range(23)]  # the turning rows add no speed
    text = scorecard_text(v)
    assert text.count("not yet simulated") == 2 * len(TURNING_ROWS)  # birdsim column + verdict
    assert "not yet simulated" in render_html(v.obj, v.rows, "t")
    # once a turning flight gives the values, the rows are scored like the others
    ms = load_measurements(data)
    flown = {
        "turn_radius": 1.0,
        "turn_force_fixed_in_body": 1.0,
        "turn_bank_within_downstroke": 0.0,
    }
    rows = {r.measurement.id: r for r in score(ms, v.sweep, bird, variants=False, turning=flown)[0]}
    assert rows["HB07_turn_radius"].verdict.startswith("agrees") and rows[
        "HB07_turn_radius"
    ].ratio == pytest.approx(1 / 0.92)
    assert rows["R11_force_in_body"].verdict == "agrees (yes/no)"
    assert rows["WD98_bank_in_downstroke"].verdict == "off (yes/no)"
    assert rows["HB07_heading_roll"].verdict == NOT_SIMULATED
    assert rows["R11_force_cone"].verdict == NOT_SIMULATED


# ---- perching rows (issue 25) ---------------------------------------------------------


def test_perch_rows_are_cited_quoted_and_from_two_sources_at_least() -> None:
    rows = [m for m in load_measurements() if m.compare.startswith("perch_")]
    assert {m.compare for m in rows} == {
        "perch_leg_share",
        "perch_takeoff_peak_force",
        "perch_touchdown_speed",
        "perch_landing_over_takeoff_force",
    }
    assert len({(m.author, m.year) for m in rows}) >= 2
    for m in rows:
        assert m.url and "'" in m.note, m.id  # a quoted passage of the paper
