"""The scorecard: each published measurement beside birdsim's value for the same quantity.

birdsim's side comes from the trimmed level-flight sweep (:mod:`birdsim.validation.trim`),
never from fitted constants.  Verdicts (stated on every row):

* values and bounds: ratio r = birdsim / measured; within the measurement's uncertainty
  or a factor :data:`AGREE` (max(r, 1/r) <= 1.5) -> ``agrees``; within :data:`ROUGH` (2)
  -> ``rough``; beyond -> ``off``.  A bound that is met agrees.
* trends: the sign of birdsim's least-squares slope over the row's speed window against
  the measured sign -> ``same sign`` / ``opposite sign`` (not a ratio score).
* yes/no: equal -> ``agrees``, else ``off``.  ``shown`` rows are not compared.
* turning and perching rows (:data:`birdsim.validation.measurements.FLIGHT_KEYS`): their value comes
  from a turning flight (``score(..., turning=...)``); without one the row says
  :data:`NOT_SIMULATED`, which is not a failure and gets no variants.

Rows that are ``off`` are recomputed with the other polar and with induced velocity
toggled (:data:`VARIANTS`), so the reader sees which physics closes the gap.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.aero import RoboflyPolar, SeedPolar
from birdsim.physics.bird import Bird
from birdsim.validation.measurements import FLIGHT_KEYS, Measurement
from birdsim.validation.trim import TrimPoint, TrimSweep, angle_of_attack_deg, trim_sweep

AGREE, ROUGH = 1.5, 2.0
#: Speeds of the power curve [m/s]: 0 to 22 every 1 m/s (plus every speed a row names).
DEFAULT_SPEEDS = tuple(float(v) for v in range(0, 23))
#: Curve rows recomputed for a variant use every second speed of the curve.
CURVE_KEYS = {
    "min_power_speed",
    "max_lift_drag",
    "max_trim_speed",
    "min_trim_speed",
    "amplitude_slope",
    "body_angle_slope",
    "stroke_plane_slope",
    "span_ratio_slope",
}
#: A wingbeat "folds" when its span ratio (mid-upstroke / mid-downstroke) is below this
#: (issue 24's threshold for the optimiser folding in pigeon cruise).
FOLDED_SPAN_RATIO = 0.95
#: The verdict of a turning row while no turning flight gives its value (issue 23).
NOT_SIMULATED = "not yet simulated (turning flight: issue 23)"


@dataclass(frozen=True)
class Row:
    """One scorecard row: a measurement and birdsim's value in the measurement's unit."""

    measurement: Measurement
    birdsim: float | None
    ratio: float | None
    verdict: str
    variants: dict[str, float | None] = field(default_factory=dict)

    @property
    def birdsim_text(self) -> str:
        return self.value_text(self.birdsim)

    def value_text(self, value: float | None) -> str:
        """A birdsim value of this row (its own or a variant's) as printed."""
        m = self.measurement
        if value is None:
            return "not yet simulated" if m.compare in FLIGHT_KEYS else "cannot trim"
        if m.kind == "trend":
            return f"{value:+.3g} {_slope_unit(m.compare)}"
        if m.kind == "yesno":
            return "yes" if value else "no"
        return f"{value:.3g} {m.unit}"

    def to_dict(self) -> dict[str, object]:
        m = self.measurement
        return {
            "id": m.id,
            "quantity": m.quantity,
            "measured": m.to_dict(),
            "source": m.source,
            "url": m.url,
            "birdsim": self.birdsim,
            "birdsim_text": self.birdsim_text,
            "ratio": self.ratio,
            "verdict": self.verdict,
            "variants": dict(self.variants),
        }


def _slope_unit(key: str) -> str:
    if key == "span_ratio_slope":  # a ratio: no degrees
        return "per m/s"
    return "W per m/s" if key == "power_slope" else "deg per m/s"


def verdict_for(m: Measurement, value: float | None) -> tuple[float | None, str]:
    """(ratio, verdict text with its tolerance) of birdsim's ``value`` against ``m``."""
    if m.compare in FLIGHT_KEYS and value is None:
        return None, NOT_SIMULATED
    if m.kind == "shown":
        return None, "not scored (shown only)"
    if value is None:
        return None, "off: birdsim cannot trim here"
    if m.kind == "trend":
        same = (value < 0) == (m.value < 0) and value != 0
        return None, "same sign (trend, sign only)" if same else "opposite sign (trend, sign only)"
    if m.kind == "yesno":
        return None, "agrees (yes/no)" if (value >= 0.5) == (m.value >= 0.5) else "off (yes/no)"
    ratio = value / m.value if m.value != 0 else math.inf
    if m.kind == "at_least" and value >= m.value:
        return ratio, "agrees (bound met)"
    if m.kind == "at_most" and value <= m.value:
        return ratio, "agrees (bound met)"
    if m.uncertainty is not None and abs(value - m.value) <= m.uncertainty:
        return ratio, f"agrees (within ± {m.uncertainty:g} {m.unit})"
    factor = max(ratio, 1 / ratio) if ratio > 0 else math.inf
    if factor <= AGREE:
        return ratio, f"agrees (within x{AGREE:g})"
    if factor <= ROUGH:
        return ratio, f"rough (within x{ROUGH:g})"
    return ratio, f"off (beyond x{ROUGH:g})"


def model_value(m: Measurement, sweep: TrimSweep, bird: Bird) -> float | None:
    """birdsim's value of the quantity ``m.compare`` from ``sweep``, in ``m.unit``.

    Returns:
        The value, or None where the bird cannot trim (or a trend has < 2 trimmed speeds).
    Raises:
        BirdsimError: the row's speed is not in the sweep, or an unknown compare key.
    """
    key = m.compare
    if key in FLIGHT_KEYS:  # from a turning flight, not the sweep (see score)
        return None
    if key == "min_power_speed":
        mp = sweep.min_power()
        return None if mp is None else mp[0]
    if key in ("max_trim_speed", "min_trim_speed"):
        rng = sweep.trim_range()
        return None if rng is None else rng[1 if key == "max_trim_speed" else 0]
    if key == "max_lift_drag":
        weight = bird.mass * bird.gravity
        ld = [
            weight * p.speed / p.power
            for p in sweep.points
            if p.trimmed and p.speed > 0 and p.power > 0
        ]
        return max(ld) if ld else None
    if key.endswith("_slope"):
        lo, hi = m.speed_m_s or 0.0, m.speed_to_m_s or 0.0
        pts = [p for p in sweep.points if p.trimmed and lo - 1e-9 <= p.speed <= hi + 1e-9]
        if len(pts) < 2:
            return None
        x = np.array([p.speed for p in pts])
        if key == "span_ratio_slope":
            y = np.array([_span_ratio(sweep, p, bird) for p in pts])
            return float(np.polyfit(x, y, 1)[0])
        attr = {
            "amplitude_slope": "amplitude_deg",
            "body_angle_slope": "body_angle_deg",
            "stroke_plane_slope": "stroke_plane_deg",
        }[key]
        y = np.array([getattr(p, attr) for p in pts])
        return float(np.polyfit(x, y, 1)[0])
    if m.window is not None:  # the mean over the sweep's speeds of the window
        pts = window_points(m, sweep)
        if not pts or not all(p.trimmed for p in pts):
            return None
        vals = [_point_value(key, sweep, p, bird) for p in pts]
        return None if any(v is None for v in vals) else float(np.mean(vals))
    speed = (
        0.0
        if key in ("hover_power", "hover_feasible", "folds_in_hover", "fct_frequency_scaling")
        else (m.speed_m_s or 0.0)
    )
    p = sweep.at(speed)
    if key == "hover_feasible":
        return 1.0 if p.trimmed else 0.0
    if not p.trimmed:
        return None
    return _point_value(key, sweep, p, bird)


def window_points(m: Measurement, sweep: TrimSweep) -> list[TrimPoint]:
    """The sweep's points in ``m.window`` (its low end included, its high end not)."""
    lo, hi = m.window or (0.0, 0.0)
    return [p for p in sweep.points if lo - 1e-9 <= p.speed < hi - 1e-9]


def _point_value(key: str, sweep: TrimSweep, p: TrimPoint, bird: Bird) -> float | None:
    """birdsim's value of ``key`` at one trimmed point ``p`` of ``sweep``."""
    speed = p.speed
    if key in ("folds_in_cruise", "folds_in_hover"):
        return 1.0 if _span_ratio(sweep, p, bird) < FOLDED_SPAN_RATIO else 0.0
    if key in ("power", "hover_power"):
        return p.power
    if key == "wing_weight_support":
        return 100.0 * p.wing_lift_fraction
    if key == "aoa_mid_downstroke":
        return abs(angle_of_attack_deg(sweep.model, bird, p, 0.0))
    if key == "aoa_mid_upstroke":
        return abs(angle_of_attack_deg(sweep.model, bird, p, math.pi))
    if key == "stroke_plane_angle":
        return p.stroke_plane_deg
    if key == "amplitude":
        return p.amplitude_deg
    if key == "body_angle":
        return p.body_angle_deg
    if key in ("roll_damping", "fct_frequency_scaling"):
        from birdsim.validation.damping import damping_coefficients, frequency_scaling

        if key == "roll_damping":
            return damping_coefficients(sweep.model, bird, p.params, speed)[0]
        return 1.0 if abs(frequency_scaling(sweep.model, bird, p.params) - 2.0) < 0.02 else 0.0
    raise BirdsimError(f"compare={key!r} has no birdsim value; allowed: a key of COMPARE_KEYS")


def _span_ratio(sweep: TrimSweep, point, bird: Bird) -> float:
    """The trimmed wingbeat's span ratio (:func:`birdsim.physics.span.span_ratio`)."""
    from birdsim.physics.span import span_ratio

    return float(span_ratio(sweep.model, point.params, bird=bird, check_bounds=False))


def sweep_speeds(
    measurements: Sequence[Measurement], base: Sequence[float] = DEFAULT_SPEEDS
) -> tuple[float, ...]:
    """The curve's speeds plus every speed a row is evaluated at, sorted."""
    extra = {
        m.speed_m_s
        for m in measurements
        if m.speed_m_s is not None and m.kind != "trend" and m.compare not in FLIGHT_KEYS
    }
    return tuple(sorted(set(base) | {float(v) for v in extra}))


def variant_birds(bird: Bird) -> dict[str, Bird]:
    """The other polar, and induced velocity toggled."""
    other = SeedPolar() if isinstance(bird.polar, RoboflyPolar) else RoboflyPolar()
    return {
        f"{other.kind} polar": replace(bird, polar=other),
        "induced velocity " + ("off" if bird.induced_velocity else "on"): replace(
            bird, induced_velocity=not bird.induced_velocity
        ),
    }


def score(
    measurements: Sequence[Measurement],
    sweep: TrimSweep,
    bird: Bird,
    *,
    variants: bool = True,
    progress: Callable[[str], None] | None = None,
    turning: dict[str, float] | None = None,
) -> tuple[tuple[Row, ...], dict[str, TrimSweep]]:
    """Score every measurement against ``sweep``; rows that are off get variant values.

    Args:
        measurements: the rows of the data file.
        sweep: the bird's trimmed sweep; must contain every speed a row names
            (:func:`sweep_speeds`).
        bird: the bird of the sweep (its polar and induced velocity are toggled for the
            variants).
        variants: recompute off rows with the other physics.
        progress: called with each variant's label before its sweep.
        turning: birdsim's values of the turning rows by compare key (in the row's unit),
            from the turning flights; a key missing here is "not yet simulated".
    Returns:
        (rows, variant sweeps by label) -- the variant sweeps cover only what off rows need.
    Raises:
        BirdsimError: a row names a speed that is not in the sweep.
    """
    rows = []
    for m in measurements:
        if m.compare in FLIGHT_KEYS:
            v = (turning or {}).get(m.compare)
        else:
            v = model_value(m, sweep, bird)
        ratio, verdict = verdict_for(m, v)
        rows.append(Row(m, v, ratio, verdict))
    off = [
        r
        for r in rows
        if r.verdict.startswith(("off", "opposite")) and r.measurement.compare not in FLIGHT_KEYS
    ]
    vsweeps: dict[str, TrimSweep] = {}
    if variants and off:
        starts = {p.speed: np.array([p.params[n] for n in p.params]) for p in sweep.points}
        need_curve = any(r.measurement.compare in CURVE_KEYS for r in off)
        point_speeds = {
            0.0 if r.measurement.compare.startswith("hover") else (r.measurement.speed_m_s or 0.0)
            for r in off
            if r.measurement.compare not in CURVE_KEYS
        } | {
            p.speed
            for r in off
            if r.measurement.window
            for p in window_points(r.measurement, sweep)
        }
        speeds = sorted(point_speeds | (set(sweep.speeds[::2].tolist()) if need_curve else set()))
        for label, vb in variant_birds(bird).items():
            if progress is not None:
                progress(label)
            vsweeps[label] = trim_sweep(
                sweep.model,
                vb,
                speeds,
                start_from=[starts[s] for s in speeds],
                label=label,
                backward=False,
            )
        rows = [
            replace(
                r,
                variants={
                    lab: _safe(r.measurement, vs, vb)
                    for (lab, vs), vb in zip(vsweeps.items(), variant_birds(bird).values())
                },
            )
            if r in off
            else r
            for r in rows
        ]
    return tuple(rows), vsweeps


def _safe(m: Measurement, sweep: TrimSweep, bird: Bird) -> float | None:
    try:
        return model_value(m, sweep, bird)
    except BirdsimError:
        return None


__all__ = [
    "AGREE",
    "DEFAULT_SPEEDS",
    "NOT_SIMULATED",
    "ROUGH",
    "Row",
    "model_value",
    "score",
    "sweep_speeds",
    "variant_birds",
    "verdict_for",
    "window_points",
]
