"""The bird: wing geometry, aerodynamic coefficients and flapping frequency.

One frozen dataclass, read from and written to TOML.  Units are the dissertation's
non-dimensional ones (rho = 1, omega = 1, semispan = 1, chord = 1) unless a bird file
says otherwise; any consistent unit system works.

Geometry per model (docs/design.md): the single-panel models (base, m1, m2, m3) use one
panel of span ``semispan`` and chord ``chord``.  m4 splits the semispan into an arm
of span ``semispan * (1 - hand_span_fraction)`` (chord ``chord``) and a hand of span
``semispan * hand_span_fraction`` (chord ``hand_chord``).  m5 (the folding wing) has
m4's panels, an elbow at ``elbow_span_fraction`` of the arm span, a wrist that flexes
``fold_coupling`` times the elbow and a hand whose area shrinks by up to
``hand_fold_area_loss`` as the wrist folds (:mod:`birdsim.physics.m5`).
"""

from __future__ import annotations

import math
import sys
from dataclasses import asdict, dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from birdsim.errors import BirdConfigError, limits_text, magnitude_ok
from birdsim.physics.aero import Polar, SeedPolar, polar_from_dict

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


@dataclass(frozen=True)
class PanelGeometry:
    """One wing panel: span along its own y axis, chord, and where its root sits
    along the previous panel's span (0 for the arm, the arm span for the hand)."""

    name: str
    span: float
    chord: float
    root_offset: float

    @property
    def area(self) -> float:
        return self.span * self.chord


