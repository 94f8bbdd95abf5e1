"""One validation run: bird file -> trimmed sweep -> scorecard -> the JSON object."""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path

from birdsim.errors import BirdConfigError
from birdsim.physics.aero import POLARS, polar_from_dict
from birdsim.physics.bird import Bird
from birdsim.validation.measurements import (
    PERCH_KEYS,
    TURNING_KEYS,
    Measurement,
    load_measurements,
)
from birdsim.validation.scorecard import Row, score, sweep_speeds
from birdsim.validation.tablecheck import find_table, level_flight_from_table
from birdsim.validation.trim import TrimSweep, trim_sweep

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

#: The shipped pigeon (SI), relative to the repository root.
DEFAULT_BIRD = Path(__file__).resolve().parents[2] / "models" / "pigeon.toml"


@dataclass(frozen=True)
class Validation:
    """Everything one run computed: the JSON object and what the page draws."""

    obj: dict
    rows: tuple[Row, ...]
    sweep: TrimSweep
    variants: dict[str, TrimSweep]


def load_flying_bird(path: str | Path | None, polar: str | None = None) -> Bird:
    """A bird file that states its mass and gravity (a real bird in consistent units).

    Raises:
        BirdConfigError: no such file, invalid TOML, missing ``mass`` or ``gravity`` (or
            gravity 0), an unknown polar.
    """
    p = Path(path) if path is not None else DEFAULT_BIRD
    if path is None and not p.exists():
        raise BirdConfigError(
            f"--bird: the default pigeon {str(p)!r} is missing; allowed: --bird FILE.toml with mass and gravity"
        )
    try:
        data = tomllib.loads(p.read_text())
    except FileNotFoundError:
        raise BirdConfigError(
            f"--bird {str(p)!r} does not exist; allowed: a readable TOML file"
        ) from None
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise BirdConfigError(f"--bird {str(p)!r} is not valid TOML: {exc}") from None
    for key in ("mass", "gravity"):
        if key not in data:
            raise BirdConfigError(
                f"--bird {str(p)!r} has no {key}; allowed: a bird file with mass and gravity > 0 (validation flies the bird's weight)"
            )
    bird = Bird.from_dict(data)
    if not bird.gravity > 0:
        raise BirdConfigError(
            f"--bird {str(p)!r}: gravity={bird.gravity!r} is invalid; allowed: a number > 0"
        )
    if polar is not None:
        if polar not in POLARS:
            raise BirdConfigError(f"--polar {polar!r} is unknown; allowed: {', '.join(POLARS)}")
        if polar != bird.polar.kind:
            bird = replace(bird, polar=polar_from_dict({"kind": polar}))
    return bird


def table_label(bird: Bird, model: str) -> str:
    """The shipped table's file name for the bird and model (for the JSON and the page)."""
    from birdsim.tables.shipped import shipped_table

    return shipped_table(bird, model).name


