"""Published measurements of a real bird, one row per measurement with its citation.

The data file is CSV (``birdsim/data/pigeon_measurements.csv`` for the pigeon) with the
columns :data:`COLUMNS`.  Each row names what birdsim quantity it is compared with
(``compare``, one of :data:`COMPARE_KEYS`) and how (``kind``, one of :data:`KINDS`):

``value``     a number with an optional uncertainty; scored by the ratio birdsim / measured
              (at ``speed_m_s``, or with ``speed_to_m_s`` too birdsim's mean over the
              sweep's speeds of that window, upper end excluded: :attr:`Measurement.window`)
``at_least``  a lower bound (e.g. the fastest speed flown); met, or scored by the ratio
``at_most``   an upper bound (e.g. the sprint power); met, or scored by the ratio
``trend``     the sign of d(quantity)/d(speed) between ``speed_m_s`` and ``speed_to_m_s``
              (value -1 or +1); compared by sign only, not scored by ratio
``yesno``     1 (yes) or 0 (no); compared, not scored by ratio
``shown``     shown beside birdsim's value, not compared (e.g. an angle whose convention
              was not read in the source)

A malformed row is one :class:`MeasurementsError` line naming the file, the row id (or
line) and the column.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from birdsim.errors import BirdsimError, limits_text, magnitude_ok

COLUMNS = (
    "id",
    "quantity",
    "compare",
    "kind",
    "speed_m_s",
    "speed_to_m_s",
    "value",
    "uncertainty",
    "uncertainty_kind",
    "unit",
    "n_birds",
    "author",
    "year",
    "journal",
    "volume",
    "pages",
    "where",
    "url",
    "note",
)
KINDS = ("value", "at_least", "at_most", "trend", "yesno", "shown")

#: birdsim quantities a row can be compared with, and the unit each is given in.
COMPARE_KEYS: dict[str, str] = {
    "min_power_speed": "m/s",
    "power": "W",
    "hover_power": "W",
    "max_lift_drag": "ratio",
    "max_trim_speed": "m/s",
    "min_trim_speed": "m/s",
    "wing_weight_support": "%",
    "aoa_mid_downstroke": "deg",
    "aoa_mid_upstroke": "deg",
    "stroke_plane_angle": "deg",
    "amplitude": "deg",
    "body_angle": "deg",
    "amplitude_slope": "sign",
    "body_angle_slope": "sign",
    "stroke_plane_slope": "sign",
    "hover_feasible": "yes=1",
    "span_ratio_slope": "sign",
    "folds_in_cruise": "yes=1",
    "folds_in_hover": "yes=1",
    "roll_damping": "non-dimensional",
    "fct_frequency_scaling": "yes=1",
    # turning flight (issue 23 item 5): from the turning presets' flights
    "turn_force_fixed_in_body": "yes=1",
    "turn_force_angle_in_body": "deg",
    "turn_radius": "m",
    "turn_heading_rate_follows_roll": "yes=1",
    "turn_bank_within_downstroke": "yes=1",
    # perching (issue 25): from the take-off and landing with legs (fly --legs)
    "perch_leg_share": "%",
    "perch_takeoff_peak_force": "body weights",
    "perch_touchdown_speed": "m/s",
    "perch_landing_over_takeoff_force": "ratio",
}
#: Keys whose birdsim value comes from a turning flight (the turning presets of
#: :mod:`birdsim.flight.turn_presets`), not from the level-flight sweep. Until the
#: bank-to-turn controller flies them, these rows print "not yet simulated" (not a failure).
TURNING_KEYS = frozenset(k for k in COMPARE_KEYS if k.startswith("turn_"))
#: Keys whose birdsim value comes from the take-off and landing with legs
#: (:mod:`birdsim.validation.perching`).
PERCH_KEYS = frozenset(k for k in COMPARE_KEYS if k.startswith("perch_"))
#: Rows scored from a flight rather than the sweep ("not yet simulated" without one).
FLIGHT_KEYS = TURNING_KEYS | PERCH_KEYS
#: Keys that need a speed (``speed_m_s``); trends need a window (``speed_to_m_s`` too).
NEEDS_SPEED = {
    "power",
    "roll_damping",
    "aoa_mid_downstroke",
    "aoa_mid_upstroke",
    "stroke_plane_angle",
    "amplitude",
    "body_angle",
    "wing_weight_support",
    "folds_in_cruise",
}


class MeasurementsError(BirdsimError):
    """A data file of measurements that cannot be read or has a malformed row."""


@dataclass(frozen=True)
class Measurement:
    """One published measurement and its citation (SI units unless ``unit`` says otherwise)."""

    id: str
    quantity: str
    compare: str
    kind: str
    value: float
    unit: str
    author: str
    year: int
    journal: str
    volume: str
    pages: str
    where: str
    url: str = ""
    note: str = ""
    uncertainty: float | None = None
    uncertainty_kind: str = ""
    n_birds: int | None = None
    speed_m_s: float | None = None
    speed_to_m_s: float | None = None

    @property
    def source(self) -> str:
        """``Author, year, journal volume:pages, where``."""
        return f"{self.author} {self.year}, {self.journal} {self.volume}:{self.pages}, {self.where}"

    @property
    def window(self) -> tuple[float, float] | None:
        """A value's window of speeds [speed_m_s, speed_to_m_s) [m/s], or None (one speed).

        A row measured over a range of speeds ("slow flight (<3 m/s)") is compared with
        birdsim's mean over the sweep's speeds from ``speed_m_s`` up to, not including,
        ``speed_to_m_s``; trends use their window for the slope instead.
        """
        if self.kind == "trend" or self.speed_to_m_s is None:
            return None
        return (self.speed_m_s or 0.0, self.speed_to_m_s)

    @property
    def scored(self) -> bool:
        """Whether the row gets a ratio verdict (values and bounds)."""
        return self.kind in ("value", "at_least", "at_most")

    def measured_text(self) -> str:
        """The measured value as printed in the scorecard."""
        if self.kind == "trend":
            window = f"{_fmt(self.speed_m_s)}-{_fmt(self.speed_to_m_s)} m/s"
            return ("decreases" if self.value < 0 else "increases") + f" with speed ({window})"
        if self.kind == "yesno":
            return "yes" if self.value else "no"
        bound = {"at_least": ">= ", "at_most": "<= "}.get(self.kind, "")
        unc = f" ± {_fmt(self.uncertainty)}" if self.uncertainty is not None else ""
        at = (
            ""
            if self.window is None
            else f" ({_fmt(self.window[0])} to <{_fmt(self.window[1])} m/s)"
        )
        return f"{bound}{_fmt(self.value)}{unc} {self.unit}{at}"

    def to_dict(self) -> dict[str, object]:
        return {
            "id": self.id,
            "quantity": self.quantity,
            "kind": self.kind,
            "value": self.value,
            "uncertainty": self.uncertainty,
            "uncertainty_kind": self.uncertainty_kind,
            "unit": self.unit,
            "speed_m_s": self.speed_m_s,
            "speed_to_m_s": self.speed_to_m_s,
            "text": self.measured_text(),
        }


def _fmt(v: float | None) -> str:
    return "" if v is None else f"{v:g}"


def default_path() -> Path:
    """The pigeon data file shipped with the package."""
    return Path(str(resources.files("birdsim") / "data" / "pigeon_measurements.csv"))


def load_measurements(path: str | Path | None = None) -> tuple[Measurement, ...]:
    """Read and check a measurements CSV (default: the shipped pigeon file).

    Raises:
        MeasurementsError: a missing file, a missing column, or a malformed row (named by
            its id, or its line when the id is empty or repeated).
    """
    p = Path(path) if path is not None else default_path()
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise MeasurementsError(
            f"--data {str(p)!r} does not exist; allowed: a measurements CSV file"
        ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise MeasurementsError(f"--data {str(p)!r} cannot be read: {exc}") from None
    reader = csv.DictReader(text.splitlines())
    missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
    if missing:
        raise MeasurementsError(
            f"measurements file {p.name}: column {missing[0]!r} is missing; allowed columns: {', '.join(COLUMNS)}"
        )
    rows: list[Measurement] = []
    seen: set[str] = set()
    for line, raw in enumerate(reader, start=2):
        rows.append(_parse_row(p.name, line, raw, seen))
    if not rows:
        raise MeasurementsError(
            f"measurements file {p.name} has no rows; allowed: at least one measurement"
        )
    return tuple(rows)


def _parse_row(name: str, line: int, raw: dict[str, str | None], seen: set[str]) -> Measurement:
    rid = (raw.get("id") or "").strip()
    where = (
        f"measurements file {name} row {rid!r} (line {line})"
        if rid
        else f"measurements file {name} line {line}"
    )

    def bad(column: str, value: object, allowed: str) -> MeasurementsError:
        return MeasurementsError(f"{where}: {column}={value!r} is invalid; allowed: {allowed}")

    if None in raw or any(v is None for v in raw.values()):
        raise MeasurementsError(
            f"{where}: has {len([v for v in raw.values() if v is not None])} fields; allowed: the {len(COLUMNS)} columns {', '.join(COLUMNS)}"
        )
    if not rid:
        raise bad("id", rid, "a non-empty identifier")
    if rid in seen:
        raise bad("id", rid, "an identifier not used by another row")
    seen.add(rid)
    f = {k: (v or "").strip() for k, v in raw.items()}
    for col in ("quantity", "unit", "author", "journal", "where"):
        if not f[col]:
            raise bad(col, f[col], "a non-empty text (every measurement needs its citation)")
    if f["kind"] not in KINDS:
        raise bad("kind", f["kind"], ", ".join(KINDS))
    if f["compare"] not in COMPARE_KEYS:
        raise bad("compare", f["compare"], ", ".join(COMPARE_KEYS))

    def number(col: str, required: bool, positive: bool = False) -> float | None:
        s = f[col]
        if not s:
            if required:
                raise bad(col, s, "a finite number")
            return None
        try:
            v = float(s)
        except ValueError:
            raise bad(col, s, "a finite number") from None
        if not math.isfinite(v) or (positive and v < 0) or not magnitude_ok(v):
            raise bad(
                col, s, "a finite number" + (" >= 0" if positive else "") + f", {limits_text()}"
            )
        return v

    value = number("value", True)
    assert value is not None
    unc = number("uncertainty", False, positive=True)
    speed = number("speed_m_s", f["compare"] in NEEDS_SPEED or f["kind"] == "trend", positive=True)
    speed_to = number("speed_to_m_s", f["kind"] == "trend", positive=True)
    if f["kind"] == "trend":
        if value not in (-1.0, 1.0):
            raise bad("value", f["value"], "-1 (decreases with speed) or 1 (increases) for a trend")
        if speed_to is None or speed is None or speed_to <= speed:
            raise bad(
                "speed_to_m_s", f["speed_to_m_s"], "a speed above speed_m_s (the trend's window)"
            )
    elif speed_to is not None and (speed is None or speed_to <= speed):
        raise bad(
            "speed_to_m_s",
            f["speed_to_m_s"],
            "empty, or a speed above speed_m_s (a value over a window of speeds)",
        )
    if f["kind"] == "yesno" and value not in (0.0, 1.0):
        raise bad("value", f["value"], "1 (yes) or 0 (no)")
    try:
        year = int(f["year"])
    except ValueError:
        raise bad("year", f["year"], "a year, e.g. 2005") from None
    n_birds = None
    if f["n_birds"]:
        try:
            n_birds = int(f["n_birds"])
        except ValueError:
            raise bad("n_birds", f["n_birds"], "an integer or empty") from None
    return Measurement(
        id=rid,
        quantity=f["quantity"],
        compare=f["compare"],
        kind=f["kind"],
        value=value,
        unit=f["unit"],
        author=f["author"],
        year=year,
        journal=f["journal"],
        volume=f["volume"],
        pages=f["pages"],
        where=f["where"],
        url=f["url"],
        note=f["note"],
        uncertainty=unc,
        uncertainty_kind=f["uncertainty_kind"],
        n_birds=n_birds,
        speed_m_s=speed,
        speed_to_m_s=speed_to,
    )


__all__ = [
    "COLUMNS",
    "COMPARE_KEYS",
    "KINDS",
    "Measurement",
    "MeasurementsError",
    "TURNING_KEYS",
    "PERCH_KEYS",
    "FLIGHT_KEYS",
    "default_path",
    "load_measurements",
]