@dataclass(frozen=True)
class Bird:
    """Geometry, coefficients and flapping frequency of one (right) wing and its body.

    ``mass`` is the whole bird's [mass units of the bird file: kg for an SI bird];
    ``gravity`` its gravitational acceleration [length / time^2], 0 = weightless (the
    first-stage default; free flight needs a bird file that sets it). Reference scales and
    the reduced (non-dimensional) bird that tables are built for: :mod:`birdsim.physics.units`.
    """

    name: str = "seed"
    semispan: float = 1.0
    chord: float = 1.0
    hand_span_fraction: float = 1.0 / 3.0
    hand_chord: float = 1.0
    cp_span_fraction: float = 0.5
    strips: int = 1
    wrist_twist_ratio: float = 0.25
    elbow_span_fraction: float = 0.45
    fold_coupling: float = 1.0
    hand_fold_area_loss: float = 0.6
    rho: float = 1.0
    omega: float = 1.0
    body_drag_area: float = 1.0
    induced_velocity: bool = False
    disc_area: float = math.pi
    mass: float = 1.0
    gravity: float = 0.0
    polar: Polar = field(default_factory=SeedPolar)
    # ---- free flight: the tail and the body's inertia (issue 22; the wings' tables do
    # not depend on them, see FLIGHT_FIELDS).  Lengths in the bird's length unit, the
    # seed bird's derived in models/seed-bird.toml, the pigeon's in models/pigeon.toml.
    #: tail length from its root to the tip of the spread fan
    tail_length: float = 0.30
    #: widest spread span of the tail fan (slender-wing span b at full spread)
    tail_span: float = 0.48
    #: distance of the tail's root behind the centre of mass (along the body's -x)
    tail_root: float = 0.24
    #: torso's principal moments of inertia (roll, pitch, yaw; seed body axes, about the
    #: centre of mass) [mass x length^2]; empty: a solid box of the bird's mass, 1.1 x
    #: 0.26 x 0.26 semispans (the model's drawn torso)
    body_inertia: tuple[float, ...] = ()
    # ---- legs and feet (issue 25; free flight with contact only, birdsim/mujoco/legs.py).
    # The seed bird's are the pigeon's reduced values (models/seed-bird.toml).
    #: leg length from the hip to the sole of the foot when standing [length]
    leg_length: float = 0.21
    #: mass of ONE leg and foot as a fraction of the bird's mass (taken out of the torso,
    #: so the whole bird weighs the same)
    leg_mass_fraction: float = 0.04
    #: toe span of one foot, front toe tip to hind toe tip [length]: the foot's grip
    toe_span: float = 0.155
    # ---- the optimiser's power (issue 24; birdsim/physics/shaft_power.py).  "net": the
    # cycle-mean aerodynamic power (negative work credited, today's cost); "positive":
    # the mean of the positive part of aerodynamic plus inertial power (work the muscles
    # cannot recover).  Left out of ``to_dict`` at their defaults (files stay as before).
    power_cost: str = "net"
    #: ONE wing's mass as a fraction of the bird's, lumped at the panels' control points
    #: by area (only the "positive" power cost reads it; 0: massless wings)
    wing_mass_fraction: float = 0.0

    def __post_init__(self) -> None:
        for name in ("leg_length", "toe_span"):
            v = getattr(self, name)
            if not (_is_number(v) and math.isfinite(v) and v > 0):
                raise BirdConfigError(f"bird.{name}={v!r} is invalid; allowed: a finite number > 0")
        v = self.leg_mass_fraction
        if not (_is_number(v) and math.isfinite(v) and 0 < v <= 0.2):
            raise BirdConfigError(
                f"bird.leg_mass_fraction={v!r} is invalid; allowed: a number in (0, 0.2] "
                "(one leg's share of the bird's mass)"
            )
        for name in ("tail_length", "tail_span"):
            v = getattr(self, name)
            if not (_is_number(v) and math.isfinite(v) and v > 0):
                raise BirdConfigError(f"bird.{name}={v!r} is invalid; allowed: a finite number > 0")
        if not (
            _is_number(self.tail_root) and math.isfinite(self.tail_root) and self.tail_root >= 0
        ):
            raise BirdConfigError(
                f"bird.tail_root={self.tail_root!r} is invalid; allowed: a finite number >= 0"
            )
        inertia = tuple(self.body_inertia) if isinstance(self.body_inertia, (list, tuple)) else None
        if inertia is None or (
            inertia
            and not (
                len(inertia) == 3
                and all(_is_number(v) and math.isfinite(v) and v > 0 for v in inertia)
            )
        ):
            raise BirdConfigError(
                f"bird.body_inertia={self.body_inertia!r} is invalid; allowed: [] or three finite numbers > 0"
            )
        object.__setattr__(self, "body_inertia", tuple(float(v) for v in inertia))
        positive = ("semispan", "chord", "hand_chord", "rho", "omega", "disc_area", "mass")
        for name in positive:
            v = getattr(self, name)
            if not (_is_number(v) and math.isfinite(v) and magnitude_ok(v, positive=True)):
                raise BirdConfigError(
                    f"bird.{name}={v!r} is invalid; allowed: a finite number > 0, {limits_text(positive=True)}"
                )
        fractions = ("hand_span_fraction", "cp_span_fraction")
        for name in fractions:
            v = getattr(self, name)
            if not (_is_number(v) and 0.0 <= v <= 1.0):
                raise BirdConfigError(f"bird.{name}={v!r} is invalid; allowed: a number in [0, 1]")
        for name in ("wrist_twist_ratio", "body_drag_area", "gravity"):
            v = getattr(self, name)
            if not (_is_number(v) and math.isfinite(v) and v >= 0 and magnitude_ok(v)):
                raise BirdConfigError(
                    f"bird.{name}={v!r} is invalid; allowed: a finite number >= 0, {limits_text()}"
                )
        for name, lo, hi, why in _FOLD_RANGES:
            v = getattr(self, name)
            if not (_is_number(v) and lo <= v <= hi):
                raise BirdConfigError(f"bird.{name}={v!r} is invalid; allowed: {why}")
        if not (
            isinstance(self.strips, int)
            and not isinstance(self.strips, bool)
            and 1 <= self.strips <= 10_000
        ):
            raise BirdConfigError(
                f"bird.strips={self.strips!r} is invalid; allowed: an integer in [1, 10000]"
            )
        if not isinstance(self.polar, Polar):
            raise BirdConfigError(f"bird.polar={self.polar!r} is invalid; allowed: a Polar object")
        if self.power_cost not in POWER_COSTS:
            raise BirdConfigError(
                f"bird.power_cost={self.power_cost!r} is invalid; allowed: {' or '.join(POWER_COSTS)}"
            )
        v = self.wing_mass_fraction
        if not (_is_number(v) and 0.0 <= v <= 0.5):
            raise BirdConfigError(
                f"bird.wing_mass_fraction={v!r} is invalid; allowed: a number in [0, 0.5] "
                "(one wing's share of the bird's mass)"
            )

    def panels(self, model: str) -> tuple[PanelGeometry, ...]:
        """The wing panels of ``model``: one for base..m3, arm and hand for m4."""
        if model in ("m4", "m5"):
            hand = self.semispan * self.hand_span_fraction
            arm = self.semispan - hand
            return (
                PanelGeometry("arm", arm, self.chord, 0.0),
                PanelGeometry("hand", hand, self.hand_chord, arm),
            )
        return (PanelGeometry("wing", self.semispan, self.chord, 0.0),)

    @property
    def period(self) -> float:
        """One wingbeat, ``2 pi / omega``."""
        return 2.0 * math.pi / self.omega

    # ---- TOML in and out -------------------------------------------------------------

    def to_dict(self) -> dict[str, Any]:
        d = {f.name: getattr(self, f.name) for f in fields(self) if f.name != "polar"}
        d["body_inertia"] = list(self.body_inertia)
        d["polar"] = self.polar.to_dict()
        for name, default in _COST_DEFAULTS.items():
            if d[name] == default:
                del d[name]  # bird files and tables written before the option, unchanged
        return d

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "Bird":
        d = dict(d)
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(d) - known)
        if unknown:
            raise BirdConfigError(
                f"bird key {unknown[0]!r} is unknown; allowed: {', '.join(sorted(known))}"
            )
        if "polar" in d and isinstance(d["polar"], dict):
            d["polar"] = polar_from_dict(d["polar"])
        return cls(**d)

    @classmethod
    def from_toml(cls, path: str | Path) -> "Bird":
        """Read a bird from a TOML file of :class:`Bird` fields (``[polar]`` a table).

        Args:
            path: the TOML file.

        Returns:
            The bird; fields the file leaves out keep their defaults.

        Raises:
            BirdConfigError: one line starting ``path='...'`` when the file is missing,
                a folder, unreadable, not TOML, or holds an unknown or invalid field.
        """
        if not str(path).strip():
            raise BirdConfigError(f"path={str(path)!r} is empty; allowed: a readable TOML file")
        p = Path(path)
        arg = f"path={str(p)!r}"
        try:
            data = tomllib.loads(p.read_text())
        except FileNotFoundError:
            raise BirdConfigError(f"{arg} does not exist; allowed: a readable TOML file") from None
        except IsADirectoryError:
            raise BirdConfigError(f"{arg} is a folder; allowed: a readable TOML file") from None
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
            raise BirdConfigError(f"{arg} is not valid TOML: {exc}") from None
        try:
            return cls.from_dict(data)
        except BirdConfigError as exc:
            raise BirdConfigError(f"{arg}: {exc}") from None

    def to_toml(self, path: str | Path) -> None:
        import tomli_w

        from birdsim.io import write_atomic

        write_atomic(Path(path), tomli_w.dumps(self.to_dict()).encode())

    def with_overrides(self, overrides: dict[str, str]) -> "Bird":
        """A copy with ``NAME=VALUE`` strings applied (``--set`` on the command line).

        ``polar.NAME`` sets a coefficient of the polar; ``polar.kind`` switches to another
        polar, which starts from its own default coefficients.

        Args:
            overrides: field name -> value as text (``{"strips": "20"}``).

        Returns:
            The new bird (this one is unchanged).

        Raises:
            BirdConfigError: one line starting ``overrides: NAME=...`` for an unknown
                field, a value of the wrong type or a value out of bounds.
        """
        top: dict[str, Any] = {}
        polar = self.polar.to_dict()
        kind = overrides.get("polar.kind")
        if kind is not None and kind != polar["kind"]:
            polar = {"kind": kind}  # the old polar's coefficients do not fit the new kind
        types = {f.name: type(getattr(self, f.name)) for f in fields(self)}
        for key, raw in overrides.items():
            if key.startswith("polar."):
                sub = key.split(".", 1)[1]
                polar[sub] = raw if sub == "kind" else _parse_number(key, raw)
                continue
            if key not in types or key == "polar":
                raise BirdConfigError(
                    f"overrides: {key}={raw} names no bird field; allowed: {', '.join(sorted(types))}"
                )
            top[key] = _parse_value(key, raw, types[key])
        try:
            if polar != self.polar.to_dict():
                top["polar"] = polar_from_dict(polar)
            return replace(self, **top)
        except (
            BirdConfigError
        ) as exc:  # "bird.strips=0 is invalid" -> "overrides: strips=0 is invalid"
            raise BirdConfigError(f"overrides: {str(exc).removeprefix('bird.')}") from None