def validate(
    bird: Bird,
    model: str = "m3",
    measurements: tuple[Measurement, ...] | None = None,
    *,
    bird_file: str = "",
    variants: bool = True,
    use_table: bool = True,
    progress: bool = False,
) -> Validation:
    """Trim the bird over the speeds, score every measurement, build the JSON object.

    With ``use_table`` the shipped table for the bird and model (if one fits) adds a start
    at each speed in its grid and its interpolated power is reported beside the solve's
    (``power_curve[i].table_power``).

    Args:
        bird: a bird with mass and gravity, in consistent units (SI: m/s and W out).
        model: kinematic model name.
        measurements: rows to score (default: the shipped pigeon file).
        bird_file: recorded in the JSON object.
        variants: recompute off rows with the other polar and induced velocity toggled.
        use_table: use the shipped table as a start and cross-check.
        progress: a tqdm bar over the speeds on stderr.
    Returns:
        Validation (the JSON object, rows, sweep and variant sweeps).
    Raises:
        BirdsimError: bird without gravity, unknown model, malformed measurements.
    """
    t0 = time.perf_counter()
    ms = measurements if measurements is not None else load_measurements()
    speeds = sweep_speeds(ms)
    table = find_table(bird, model) if use_table else None
    tab = level_flight_from_table(table, bird, speeds) if table is not None else None
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(
            total=len(speeds), unit="speed", desc=f"validate {model}", leave=False, disable=None
        )
    try:
        sweep = trim_sweep(
            model, bird, speeds, extra_starts=tab.starts if tab else None, progress=bar
        )
    finally:
        if bar is not None:
            bar.close()
    flights: dict[str, float] = {}
    if any(m.compare in PERCH_KEYS for m in ms):  # issue 25: take-off and landing with legs
        from birdsim.validation.perching import perch_values

        flights.update(perch_values(bird))
    turning_flight = None
    if any(m.compare in TURNING_KEYS for m in ms):  # issue 23: the slow 90-degree turn
        from birdsim.validation.turning import turn_values

        values, turning_flight = turn_values(bird)
        flights.update(values)
    rows, vsweeps = score(ms, sweep, bird, variants=variants, turning=flights)
    mp = sweep.min_power()
    rng = sweep.trim_range()
    hover = any(p.trimmed for p in sweep.points if p.speed == 0.0)
    obj = {
        "model": sweep.model,
        "bird": bird.name,
        "bird_file": bird_file,
        "polar": bird.polar.kind,
        "induced_velocity": bird.induced_velocity,
        "units": {
            "speed": "m/s",
            "power": "W (whole bird, both wings, mechanical)",
            "params": "rad (table names)",
        },
        "rows": [r.to_dict() for r in rows],
        "power_curve": [
            {**p.to_dict(), "table_power": None if tab is None else tab.power[i]}
            for i, p in enumerate(sweep.points)
        ],
        "table": None if table is None else table_label(bird, model),
        "min_power_speed": None if mp is None else mp[0],
        "min_power": None if mp is None else mp[1],
        "trim_range": None if rng is None else list(rng),
        "hover": hover,
        "variants": {k: [p.to_dict() for p in v.points] for k, v in vsweeps.items()},
        "turning_flight": turning_flight,
        "seconds": time.perf_counter() - t0,
    }
    return Validation(obj, rows, sweep, vsweeps)


def scorecard_text(v: Validation) -> str:
    """The scorecard as a plain-text table (the command's default output)."""
    lines = [
        f"birdsim validate: {v.obj['bird']}, model {v.obj['model']}, {v.obj['polar']} polar"
        + (", induced velocity on" if v.obj["induced_velocity"] else ""),
        f"{'quantity':60s} {'measured':32s} {'birdsim':20s} {'ratio':>6s}  verdict   [source]",
    ]
    for r in v.rows:
        m = r.measurement
        ratio = "" if r.ratio is None else f"{r.ratio:.2f}"
        lines.append(
            f"{m.quantity[:60]:60s} {m.measured_text()[:32]:32s} {r.birdsim_text:20s} {ratio:>6s}  {r.verdict}   [{m.source}]"
        )
        for k, val in r.variants.items():
            lines.append(f"{'':60s} {'':32s}   with {k}: {r.value_text(val)}")
    mp, rng, pmin = v.obj["min_power_speed"], v.obj["trim_range"], v.obj["min_power"]
    lines.append(
        f"minimum-power speed {'none' if mp is None else f'{mp:.2f} m/s ({pmin:.2f} W)'}; "
        f"trimmed {'none' if rng is None else f'{rng[0]:g}-{rng[1]:g} m/s'}; hover {'trims' if v.obj['hover'] else 'does not trim'}; "
        f"table {v.obj['table'] or 'none'}; {v.obj['seconds']:.1f} s"
    )
    if v.obj.get("turning_flight"):
        lines.append(f"turning rows from {v.obj['turning_flight']}")
    return "\n".join(lines)


__all__ = ["DEFAULT_BIRD", "Validation", "load_flying_bird", "scorecard_text", "validate"]
