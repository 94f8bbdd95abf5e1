"""The bad-input matrix: every subcommand and public function, one row per mistake.

Each row of :data:`CASES` is ``(case id, call, text)``:

* ``call`` is an argv list (``birdsim`` run in this process through ``birdsim.cli.main``),
  a Python callable taking the case's work folder ``w`` (the public API), or an
  :class:`Interrupt` (Ctrl-C delivered while the command runs);
* ``{w}`` in an argv is the case's work folder: a fresh copy of :func:`_workspace`
  (tables, bird and manoeuvre files, good and broken); the command runs with it as the
  current folder, so default outputs (``tables/``, ``report/``, ``renders/``) land there;
* ``text`` must be in the one line of the message: it names the argument (the flag on the
  command line, the Python argument in the API).

Every case asserts: exit status 2 (a Python row: a :class:`BirdsimError`), exactly one
line on stderr, no traceback, no RuntimeWarning (numpy's overflow warnings are errors
here), nothing written or changed in the work folder.  A Ctrl-C
row expects status 130 and one line instead (and keeps nothing but a build's
checkpoints).  Python rows also assert that the message names no command-line flag.

Rows marked ``_owned(helper, why)`` are defects in files another helper is changing;
they are strict xfails, so a fix shows up as an XPASS failure and the mark must go.
"""

from __future__ import annotations

import hashlib
import importlib
import os
import re
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from birdsim import Bird, LookupTable, evaluate_cycle, load_table
from birdsim.cli import main
from birdsim.errors import BirdsimError
from birdsim.flight.freeflight import Gust, fly
from birdsim.flight.manoeuvre import Keyframe, Manoeuvre, get_manoeuvre, load_manoeuvre
from birdsim.flight.path_file import get_flight
from birdsim.flight.presets import PATH_PRESETS, demo_bird
from birdsim.mujoco.crosscheck import crosscheck
from birdsim.physics.kinematics import get_model
from birdsim.physics.moments import wingbeat_moments
from birdsim.tables.build import BuildConfig, BuildSettings, Grid, build_table
from birdsim.tables.optimize import ForceProblem

# fmt: off
HOVER = ["--param", "pitch=1.5", "--param", "flap_amp=1.5", "--param", "twist_amp=0.7"]
FORCES = ["forces", "--model", "m1", "--speed", "0"]
HOVER_PARAMS = dict(pitch=1.5, flap_amp=1.5, twist_amp=0.7)
BUILD_BASE = ["tables", "build", "--model", "base", "--quiet"]  # a single-valued option is given once
TINY_GRID = ["--grid", "Fx=0|0.2,Fz=-0.5|-0.2,V=0|0.9"]
BUILD = [*BUILD_BASE, *TINY_GRID, "--jobs", "1"]
BUILD_NO_GRID = [*BUILD_BASE, "--jobs", "1"]
RENDER_NO_MODEL = ["render", "hover", "--table", "{w}/table.npz", "--quiet"]
RENDER = [*RENDER_NO_MODEL, "--model", "base"]
M5_PARAMS = [x for n in ("pitch=0.2", "flap_amp=0.5", "twist_amp=0.2", "stroke_plane=0.2", "wrist_amp=0.1", "wrist_bias=0.1", "wrist_lag=0.5", "fold_phase=0", "supination_amp=0.3") for x in ("--param", n)]
TINY = Grid.parse("Fx=0|0.2,Fz=-0.5|-0.2,V=0|0.9")
SEED_TABLE = Path(__file__).resolve().parent.parent / "tables" / "seed-m3.npz"
# fmt: on


@dataclass(frozen=True)
class Interrupt:
    """``argv`` run with ``target`` ("module:attribute") replaced by a function that
    calls the original ``after`` times and then raises KeyboardInterrupt (Ctrl-C)."""

    argv: list[str]
    target: str
    after: int = 0
    keep: str = ""  # a regex of paths the interrupted run may leave (a build's checkpoints)


def _owned(helper: str, why: str) -> pytest.MarkDecorator:
    return pytest.mark.xfail(strict=True, reason=f"owned by {helper}: {why}")


def _lookup(w: Path, *demand: Any) -> Any:
    return load_table(w / "table.npz").lookup(*demand)