#: Bird fields that only free flight uses (the tables' wings do not depend on them).
FLIGHT_FIELDS = (
    "tail_length",
    "tail_span",
    "tail_root",
    "body_inertia",
    "leg_length",
    "leg_mass_fraction",
    "toe_span",
)

#: The optimiser's power measures (the ``power_cost`` field).
POWER_COSTS = ("net", "positive")
#: Fields left out of ``to_dict`` at these (default) values.
_COST_DEFAULTS = {"power_cost": "net", "wing_mass_fraction": 0.0}

#: m5's skeleton: (field, lower, upper, what is allowed and why).  Estimates, not
#: measured ranges (docs/conventions.md): the elbow strictly inside the arm (a humerus and
#: a forearm of non-zero length); the wrist flexing between not at all and twice the
#: elbow (1 is the planar "drawing parallels" coupling); the hand losing at most all of
#: its area when folded back on itself.
_FOLD_RANGES = (
    (
        "elbow_span_fraction",
        0.05,
        0.95,
        "a number in [0.05, 0.95] of the arm span (humerus and forearm both present)",
    ),
    ("fold_coupling", 0.0, 2.0, "a number in [0, 2] (wrist flexion per radian of elbow flexion)"),
    (
        "hand_fold_area_loss",
        0.0,
        1.0,
        "a number in [0, 1] (fraction of the hand's area lost when folded back)",
    ),
)


def _is_number(v: Any) -> bool:
    """An int or float, not a bool (TOML's ``true`` is no length)."""
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _parse_number(key: str, raw: str) -> float:
    try:
        return float(raw)
    except ValueError:
        raise BirdConfigError(f"overrides: {key}={raw!r} is not a number") from None


def _parse_value(key: str, raw: str, kind: type) -> Any:
    if kind is bool:
        if raw.lower() in ("1", "true", "yes", "on"):
            return True
        if raw.lower() in ("0", "false", "no", "off"):
            return False
        raise BirdConfigError(f"overrides: {key}={raw!r} is not a boolean; allowed: true or false")
    if kind is int:
        try:
            return int(raw)
        except ValueError:
            raise BirdConfigError(f"overrides: {key}={raw!r} is not an integer") from None
    if kind is str:
        return raw
    return _parse_number(key, raw)


__all__ = ["FLIGHT_FIELDS", "POWER_COSTS", "Bird", "PanelGeometry", "asdict"]