# fmt: off
CASES: list[tuple[str, Any, str] | Any] = [
    # ---- birdsim forces ---------------------------------------------------------------
    ("forces/unknown-model", ["forces", "--model", "m9", "--speed", "0", *HOVER], "--model 'm9' is unknown"),
    ("forces/unknown-param", [*FORCES, *HOVER, "--param", "sweep=0.1"], "--param 'sweep' is unknown"),
    ("forces/param-out-of-bounds", [*FORCES, *HOVER[:-1], "twist_amp=2"], "--param twist_amp=2"),
    ("forces/param-nan", [*FORCES, *HOVER[:-1], "twist_amp=nan"], "--param twist_amp=nan is not finite"),
    ("forces/param-inf", [*FORCES, *HOVER[:-1], "twist_amp=-inf"], "--param twist_amp=-inf is not finite"),
    ("forces/param-huge", [*FORCES, *HOVER[:-1], "twist_amp=1e308"], "--param twist_amp=1e+308"),
    ("forces/param-not-a-number", [*FORCES, *HOVER[:-1], "twist_amp=x"], "--param twist_amp='x' is not a number"),
    ("forces/param-malformed", [*FORCES, *HOVER, "--param", "oops"], "--param 'oops' is malformed"),
    ("forces/param-twice", [*FORCES, *HOVER, "--param", "pitch=0.2"], "--param pitch is given twice"),
    ("forces/speed-nan", ["forces", "--model", "m1", "--speed", "nan", *HOVER], "--speed=nan is invalid"),
    ("forces/speed-negative", ["forces", "--model", "m1", "--speed", "-1", *HOVER], "--speed=-1.0 is invalid"),
    ("forces/speed-inf", ["forces", "--model", "m1", "--speed", "inf", *HOVER], "--speed=inf is invalid"),
    ("forces/speed-not-a-number", ["forces", "--model", "m1", "--speed", "fast", *HOVER], "--speed='fast' is not a number"),
    ("forces/samples-zero", [*FORCES, *HOVER, "--samples", "0"], "--samples 0 is invalid"),
    ("forces/samples-huge", [*FORCES, *HOVER, "--samples", "1000000000"], "--samples 1000000000 is invalid"),
    ("forces/samples-not-int", [*FORCES, *HOVER, "--samples", "2.5"], "--samples '2.5' is not an integer; allowed: an integer"),
    ("forces/bird-missing", [*FORCES, *HOVER, "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("forces/bird-malformed-toml", [*FORCES, *HOVER, "--bird", "{w}/malformed.toml"], "--bird '{w}/malformed.toml' is not valid TOML"),
    ("forces/bird-directory", [*FORCES, *HOVER, "--bird", "{w}/folder"], "--bird '{w}/folder' is a folder"),
    ("forces/bird-binary", [*FORCES, *HOVER, "--bird", "{w}/table.npz"], "--bird '{w}/table.npz' is not valid TOML"),
    ("forces/bird-unknown-key", [*FORCES, *HOVER, "--bird", "{w}/bird_unknown_key.toml"], "--bird '{w}/bird_unknown_key.toml': bird key 'wingspan' is unknown"),
    ("forces/bird-negative", [*FORCES, *HOVER, "--bird", "{w}/bird_negative.toml"], "--bird '{w}/bird_negative.toml': bird.semispan=-1.0 is invalid"),
    ("forces/bird-nan", [*FORCES, *HOVER, "--bird", "{w}/bird_nan.toml"], "--bird '{w}/bird_nan.toml': bird.chord=nan is invalid"),
    ("forces/bird-wrong-type", [*FORCES, *HOVER, "--bird", "{w}/bird_type.toml"], "--bird '{w}/bird_type.toml': bird.semispan='long' is invalid"),
    ("forces/bird-bool", [*FORCES, *HOVER, "--bird", "{w}/bird_bool.toml"], "--bird '{w}/bird_bool.toml': bird.semispan=True is invalid"),
    ("forces/bird-unknown-polar", [*FORCES, *HOVER, "--bird", "{w}/bird_polar.toml"], "--bird '{w}/bird_polar.toml': polar.kind='magic' is unknown"),
    ("forces/bird-empty", [*FORCES, *HOVER, "--bird", ""], "--bird '' is empty"),
    ("forces/set-unknown-field", [*FORCES, *HOVER, "--set", "wingspan=2"], "--set wingspan=2 names no bird field"),
    ("forces/set-not-integer", [*FORCES, *HOVER, "--set", "strips=x"], "--set strips='x' is not an integer"),
    ("forces/set-out-of-bounds", [*FORCES, *HOVER, "--set", "strips=0"], "--set strips=0 is invalid"),
    ("forces/set-tail-zero", [*FORCES, *HOVER, "--set", "tail_length=0"], "--set tail_length=0.0 is invalid"),
    ("forces/set-tail-negative", [*FORCES, *HOVER, "--set", "tail_span=-0.1"], "--set tail_span=-0.1 is invalid"),
    ("forces/set-tail-nan", [*FORCES, *HOVER, "--set", "tail_root=nan"], "--set tail_root=nan is invalid"),
    ("forces/set-huge", [*FORCES, *HOVER, "--set", "strips=1000000000"], "--set strips=1000000000 is invalid"),
    ("forces/set-unknown-polar", [*FORCES, *HOVER, "--set", "polar.kind=magic"], "--set polar.kind='magic' is unknown"),
    ("forces/set-malformed", [*FORCES, *HOVER, "--set", "strips"], "--set 'strips' is malformed"),
    ("forces/unknown-option", [*FORCES, *HOVER, "--sped", "1"], "unrecognized arguments: --sped"),
    # issue 28 item 6: a single-valued option given twice is refused (argparse keeps the last)
    ("forces/model-twice", ["forces", "--model", "m1", "--model", "m3", "--speed", "0", *HOVER], "--model is given twice ('m1', 'm3'); allowed: once"),
    ("forces/bird-twice", [*FORCES, *HOVER, "--bird", "{w}/a.toml", "--bird", "{w}/b.toml"], "--bird is given twice"),
    ("forces/speed-twice", [*FORCES, *HOVER, "--speed", "0.5"], "--speed is given twice ('0', '0.5')"),
    ("fly/bird-twice", ["fly", "cruise", "--bird", "{w}/a.toml", "--bird", "{w}/b.toml"], "--bird is given twice"),
    ("fly/out-twice", ["fly", "cruise", "--out", "{w}/a.npz", "--out", "{w}/b.npz"], "--out is given twice"),
    ("render/camera-twice", [*RENDER, "--camera", "side", "--camera", "top"], "--camera is given twice"),
    ("export/format-twice", ["export", "cruise", "--format", "csv", "--format", "bvh", "--out", "{w}/x.csv"], "--format is given twice"),
    ("build/grid-twice", [*BUILD, "--grid", "V=0|1"], "--grid is given twice"),
    # absurd but finite numbers (issue 21 item 4): birdsim.errors.MAX_MAGNITUDE / MIN_POSITIVE
    ("forces/speed-huge", ["forces", "--model", "m3", "--speed", "1e300"], "--speed=1e+300 is invalid; allowed: a finite number >= 0, at most 1e+06 in magnitude"),
    ("forces/speed-overflows", ["forces", "--model", "m1", "--speed", "1e160", *HOVER], "--speed=1e+160 is invalid"),
    ("forces/climb-huge", [*FORCES, *HOVER, "--climb=-1e300"], "--climb=-1e+300 is invalid"),
    ("forces/set-mass-huge", [*FORCES, *HOVER, "--set", "mass=1e300"], "--set mass=1e+300 is invalid; allowed: a finite number > 0, at least 1e-06 and at most 1e+06"),
    ("forces/set-semispan-huge", [*FORCES, *HOVER, "--set", "semispan=1e300"], "--set semispan=1e+300 is invalid"),
    ("forces/set-omega-tiny", [*FORCES, *HOVER, "--set", "omega=1e-300"], "--set omega=1e-300 is invalid"),
    ("forces/set-gravity-huge", [*FORCES, *HOVER, "--set", "gravity=1e300"], "--set gravity=1e+300 is invalid"),
    ("forces/bird-huge", [*FORCES, *HOVER, "--bird", "{w}/bird_huge.toml"], "--bird '{w}/bird_huge.toml': bird.chord=1e+300 is invalid"),
    # ---- birdsim examples ---------------------------------------------------------------
    ("examples/unknown-option", ["examples", "--model", "m1"], "unrecognized arguments: --model"),
    # ---- birdsim tables build -----------------------------------------------------------
    ("build/unknown-model", ["tables", "build", "--model", "m9"], "--model 'm9' is unknown"),
    ("build/m5-bird-without-hand", [*BUILD[:3], "m5", *BUILD[4:], "--bird", "{w}/nohand.toml"], "bird: bird.hand_span_fraction=0.0 leaves no arm or no hand; allowed for model m5"),
    ("build/m5-coupling-out-of-range", [*BUILD[:3], "m5", *BUILD[4:], "--bird", "{w}/badfold.toml"], "--bird '{w}/badfold.toml': bird.fold_coupling=3.0 is invalid; allowed: a number in [0, 2]"),
    ("forces/m5-fold-out-of-bounds", ["forces", "--model", "m5", "--speed", "0.3", *M5_PARAMS, "--param", "fold_amp=1.5"], "--param fold_amp=1.5 is out of bounds for model m5; allowed: [0, 1.0472]"),
    ("build/grid-malformed", [*BUILD_NO_GRID, "--grid", "Fx=1:2"], "--grid 'Fx=1:2' is malformed"),
    ("build/grid-nan", [*BUILD_NO_GRID, "--grid", "Fx=nan:1:3"], "--grid"),
    ("build/grid-negative-V", [*BUILD_NO_GRID, "--grid", "V=-1:1:3"], "--grid V starts at -1"),
    ("build/grid-huge", [*BUILD_NO_GRID, "--grid", "Fx=-1:1:1000,Fz=-1:0:1000,V=0:1:1000"], "--grid"),
    ("build/grid-value-huge", [*BUILD_NO_GRID, "--grid", "Fx=-1e300:1e300:2,Fz=-0.5:0:2,V=0:1:2"], "--grid Fx=[-1e+300, 1e+300] is invalid"),
    ("build/grid-speed-huge", [*BUILD_NO_GRID, "--grid", "Fx=0:0.2:2,Fz=-0.5:0:2,V=0:1e300:2"], "--grid V=[0.0, 1e+300] is invalid"),
    ("build/set-chord-huge", [*BUILD, "--set", "chord=1e300"], "--set chord=1e+300 is invalid"),
    ("build/size-zero", ["tables", "build", "--model", "base", "--size", "0"], "--size 0 is invalid"),
    ("build/jobs-zero", [*BUILD_BASE, *TINY_GRID, "--jobs", "0"], "--jobs 0 is invalid"),
    ("build/screen-zero", [*BUILD, "--screen", "0"], "--screen"),
    ("build/starts-negative", [*BUILD, "--starts", "-1"], "--starts"),
    ("build/relax-too-large", [*BUILD, "--relax", "2"], "--relax"),
    ("build/distance-negative", [*BUILD, "--distance", "-1"], "--distance"),
    ("build/power-weight-nan", [*BUILD, "--power-weight", "nan"], "--power-weight"),
    ("build/incidence-weight-negative", [*BUILD, "--incidence-weight", "-1"], "--incidence-weight -1 is invalid"),
    ("build/incidence-params-unknown", [*BUILD, "--incidence-weight", "1e-4", "--incidence-params", "pitch,fold_amp"], "--incidence-params 'pitch,fold_amp' is invalid; allowed: comma-separated parameters of base"),
    ("build/reach-tol-zero", [*BUILD, "--reach-tol", "0"], "--reach-tol"),
    ("build/smooth-rounds-zero", [*BUILD, "--smooth-rounds", "0"], "--smooth-rounds 0 is invalid; allowed: an integer >= 1"),
    ("build/smooth-fixed-point-without-pass", [*BUILD, "--smooth-tol", "0", "--smooth-fixed-point"], "--smooth-fixed-point with --smooth-tol 0 is invalid; allowed: with a regularising pass"),
    ("build/smooth-planes-without-pass", [*BUILD, "--smooth-tol", "0", "--smooth-planes"], "--smooth-planes with --smooth-tol 0 is invalid; allowed: with a regularising pass"),
    ("build/out-exists", [*BUILD, "--out", "{w}/table.npz"], "--out '{w}/table.npz' exists"),
    ("build/out-is-a-folder", [*BUILD, "--out", "{w}/folder.npz", "--force"], "--out '{w}/folder.npz' is a directory"),
    ("build/out-parent-is-a-file", [*BUILD, "--out", "{w}/malformed.toml/t.npz"], "cannot be created"),
    ("build/out-unwritable", [*BUILD, "--out", "/proc/t.npz"], "--out '/proc/t.npz'"),
    ("build/bird-malformed", [*BUILD, "--bird", "{w}/malformed.toml"], "--bird '{w}/malformed.toml' is not valid TOML"),
    ("build/ctrl-c", Interrupt([*BUILD, "--out", "{w}/new.npz"], "birdsim.tables.build:solve_slice", keep=r"^\.new\.build(/|$)"), "interrupted"),
    # ---- birdsim tables info / lookup ---------------------------------------------------
    ("info/missing", ["tables", "info", "{w}/nope.npz"], "table file '{w}/nope.npz' does not exist"),
    ("info/folder", ["tables", "info", "{w}/folder.npz"], "table file '{w}/folder.npz' does not exist"),
    ("info/corrupt-pair", ["tables", "info", "{w}/corrupt.npz"], "do not belong together"),
    ("info/truncated", ["tables", "info", "{w}/truncated.npz"], "table file '{w}/truncated.npz' is unreadable or incomplete"),
    ("info/foreign-json", ["tables", "info", "{w}/foreign.json"], "table file '{w}/foreign.json' has format version None"),
    ("info/not-json", ["tables", "info", "{w}/notjson.npz"], "table file '{w}/notjson.json' is unreadable"),
    ("info/foreign-npz", ["tables", "info", "{w}/alien.npz"], "table file '{w}/alien.npz' is unreadable or incomplete"),
    ("jacobians/in-place-without-force", ["tables", "jacobians", "{w}/table.npz"], "--out is missing"),
    ("jacobians/out-exists", ["tables", "jacobians", "{w}/table.npz", "--out", "{w}/table.npz"], "--out '{w}/table.npz' exists"),
    ("jacobians/missing", ["tables", "jacobians", "{w}/nope.npz", "--out", "{w}/new.npz"], "table file '{w}/nope.npz' does not exist"),
    ("api/moments-u-length", lambda w: wingbeat_moments("m1", HOVER_PARAMS, 0.5, u=[1.0]), "u=[1.0] is invalid"),
    ("api/moments-rate-nan", lambda w: wingbeat_moments("m1", HOVER_PARAMS, 0.5, body_rate=(0, float("nan"), 0)), "body_rate=nan is invalid"),
    ("lookup/Fx-nan", ["tables", "lookup", "{w}/table.npz", "--Fx", "nan", "--Fz", "-0.3", "--V", "0"], "--Fx='nan' is not finite"),
    ("lookup/Fz-inf", ["tables", "lookup", "{w}/table.npz", "--Fx", "0", "--Fz=-inf", "--V", "0"], "--Fz='-inf' is not finite"),
    ("lookup/Fx-not-a-number", ["tables", "lookup", "{w}/table.npz", "--Fx", "a", "--Fz", "-0.3", "--V", "0"], "--Fx='a' is not a number"),
    ("lookup/V-negative", ["tables", "lookup", "{w}/table.npz", "--Fx", "0", "--Fz", "-0.3", "--V", "-1"], "--V=-1 is outside the table grid"),
    ("lookup/Fz-huge", ["tables", "lookup", "{w}/table.npz", "--Fx", "0", "--Fz", "1e300", "--V", "0"], "--Fz=1e+300 is outside the table grid"),
    ("lookup/missing", ["tables", "lookup", "{w}/nope.npz", "--Fx", "0", "--Fz", "-0.3", "--V", "0"], "table file '{w}/nope.npz' does not exist"),
    ("lookup/missing-flag", ["tables", "lookup", "{w}/table.npz", "--Fx", "0", "--Fz", "-0.3"], "the following arguments are required: --V"),
    ("tables/unknown-subcommand", ["tables", "destroy"], "invalid choice: 'destroy'"),
    # ---- birdsim crosscheck -------------------------------------------------------------
    ("crosscheck/unknown-model", ["crosscheck", "--model", "m9"], "--model 'm9' is unknown"),
    ("crosscheck/samples-one", ["crosscheck", "--model", "base", "--samples", "1"], "--samples 1 is invalid"),
    ("crosscheck/samples-huge", ["crosscheck", "--model", "base", "--samples", "1000000000"], "--samples 1000000000 is invalid"),
    ("crosscheck/random-negative", ["crosscheck", "--model", "base", "--random", "-1"], "--random -1 is invalid"),
    ("crosscheck/random-huge", ["crosscheck", "--model", "base", "--random", "1000000000"], "--random 1000000000 is invalid"),
    ("crosscheck/seed-negative", ["crosscheck", "--model", "base", "--seed", "-1", "--random", "1"], "--seed -1 is invalid"),
    ("crosscheck/forward-unknown", ["crosscheck", "--forward", "sideways"], "--forward: invalid choice: 'sideways'"),
    ("crosscheck/figure-suffix", ["crosscheck", "--model", "base", "--figure", "{w}/f.txt"], "--figure '{w}/f.txt' has an unknown suffix"),
    ("crosscheck/figure-exists", ["crosscheck", "--model", "base", "--figure", "{w}/exists.png"], "--figure '{w}/exists.png' exists"),
    ("crosscheck/figure-unwritable", ["crosscheck", "--model", "base", "--figure", "/proc/f.png"], "--figure '/proc/f.png'"),
    ("crosscheck/bird-missing", ["crosscheck", "--model", "base", "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("crosscheck/set-semispan-huge", ["crosscheck", "--model", "base", "--set", "semispan=1e300"], "--set semispan=1e+300 is invalid"),
    ("envelope/set-mass-huge", ["envelope", "--set", "mass=1e300"], "--set mass=1e+300 is invalid"),
    ("envelope/bird-huge", ["envelope", "--bird", "{w}/bird_huge.toml"], "--bird '{w}/bird_huge.toml': bird.chord=1e+300 is invalid"),
    ("fly/gust-wind-huge", ["fly", "cruise", "--quiet", "--gust", "0:1:1e300:0"], "--gust '0:1:1e300:0': gust wx=1e+300 is invalid"),
    ("fly/gust-duration-huge", ["fly", "cruise", "--quiet", "--gust", "0:1e300:1:0"], "gust duration=1e+300 is invalid"),
    ("fly/gust-start-huge", ["fly", "cruise", "--quiet", "--gust", "1e300:1:1:0"], "gust t0=1e+300 is invalid"),
    ("fly/manoeuvre-speed-huge", ["fly", "{w}/man_huge_v.toml", "--quiet"], "keyframe 1 V=1e+300 is invalid"),
    ("fly/manoeuvre-height-huge", ["fly", "{w}/man_huge_z.toml", "--quiet"], "keyframe 1 z=1e+300 is invalid"),
    ("fly/path-speed-huge", ["fly", "{w}/path_huge_v.toml", "--quiet"], "keyframe 2 V=1e+300 is invalid"),
    ("fly/bird-huge", ["fly", "cruise", "--quiet", "--bird", "{w}/bird_huge.toml"], "--bird '{w}/bird_huge.toml': bird.chord=1e+300 is invalid"),
    ("fly/seconds-huge", ["fly", "cruise", "--quiet", "--seconds", "1e300"], "--seconds 1e300 is"),
    ("render/gust-huge", [*RENDER, "--gust", "0:1:0:1e300"], "gust wz=1e+300 is invalid"),
    ("export/metres-per-unit-huge", ["export", "cruise", "--format", "csv", "--out", "{w}/x.csv", "--metres-per-unit", "1e300"], "--metres-per-unit '1e300' is invalid"),
    ("export/beat-rate-tiny", ["export", "cruise", "--format", "csv", "--out", "{w}/x.csv", "--beat-rate", "1e-300"], "--beat-rate 1e-300 is invalid"),
    ("export/gust-huge", ["export", "cruise", "--format", "csv", "--out", "{w}/x.csv", "--gust", "0:1:1e300:0"], "gust wx=1e+300 is invalid"),
    ("bird/mass-huge", ["bird", "new", "big", "--mass", "1e300", "--span", "1", "--mean-chord", "0.1", "--frequency", "5", "--out", "{w}/b.toml"], "--mass 1e+300 is invalid"),
    ("bird/span-huge", ["bird", "new", "big", "--mass", "1", "--span", "1e300", "--mean-chord", "0.1", "--frequency", "5", "--out", "{w}/b.toml"], "--span 1e+300 is invalid"),
    ("bird/frequency-tiny", ["bird", "new", "big", "--mass", "1", "--span", "1", "--mean-chord", "0.1", "--frequency", "1e-300", "--out", "{w}/b.toml"], "--frequency 1e-300 is invalid"),
    ("validate/data-speed-huge", ["validate", "--data", "{w}/measurements_huge.csv"], "speed_m_s='1e300' is invalid"),
    ("validate/bird-mass-huge", ["validate", "--bird", "{w}/bird_heavy.toml"], "bird.mass=1e+300 is invalid"),
    ("crosscheck/ctrl-c", Interrupt(["crosscheck", "--model", "base", "--forward", "none", "--samples", "8", "--figure", "{w}/new.png"],
                                    "birdsim.mujoco.crosscheck:crosscheck", after=1), "interrupted"),
    # ---- birdsim render (every mistake is found before any rendering) --------------------
    ("render/unknown-manoeuvre", ["render", "loop", "--table", "{w}/table.npz"], "manoeuvre 'loop' is unknown"),
    ("render/manoeuvre-missing", ["render", "{w}/nope.toml", "--table", "{w}/table.npz"], "manoeuvre file '{w}/nope.toml' does not exist"),
    ("render/manoeuvre-malformed", ["render", "{w}/malformed.toml", "--table", "{w}/table.npz"], "manoeuvre file '{w}/malformed.toml' is not valid TOML"),
    ("render/manoeuvre-folder", ["render", "{w}/folder.toml", "--table", "{w}/table.npz"], "manoeuvre file '{w}/folder.toml' cannot be read"),
    ("render/manoeuvre-unknown-key", ["render", "{w}/man_unknown_key.toml", "--table", "{w}/table.npz"], "key 'speed' is unknown"),
    ("render/manoeuvre-negative-V", ["render", "{w}/man_negative_v.toml", "--table", "{w}/table.npz"], "keyframe 1: V=-1 is negative"),
    ("render/manoeuvre-nan", ["render", "{w}/man_nan.toml", "--table", "{w}/table.npz"], "keyframe 1: Fz=nan is not a finite number"),
    ("render/manoeuvre-below-floor", ["render", "{w}/man_below.toml", "--kinematic", "--table", "{w}/table.npz"], "keyframe 2 (t=3) has z=-1, below the floor"),
    ("fly/manoeuvre-below-floor", ["fly", "{w}/man_below.toml"], "keyframe 2 (t=3) has z=-1, below the floor"),
    # issue 28 item 3: the keyframe that is itself below the floor is named, else the segment
    ("fly/path-keyframe-below-floor", ["fly", "{w}/path_kf2_low.toml", "--quiet"], "path 'path_kf2_low': keyframe 2 (t=4) is below the floor clearance"),
    ("fly/path-segment-below-floor", ["fly", "{w}/path_dip.toml", "--quiet"], "the segment from keyframe 2 (t=4) to keyframe 3 (t=8) goes below the floor clearance"),
    # issue 23 item 1: paths in 3-D
    ("fly/path-heading-not-a-number", ["fly", "{w}/path_heading_str.toml", "--quiet"], "keyframe 2: heading='left' is not a finite number; allowed: a finite number of radians"),
    ("fly/path-y-nan", ["fly", "{w}/path_y_nan.toml", "--quiet"], "keyframe 2: y=nan is not a finite number; allowed"),
    ("fly/path-key-unknown", ["fly", "{w}/path_bank.toml", "--quiet"], "keyframe 1: key 'bank' is unknown; allowed: t, x, y, V, heading"),
    ("fly/path-3d-through-perch", ["fly", "{w}/path_perch3d.toml", "--quiet"], "through the perch (within 0.55 of x = 6, y = 0"),
    ("fly/path-3d-below-floor", ["fly", "{w}/path_low3d.toml", "--quiet"], "keyframe 2 (t=4) is below the floor clearance"),
    ("fly/path-turning-posed", ["fly", "{w}/path_turn.toml", "--quiet", "--attitude", "posed"], "--attitude posed cannot fly"),
    ("render/path-turning-posed", ["render", "{w}/path_turn.toml", "--table", "{w}/table.npz", "--attitude", "posed"], "--attitude posed cannot fly"),
    ("export/path-turning-posed", ["export", "circle", "--format", "csv", "--out", "{w}/x.csv", "--attitude", "posed"], "--attitude posed cannot fly 'circle'"),
    ("export/attitude-kinematic", ["export", "cruise", "--format", "csv", "--out", "{w}/x.csv", "--kinematic", "--attitude", "free"], "--attitude needs free flight; allowed: omit --attitude with --kinematic"),
    ("fly/bird-missing", ["fly", "cruise", "--quiet", "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("render/bird-missing", [*RENDER, "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("export/bird-missing", ["export", "cruise", "--format", "csv", "--out", "{w}/x.csv", "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("envelope/bird-missing", ["envelope", "--bird", "{w}/nope.toml"], "--bird '{w}/nope.toml' does not exist"),
    ("fly/gust-three-numbers", ["fly", "cruise", "--gust", "1:1:0"], "--gust '1:1:0' has 3 field(s)"),
    ("fly/gust-six-numbers", ["fly", "cruise", "--gust", "1:1:0:0:0:0"], "--gust '1:1:0:0:0:0' has 6 field(s)"),
    ("fly/gust-nan", ["fly", "cruise", "--gust", "1:1:0:nan:0"], "--gust '1:1:0:nan:0' is not finite"),
    ("render/manoeuvre-huge-t", ["render", "{w}/man_huge_t.toml", "--table", "{w}/table.npz"], "keyframe t=1e+12"),
    ("render/unknown-model", [*RENDER_NO_MODEL, "--model", "m9"], "--model 'm9' is unknown"),
    ("render/size-odd", [*RENDER, "--size", "100x100"], "--size"),
    ("render/size-malformed", [*RENDER, "--size", "big"], "--size 'big' is malformed"),
    ("render/fps-zero", [*RENDER, "--fps", "0"], "--fps 0 is invalid"),
    ("render/fps-not-int", [*RENDER, "--fps", "x"], "--fps 'x' is not an integer"),
    ("render/seconds-nan", [*RENDER, "--seconds", "nan"], "--seconds nan is invalid"),
    ("render/seconds-negative", [*RENDER, "--seconds", "-1"], "--seconds -1.0 is invalid"),
    ("render/beat-rate-inf", [*RENDER, "--beat-rate", "inf"], "--beat-rate inf is invalid"),
    ("render/slow-motion-zero", [*RENDER, "--slow-motion", "0"], "--slow-motion 0 is invalid; allowed: a number in (0, 1000]"),
    ("render/slow-motion-and-beat-rate", [*RENDER, "--slow-motion", "2", "--beat-rate", "3"], "--beat-rate and --slow-motion both set the time base"),
    ("render/overlay-unknown", [*RENDER, "--overlay", "most"], "--overlay 'most' is unknown; allowed: short, full or none"),
    ("render/clean-with-forces", [*RENDER, "--clean", "--forces"], "--clean draws no force arrows"),
    ("export/slow-motion-text", ["export", "hover", "--format", "csv", "--out", "{w}/x.csv", "--slow-motion", "lots"], "--slow-motion 'lots' is not a number"),
    ("render/camera-unknown", [*RENDER, "--camera", "drone"], "--camera 'drone' is unknown"),
    ("render/gl-unknown", [*RENDER, "--gl", "vulkan"], "--gl 'vulkan' is unknown"),
    ("render/out-not-mp4", [*RENDER, "--out", "{w}/x.avi"], "--out '{w}/x.avi' does not end in .mp4"),
    ("render/out-exists", [*RENDER, "--out", "{w}/exists.mp4"], "--out '{w}/exists.mp4' exists"),
    ("render/out-unwritable", [*RENDER, "--out", "/proc/x.mp4"], "--out '/proc/x.mp4'"),
    ("render/sheet-not-png", [*RENDER, "--out", "{w}/x.mp4", "--sheet", "{w}/s.jpg"], "--sheet '{w}/s.jpg' does not end in .png"),
    ("render/table-missing", ["render", "hover", "--model", "base", "--table", "{w}/nope.npz", "--out", "{w}/x.mp4"], "--table '{w}/nope.npz' does not exist"),
    ("render/table-corrupt", ["render", "hover", "--model", "base", "--table", "{w}/corrupt.npz", "--out", "{w}/x.mp4"], "do not belong together"),
    ("render/table-other-model", ["render", "hover", "--model", "m4", "--table", "{w}/table.npz", "--out", "{w}/x.mp4"], "--table"),
    # ---- birdsim view / studio -------------------------------------------------------------
    ("view/out-not-html", ["view", "hover", "--out", "{w}/x.png"], "--out '{w}/x.png' does not end in .html"),
    ("view/out-exists", ["view", "hover", "--out", "{w}/done/index.html"], "--out '{w}/done/index.html' exists"),
    ("view/fps-zero", ["view", "hover", "--out", "{w}/x.html", "--fps", "0"], "--fps '0' is out of range; allowed: 1 to 240"),
    ("view/fps-text", ["view", "hover", "--out", "{w}/x.html", "--fps", "fast"], "--fps 'fast' is not a number"),
    ("view/source-unknown", ["view", "loop", "--out", "{w}/x.html"], "manoeuvre 'loop' is unknown"),
    ("view/source-malformed", ["view", "{w}/malformed.toml", "--out", "{w}/x.html"], "is not valid TOML"),
    ("view/log-not-a-log", ["view", "{w}/table.npz", "--out", "{w}/x.html"], "is not a birdsim flight log"),
    ("view/log-with-model", ["view", "{w}/table.npz", "--out", "{w}/x.html", "--model", "m4"], "--model does not apply to a flight log"),
    ("view/model-unknown", ["view", "hover", "--out", "{w}/x.html", "--model", "m9"], "model 'm9' is unknown"),
    ("studio/port-out-of-range", ["studio", "--port", "70000"], "--port '70000' is out of range; allowed: 1 to 65535"),
    ("studio/port-text", ["studio", "--port", "web"], "--port 'web' is not a whole number"),
    # ---- birdsim report -------------------------------------------------------------------
    ("report/only-unknown", ["report", "--out", "{w}/r", "--only", "nonsense"], "--only 'nonsense' is unknown"),
    ("report/out-exists", ["report", "--out", "{w}/done", "--only", "thrust"], "--out '{w}/done' already holds a report"),
    ("report/out-is-a-file", ["report", "--out", "{w}/malformed.toml", "--only", "thrust"], "--out '{w}/malformed.toml' is a file"),
    ("report/out-empty", ["report", "--out", "", "--only", "thrust"], "--out '' is empty"),
    ("report/out-parent-is-a-file", ["report", "--out", "{w}/malformed.toml/r", "--only", "thrust"], "--out '{w}/malformed.toml/r' cannot be created"),
    ("report/out-unwritable", ["report", "--out", "/proc/birdsim-report", "--only", "thrust"], "--out '/proc/birdsim-report' cannot be created"),
    ("report/bird-malformed", ["report", "--out", "{w}/r", "--bird", "{w}/malformed.toml"], "--bird '{w}/malformed.toml' is not valid TOML"),
    ("report/set-unknown", ["report", "--out", "{w}/r", "--set", "wingspan=2"], "--set wingspan=2 names no bird field"),
    ("report/ctrl-c", Interrupt(["report", "--out", "{w}/r", "--quick", "--only", "thrust", "--only", "wrist"],
                                "birdsim.report.plots:save_png", after=1), "interrupted"),
    # ---- Python: evaluate_cycle ---------------------------------------------------------
    ("py/evaluate_cycle-unknown-model", lambda w: evaluate_cycle("m9", HOVER_PARAMS, 0.0), "model 'm9' is unknown"),
    ("py/evaluate_cycle-param-nan", lambda w: evaluate_cycle("base", {**HOVER_PARAMS, "pitch": float("nan")}, 0.0), "parameter pitch=nan is not finite"),
    ("py/evaluate_cycle-param-array-inf", lambda w: evaluate_cycle("base", {**HOVER_PARAMS, "pitch": np.array([0.1, np.inf])}, 0.0), "parameter pitch=inf is not finite"),
    ("py/evaluate_cycle-param-out-of-bounds", lambda w: evaluate_cycle("base", {**HOVER_PARAMS, "twist_amp": 2.0}, 0.0), "twist_amp"),
    ("py/evaluate_cycle-param-missing", lambda w: evaluate_cycle("base", {"pitch": 0.1}, 0.0), "flap_amp"),
    ("py/evaluate_cycle-params-not-mapping", lambda w: evaluate_cycle("base", [0.1, 0.2, 0.3], 0.0), "params=[0.1, 0.2, 0.3] is not a mapping"),
    ("py/evaluate_cycle-speed-inf", lambda w: evaluate_cycle("base", HOVER_PARAMS, float("inf")), "speed=inf is invalid"),
    ("py/evaluate_cycle-speed-negative", lambda w: evaluate_cycle("base", HOVER_PARAMS, -1e300), "speed=-1e+300 is invalid"),
    ("py/evaluate_cycle-n-one", lambda w: evaluate_cycle("base", HOVER_PARAMS, 0.0, n=1), "n=1 is invalid"),
    ("py/evaluate_cycle-no-broadcast", lambda w: evaluate_cycle("base", {**HOVER_PARAMS, "pitch": np.zeros(2), "flap_amp": np.ones(3)}, 0.0), "do not broadcast"),
    ("py/evaluate_cycle-bird-not-a-bird", lambda w: evaluate_cycle("base", HOVER_PARAMS, 0.0, bird="pigeon"), "bird='pigeon'"),
    ("py/evaluate_cycle-speed-huge", lambda w: evaluate_cycle("base", HOVER_PARAMS, 1e300), "speed=1e+300 is invalid; allowed: a finite number >= 0, at most 1e+06 in magnitude"),
    ("py/evaluate_cycle-speed-array-huge", lambda w: evaluate_cycle("base", HOVER_PARAMS, np.array([0.5, 1e200])), "speed=1e+200 is invalid"),
    ("py/evaluate_cycle-climb-huge", lambda w: evaluate_cycle("base", HOVER_PARAMS, 0.0, climb=1e300), "climb=1e+300 is invalid"),
    ("py/ForceProblem-demand-huge", lambda w: ForceProblem("base", 1e300, -0.3, 0.0), "Fx_demand=1e+300 is invalid"),
    ("py/ForceProblem-speed-huge", lambda w: ForceProblem("base", 0.0, -0.3, 1e300), "speed=1e+300 is invalid"),
    ("py/crosscheck-speed-huge", lambda w: crosscheck("base", HOVER_PARAMS, 1e300), "speed=1e+300 is invalid"),
    ("py/fly-beats-huge", lambda w: fly(PATH_PRESETS["cruise"], load_table(SEED_TABLE), demo_bird(), "m3", beats=1e300), "beats=1e+300 is invalid"),
    ("py/Gust-huge", lambda w: Gust(0.0, 1.0, 1e300, 0.0), "gust wx=1e+300 is invalid"),
    ("py/Grid-huge", lambda w: Grid(Fx=np.array([0.0, 1e300]), Fz=np.array([-0.5, 0.0]), V=np.array([0.0, 1.0])), "grid Fx=[0.0, 1e+300] is invalid"),
    # ---- Python: tables ---------------------------------------------------------------
    ("py/load_table-missing", lambda w: load_table(w / "nope.npz"), "table file"),
    ("py/load_table-folder", lambda w: load_table(w / "folder.npz"), "does not exist"),
    ("py/load_table-truncated", lambda w: load_table(w / "truncated.npz"), "is unreadable or incomplete"),
    ("py/load_table-corrupt", lambda w: load_table(w / "corrupt.json"), "do not belong together"),
    ("py/lookup-nan", lambda w: _lookup(w, float("nan"), -0.3, 0.0), "Fx=nan is not finite"),
    ("py/lookup-outside", lambda w: _lookup(w, 0.0, -0.3, 5.0), "V=5 is outside the table grid; allowed: [0, 0.9] (or clip=True)"),
    ("py/lookup-not-a-number", lambda w: _lookup(w, "a", -0.3, 0.0), "Fx='a' is not a number"),
    ("py/LookupTable.save-exists", lambda w: load_table(w / "table.npz").save(w / "table.npz"), "exists; allowed: a new path, or force=True"),
    ("py/build_table-unknown-model", lambda w: build_table(BuildConfig("m9", TINY)), "model 'm9' is unknown"),
    ("py/build_table-checkpoint-dir-is-a-file", lambda w: build_table(BuildConfig("base", TINY), jobs=1, checkpoint_dir=w / "malformed.toml"), "checkpoint_dir"),
    ("py/BuildSettings-screen-zero", lambda w: BuildSettings(screen=0), "screen=0 is invalid"),
    ("py/Grid-nan", lambda w: Grid(Fx=np.array([np.nan, 1.0]), Fz=np.array([-0.5, 0.0]), V=np.array([0.0, 1.0])), "Fx="),
    ("py/build_table-jobs-negative", lambda w: build_table(BuildConfig("base", TINY), jobs=-1), "jobs=-1"),
    # ---- Python: Bird -------------------------------------------------------------------
    ("py/Bird-negative", lambda w: Bird(semispan=-1.0), "bird.semispan=-1.0 is invalid"),
    ("py/Bird-nan", lambda w: Bird(chord=float("nan")), "bird.chord=nan is invalid"),
    ("py/Bird-strips-huge", lambda w: Bird(strips=10**9), "bird.strips=1000000000 is invalid"),
    ("py/Bird-fraction", lambda w: Bird(hand_span_fraction=2.0), "bird.hand_span_fraction=2.0 is invalid"),
    ("py/Bird-bool", lambda w: Bird(mass=True), "bird.mass=True is invalid"),
    ("py/Bird-mass-huge", lambda w: Bird(mass=1e300), "bird.mass=1e+300 is invalid; allowed: a finite number > 0, at least 1e-06 and at most 1e+06"),
    ("py/Bird-omega-tiny", lambda w: Bird(omega=1e-300), "bird.omega=1e-300 is invalid"),
    ("py/Bird-drag-area-huge", lambda w: Bird(body_drag_area=1e300), "bird.body_drag_area=1e+300 is invalid"),
    ("py/Bird.from_toml-huge", lambda w: Bird.from_toml(w / "bird_huge.toml"), "bird.chord=1e+300 is invalid"),
    ("py/Bird.from_toml-missing", lambda w: Bird.from_toml(w / "nope.toml"), "path='"),
    ("py/Bird.from_toml-malformed", lambda w: Bird.from_toml(w / "malformed.toml"), "is not valid TOML"),
    ("py/Bird.from_toml-folder", lambda w: Bird.from_toml(w / "folder"), "is a folder"),
    ("py/Bird.from_toml-unknown-key", lambda w: Bird.from_toml(w / "bird_unknown_key.toml"), "bird key 'wingspan' is unknown"),
    ("py/Bird.with_overrides-not-integer", lambda w: Bird().with_overrides({"strips": "x"}), "overrides: strips='x' is not an integer"),
    # ---- Python: manoeuvres -------------------------------------------------------------
    ("py/get_manoeuvre-unknown", lambda w: get_manoeuvre("loop"), "manoeuvre 'loop' is unknown"),
    ("py/load_manoeuvre-missing", lambda w: load_manoeuvre(w / "nope.toml"), "does not exist"),
    ("py/load_manoeuvre-malformed", lambda w: load_manoeuvre(w / "malformed.toml"), "is not valid TOML"),
    ("py/load_manoeuvre-no-keyframes", lambda w: load_manoeuvre(w / "man_empty.toml"), "has no [[keyframe]] table and no [demands] table; allowed: either [[keyframe]] tables or one [demands] table"),
    ("py/load_manoeuvre-speed-huge", lambda w: load_manoeuvre(w / "man_huge_v.toml"), "keyframe 1 V=1e+300 is invalid"),
    ("py/Manoeuvre-force-huge", lambda w: Manoeuvre("m", (Keyframe(0.0, 1e300, -0.3, 0.0, 6.0),), 1.0), "keyframe 1 Fx=1e+300 is invalid"),
    ("py/get_flight-path-huge", lambda w: get_flight(str(w / "path_huge_v.toml")), "keyframe 2 V=1e+300 is invalid"),
    ("py/get_model-unknown", lambda w: get_model("m6"), "model 'm6' is unknown"),
]
# fmt: on


# ---- the work folder ----------------------------------------------------------------------


def _table(model: str) -> LookupTable:
    """A made-up table over TINY (no optimisation): valid for every reader."""
    m = get_model(model)
    shape = tuple(len(a) for a in (TINY.Fx, TINY.Fz, TINY.V))
    mid = np.array([(p.lower + p.upper) / 2 for p in m.params])
    return LookupTable(
        model=model,
        bird=Bird(),
        param_names=m.param_names,
        axes={"Fx": TINY.Fx, "Fz": TINY.Fz, "V": TINY.V},
        params=np.broadcast_to(mid, shape + (len(mid),)).copy(),
        cost=np.zeros(shape),
        cost_fractions=np.zeros(shape + (4,)),
        achieved=np.zeros(shape + (3,)),
        status_code=np.zeros(shape, dtype=np.uint8),
        evaluations=np.ones(shape, dtype=np.int64),
    )


@pytest.fixture(scope="module")
def template(tmp_path_factory: pytest.TempPathFactory) -> Path:
    w = tmp_path_factory.mktemp("bad-input-template")
    _table("base").save(w / "table.npz")
    # a pair that does not belong together: the npz of one table, the json of another
    _table("base").save(w / "corrupt.npz")
    (w / "corrupt.npz").write_bytes(_rewrite_npz(w / "table.npz", scale=2.0))
    # truncated: the json's checksum fits the cut file (a copy interrupted mid-way)
    _table("base").save(w / "truncated.npz")
    cut = (w / "table.npz").read_bytes()[:200]
    (w / "truncated.npz").write_bytes(cut)
    _set_checksum(w / "truncated.json", cut)
    # a foreign npz (not a table) with a matching json
    _table("base").save(w / "alien.npz")
    alien = _npz_bytes(something=np.arange(3))
    (w / "alien.npz").write_bytes(alien)
    _set_checksum(w / "alien.json", alien)
    (w / "foreign.json").write_text('{"name": "not a table"}\n')
    (w / "foreign.npz").write_bytes(alien)
    (w / "notjson.npz").write_bytes(alien)
    (w / "notjson.json").write_text("this is not JSON\n")
    for folder in ("folder", "folder.npz", "folder.toml"):
        (w / folder).mkdir()
    (w / "malformed.toml").write_text("semispan = = 1\n[polar\n")
    (w / "bird_unknown_key.toml").write_text("wingspan = 2.0\n")
    (w / "bird_negative.toml").write_text("semispan = -1.0\n")
    (w / "bird_nan.toml").write_text("chord = nan\n")
    (w / "nohand.toml").write_text("hand_span_fraction = 0.0\n")
    (w / "badfold.toml").write_text("fold_coupling = 3.0\n")
    (w / "bird_type.toml").write_text('semispan = "long"\n')
    (w / "bird_bool.toml").write_text("semispan = true\n")
    (w / "bird_polar.toml").write_text('[polar]\nkind = "magic"\n')
    (w / "bird_huge.toml").write_text("chord = 1e300\n")
    shipped = (
        Path(__file__).resolve().parent.parent / "birdsim" / "data" / "pigeon_measurements.csv"
    )
    (w / "measurements_huge.csv").write_text(shipped.read_text().replace(",4.46,,", ",1e300,,", 1))
    (w / "path_kf2_low.toml").write_text(
        "duration = 8\n[[keyframe]]\nt = 0\nV = 0.5\nz = 6\n[[keyframe]]\nt = 4\nV = 0.5\nz = 0.3\n"
        "[[keyframe]]\nt = 8\nV = 0.5\nz = 6\n"
    )
    (w / "path_dip.toml").write_text(
        "duration = 8\n[[keyframe]]\nt = 0\nx = 0\nz = 1.2\n[[keyframe]]\nt = 4\nx = 1\nz = 1.2\nvz = -2\n"
        "[[keyframe]]\nt = 8\nx = 2\nz = 6\n"
    )
    speed_path = "[[keyframe]]\nt = 0\nV = 0.3\nz = 6\n[[keyframe]]\nt = 4\nV = 0.3\n"
    (w / "path_heading_str.toml").write_text(speed_path + 'z = 6\nheading = "left"\n')
    (w / "path_turn.toml").write_text(speed_path + "z = 6\nheading = 1.0\n")
    (w / "path_low3d.toml").write_text(speed_path + "z = 0.4\nheading = 1.0\n")
    pos_path = (
        "[[keyframe]]\nt = 0\nx = 2\ny = 0.3\nz = 1.2\n[[keyframe]]\nt = 4\nx = 10\nz = 1.2\n"
    )
    (w / "path_perch3d.toml").write_text(pos_path + "y = 0.3\n")
    (w / "path_y_nan.toml").write_text(pos_path + "y = nan\n")
    (w / "path_bank.toml").write_text("[[keyframe]]\nt = 0\nV = 0.3\nbank = 0.5\nz = 6\n")
    (w / "bird_heavy.toml").write_text("mass = 1e300\ngravity = 0.012\n")
    (w / "man_huge_v.toml").write_text("[[keyframe]]\nt = 0\nFx = 0\nFz = -0.3\nV = 1e300\n")
    (w / "man_huge_z.toml").write_text("[[keyframe]]\nt = 0\nFx = 0\nFz = -0.3\nV = 0\nz = 1e300\n")
    (w / "path_huge_v.toml").write_text(
        "[[keyframe]]\nt = 0\nz = 6\nV = 0.5\n[[keyframe]]\nt = 4\nz = 6\nV = 1e300\n"
    )
    (w / "man_unknown_key.toml").write_text(
        "speed = 2\n[[keyframe]]\nt = 0\nFx = 0\nFz = -0.3\nV = 0\n"
    )
    (w / "man_negative_v.toml").write_text("[[keyframe]]\nt = 0\nFx = 0\nFz = -0.3\nV = -1\n")
    (w / "man_nan.toml").write_text("[[keyframe]]\nt = 0\nFx = 0\nFz = nan\nV = 0\n")
    (w / "man_below.toml").write_text(
        "[[keyframe]]\nt = 0\nFx = 0\nFz = -0.2\nV = 0.5\nz = 6\n[[keyframe]]\nt = 3\nFx = 0\nFz = -0.2\nV = 0.5\nz = -1\n"
    )
    (w / "man_huge_t.toml").write_text(
        "[[keyframe]]\nt = 0\nFx = 0\nFz = -0.3\nV = 0\n[[keyframe]]\nt = 1e12\nFx = 0\nFz = -0.3\nV = 0\n"
    )
    (w / "man_empty.toml").write_text('name = "empty"\n')
    (w / "exists.png").write_bytes(b"\x89PNG old figure")
    (w / "exists.mp4").write_bytes(b"old video")
    (w / "done").mkdir()
    (w / "done" / "index.html").write_text("<html>an earlier report</html>\n")
    return w


def _npz_bytes(**arrays: np.ndarray) -> bytes:
    import io

    buf = io.BytesIO()
    np.savez_compressed(buf, **arrays)
    return buf.getvalue()


def _rewrite_npz(path: Path, scale: float) -> bytes:
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    arrays["cost"] = arrays["cost"] + scale
    return _npz_bytes(**arrays)


def _set_checksum(json_path: Path, data: bytes) -> None:
    import json

    meta = json.loads(json_path.read_text())
    meta["npz_sha256"] = hashlib.sha256(data).hexdigest()
    json_path.write_text(json.dumps(meta))


def _snapshot(root: Path) -> dict[str, tuple]:
    out = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = Path(dirpath) / name
            st = p.lstat()
            digest = hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else "dir"
            out[str(p.relative_to(root))] = (
                digest,
                st.st_size if p.is_file() else 0,
                st.st_mtime_ns,
                st.st_mode,
            )
    return out


def _fill(item: Any, w: Path) -> Any:
    if isinstance(item, str):
        return item.replace("{w}", str(w))
    if isinstance(item, list):
        return [_fill(x, w) for x in item]
    return item


def _interrupting(monkeypatch: pytest.MonkeyPatch, target: str, after: int) -> None:
    module_name, attr = target.split(":")
    module = importlib.import_module(module_name)
    original = getattr(module, attr)
    calls = {"n": 0}

    def stop(*args: Any, **kwargs: Any) -> Any:
        calls["n"] += 1
        if calls["n"] > after:
            raise KeyboardInterrupt
        return original(*args, **kwargs)

    monkeypatch.setattr(module, attr, stop)


def _run_cli(argv: list[str], capsys: pytest.CaptureFixture) -> tuple[int, str]:
    capsys.readouterr()
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse's own usage errors
        code = exc.code if isinstance(exc.code, int) else 1
    return code, capsys.readouterr().err


FLAG = re.compile(r"(^|[\s(/])--[a-z]")


def _ids(cases: list) -> list:
    out = []
    for case in cases:
        if hasattr(case, "marks"):  # a pytest.param with marks
            out.append(pytest.param(*case.values, marks=case.marks, id=case.values[0]))
        else:
            out.append(pytest.param(*case, id=case[0]))
    return out


@pytest.mark.filterwarnings("error::RuntimeWarning")  # no numpy overflow warning on the way
@pytest.mark.parametrize("case_id, call, text", _ids(CASES))
def test_bad_input(
    case_id: str,
    call: Any,
    text: str,
    template: Path,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture,
) -> None:
    w = tmp_path / "w"
    shutil.copytree(template, w, symlinks=True)
    monkeypatch.chdir(w)
    monkeypatch.setenv("COLUMNS", "200")
    before = _snapshot(w)
    keep = ""
    if callable(call) and not isinstance(call, (list, Interrupt)):
        with pytest.raises(BirdsimError) as info:
            call(w)
        message = str(info.value)
        assert "\n" not in message, message
        assert text in message, message
        assert not FLAG.search(message), f"a Python caller is told about a flag: {message}"
    else:
        expected = 2
        argv = call
        if isinstance(call, Interrupt):
            _interrupting(monkeypatch, call.target, call.after)
            argv, expected, keep = call.argv, 130, call.keep
        code, err = _run_cli(_fill(argv, w), capsys)
        lines = err.splitlines()
        assert code == expected, err
        assert len(lines) == 1, err
        assert "Traceback" not in err
        assert _fill(text, w) in lines[0], lines[0]
        assert lines[0].startswith("birdsim"), lines[0]
    after = _snapshot(w)
    changed = {k for k in before.keys() | after.keys() if before.get(k) != after.get(k)}
    if keep:
        changed = {k for k in changed if not re.search(keep, k)}
    assert not changed, f"{case_id} wrote or changed {sorted(changed)}"


def test_the_matrix_covers_every_subcommand_and_function() -> None:
    ids = [c.values[0] if hasattr(c, "marks") else c[0] for c in CASES]
    assert len(ids) == len(set(ids)) and len(ids) >= 60
    prefixes = {i.split("/")[0] for i in ids}
    for part in (
        "forces",
        "examples",
        "build",
        "info",
        "lookup",
        "crosscheck",
        "render",
        "report",
        "py",
        "fly",
        "export",
        "bird",
        "envelope",
        "validate",
    ):
        assert part in prefixes, part
    for fn in (
        "evaluate_cycle",
        "load_table",
        "lookup",
        "Bird",
        "Bird.from_toml",
        "get_manoeuvre",
        "load_manoeuvre",
        "build_table",
    ):
        assert any(i.startswith(f"py/{fn}-") for i in ids), fn
