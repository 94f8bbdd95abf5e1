"""The dissertation's statements, as data: one registered check per figure.

Each check is a function registered under the key of the figure it speaks about (the
example's equation number for the wingbeat histories, sec. 3.5; the model for the
speed sweeps, sec. 4.1) together with what the dissertation printed there.  It tests
each statement on our numbers and returns :class:`~birdsim.report.records.Claim`
records (never a hard-coded verdict).  Drawing is in :mod:`birdsim.report.plots`, the
page in :mod:`birdsim.report.page`.

Add a check with the decorator, like dm_control's ``@SUITE.add``::

    @HISTORY.add(57, "Fig 12: ...")
    def _eq57(h: HistoryView, cyc: dict) -> list[Claim]:
        return [Claim("net upward force", h.Fz < 0, f"mean Fz = {h.Fz:+.4f}")]
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Any

import numpy as np

from birdsim.report.records import Claim

PI = math.pi


@dataclass(frozen=True)
class Check:
    """One figure's statements: the printed text and the function that tests them."""

    key: Hashable
    said: str
    test: Callable[..., list[Claim]]


class ClaimRegistry:
    """Checks keyed by figure (equation number, model name, ...), in registration order."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._checks: dict[Hashable, Check] = {}

    def add(
        self, key: Hashable, said: str
    ) -> Callable[[Callable[..., list[Claim]]], Callable[..., list[Claim]]]:
        """Register the decorated function as the check of ``key``.

        ``said`` is what the dissertation printed about ``key``."""

        def register(fn: Callable[..., list[Claim]]) -> Callable[..., list[Claim]]:
            if key in self._checks:
                raise ValueError(f"{self.name}: a check for {key!r} is registered twice")
            self._checks[key] = Check(key, said, fn)
            return fn

        return register

    def keys(self) -> list[Hashable]:
        return list(self._checks)

    def said(self, key: Hashable) -> str:
        """What the dissertation printed about ``key`` ("" when nothing is registered)."""
        check = self._checks.get(key)
        return check.said if check else ""

    def check(self, key: Hashable, *args: Any) -> tuple[str, list[Claim]]:
        """``(said, claims)`` of ``key`` on our numbers; ``("", [])`` when nothing is registered."""
        check = self._checks.get(key)
        if check is None:
            return "", []
        return check.said, list(check.test(*args))


# ---- wingbeat histories (sec. 3.5, Figs 12-25), keyed by the example's equation --------

HISTORY = ClaimRegistry("history claims")


def _phase_mask(n: int, lo: float, hi: float) -> np.ndarray:
    ph = np.arange(n) / n
    return (ph >= lo) & (ph < hi)


@dataclass(frozen=True)
class HistoryView:
    """The histories of one cycle as the statements read them (seed axes, Fz < 0 up).

    ``fz``, ``fx``, ``p``: arrays of N samples over one wingbeat (fx includes the body
    drag); ``Fx``, ``Fz``: cycle means; ``down``: the downstroke samples (phase < 0.25 or
    >= 0.75); ``cycle``: the :class:`~birdsim.physics.cycle.Cycle` itself.
    """

    cycle: Any
    fz: np.ndarray
    fx: np.ndarray
    p: np.ndarray
    Fx: float
    Fz: float
    n: int
    down: np.ndarray

    @classmethod
    def of(cls, c: Any) -> HistoryView:
        n = c.Fz.shape[-1]
        down = _phase_mask(n, 0.0, 0.25) | _phase_mask(n, 0.75, 1.0)
        fx = c.Fx + float(c.body_drag_x)
        return cls(c, c.Fz, fx, c.P, float(c.mean.Fx), float(c.mean.Fz), n, down)

    def near(self, centre: float) -> np.ndarray:
        """Samples within 0.1 of phase ``centre``."""
        return _phase_mask(self.n, centre - 0.1, centre + 0.1)

    def between(self, lo: float, hi: float) -> np.ndarray:
        return _phase_mask(self.n, lo, hi)


def history_claims(eq: int, c: Any, cyc: dict) -> tuple[str, list[Claim]]:
    """What the dissertation says about the example of equation ``eq`` (sec. 3.5) and
    the test of each statement on our cycle ``c`` (``cyc`` maps equation -> Cycle)."""
    return HISTORY.check(eq, HistoryView.of(c), cyc)


def _down_up(h: HistoryView, a: np.ndarray, fmt: str = ".3f") -> str:
    return f"{a[h.down].mean():{fmt}} / {a[~h.down].mean():{fmt}}"


@HISTORY.add(
    57,
    "Fig 12: oscillating negative Fz over the cycle; oscillating Fx with no net horizontal force.",
)
def _eq57(h: HistoryView, cyc: dict) -> list[Claim]:
    return [
        Claim(
            "Fz is negative (upward) over the whole cycle",
            bool(h.fz.max() <= 1e-9),
            f"max Fz = {h.fz.max():+.3g}",
        ),
        Claim("net upward force", h.Fz < 0, f"mean Fz = {h.Fz:+.4f}"),
        Claim("no net Fx", abs(h.Fx) < 1e-6, f"mean Fx = {h.Fx:+.2g}"),
    ]


@HISTORY.add(
    58,
    "Fig 13: Fz negative over most of the cycle with a small positive part near phase 0.5; a net "
    "thrust "
    "(mean Fx > 0); Fx negative near phases 0.25 and 0.75; more power on the downstroke.",
)
def _eq58(h: HistoryView, cyc: dict) -> list[Claim]:
    fz, fx, p = h.fz, h.fx, h.p
    return [
        Claim(
            "Fz < 0 over most of the cycle",
            bool(np.mean(fz < 0) > 0.5),
            f"Fz < 0 on {np.mean(fz < 0):.0%} of the cycle",
        ),
        Claim(
            "small positive Fz near phase 0.5",
            bool(fz[h.near(0.5)].max() > 0),
            f"max Fz near 0.5 = {fz[h.near(0.5)].max():+.3f}",
        ),
        Claim("net thrust", h.Fx > 0, f"mean Fx = {h.Fx:+.4f}"),
        Claim(
            "Fx < 0 near phases 0.25 and 0.75",
            bool(fx[h.near(0.25)].min() < 0 and fx[h.near(0.75)].min() < 0),
            f"min Fx near 0.25 / 0.75 = {fx[h.near(0.25)].min():+.3f} / "
            f"{fx[h.near(0.75)].min():+.3f}",
        ),
        Claim(
            "more power on the downstroke",
            bool(p[h.down].mean() > p[~h.down].mean()),
            f"mean P down / up = {_down_up(h, p)}",
        ),
    ]


@HISTORY.add(61, "Fig 15: Fz like the base model's; power the same as the base model's.")
def _eq61(h: HistoryView, cyc: dict) -> list[Claim]:
    b = cyc[57]
    return [
        Claim(
            "mean Fz equals the base model's",
            bool(np.isclose(h.Fz, float(b.mean.Fz), rtol=1e-6)),
            f"{h.Fz:+.4f} vs base {float(b.mean.Fz):+.4f}",
        ),
        Claim(
            "power history the same as the base model's",
            bool(np.allclose(h.p, b.P, atol=1e-9)),
            f"max |dP| = {np.abs(h.p - b.P).max():.2g}",
        ),
    ]


@HISTORY.add(62, "Fig 16: Fx and power appear identical to the base model's; Fz differs somewhat.")
def _eq62(h: HistoryView, cyc: dict) -> list[Claim]:
    b = cyc[58]
    dfx = np.abs(h.fx - (b.Fx + float(b.body_drag_x))).max() / np.abs(b.Fx).max()
    dp = np.abs(h.p - b.P).max() / np.abs(b.P).max()
    return [
        Claim(
            "Fx history within 10% of the base model's",
            bool(dfx < 0.1),
            f"max |dFx| / max |Fx| = {dfx:.1%}",
        ),
        Claim(
            "power history within 10% of the base model's",
            bool(dp < 0.1),
            f"max |dP| / max |P| = {dp:.1%}",
        ),
        Claim(
            "mean Fz differs from the base model's",
            abs(h.Fz - float(b.mean.Fz)) > 1e-3,
            f"{h.Fz:+.4f} vs base {float(b.mean.Fz):+.4f}",
        ),
    ]


@HISTORY.add(
    68,
    "Fig 18: Fz like model 1's but smaller; Fx unaffected by the sweep; power negative near phases "
    "0.25 and 0.75.",
)
def _eq68(h: HistoryView, cyc: dict) -> list[Claim]:
    b = cyc[61]
    return [
        Claim(
            "smaller upward force than model 1",
            abs(h.Fz) < abs(float(b.mean.Fz)),
            f"mean Fz {h.Fz:+.4f} vs m1 {float(b.mean.Fz):+.4f}",
        ),
        Claim(
            "Fx history unchanged from model 1",
            bool(np.allclose(h.fx, b.Fx, atol=1e-9)),
            f"max |dFx| = {np.abs(h.fx - b.Fx).max():.2g}",
        ),
        Claim(
            "power negative near phases 0.25 and 0.75 (docs/conventions.md: no consistent reading "
            "gives this)",
            bool(h.p.min() < 0),
            f"min P = {h.p.min():+.3g}",
        ),
    ]


@HISTORY.add(
    69,
    "Fig 19: Fz differs between downstroke and upstroke; near phase 0.25 negative Fx; "
    "for phases 0.75-1 positive Fx and power.",
)
def _eq69(h: HistoryView, cyc: dict) -> list[Claim]:
    late = h.between(0.75, 1)
    return [
        Claim(
            "Fz differs between the two half-strokes",
            abs(h.fz[h.down].mean() - h.fz[~h.down].mean()) > 1e-3,
            f"mean Fz down / up = {_down_up(h, h.fz, '+.3f')}",
        ),
        Claim(
            "Fx < 0 near phase 0.25",
            bool(h.fx[h.near(0.25)].min() < 0),
            f"min Fx near 0.25 = {h.fx[h.near(0.25)].min():+.3f}",
        ),
        Claim(
            "Fx and power > 0 for phases 0.75-1",
            bool(h.fx[late].mean() > 0 and h.p[late].mean() > 0),
            f"mean Fx, P there = {h.fx[late].mean():+.3f}, {h.p[late].mean():+.3f}",
        ),
    ]


@HISTORY.add(
    75,
    "Fig 21: less upward Fz on the downstroke, more on the upstroke; a net negative Fx; power "
    "identical to model 1.",
)
def _eq75(h: HistoryView, cyc: dict) -> list[Claim]:
    b = cyc[61]
    return [
        Claim(
            "less upward force on the downstroke than on the upstroke",
            bool(h.fz[h.down].mean() > h.fz[~h.down].mean()),
            f"mean Fz down / up = {_down_up(h, h.fz, '+.3f')}",
        ),
        Claim("net negative Fx", h.Fx < 0, f"mean Fx = {h.Fx:+.4f}"),
        Claim(
            "power identical to model 1",
            bool(np.allclose(h.p, b.P, atol=1e-9)),
            f"max |dP| = {np.abs(h.p - b.P).max():.2g}",
        ),
    ]


@HISTORY.add(
    76,
    "Fig 22: Fz negative over the entire cycle; Fx negative over the entire cycle; much more power "
    "on the downstroke.",
)
def _eq76(h: HistoryView, cyc: dict) -> list[Claim]:
    return [
        Claim(
            "Fz <= 0 over the whole cycle", bool(h.fz.max() <= 1e-9), f"max Fz = {h.fz.max():+.3g}"
        ),
        Claim("Fx < 0 over the whole cycle", bool(h.fx.max() < 0), f"max Fx = {h.fx.max():+.3g}"),
        Claim(
            "more power on the downstroke",
            bool(h.p[h.down].mean() > h.p[~h.down].mean()),
            f"mean P down / up = {_down_up(h, h.p)}",
        ),
    ]


def _joint_power(h: HistoryView) -> dict[str, float]:
    return {g: float(v.mean()) for g, v in h.cycle.joint_power.items()}


def _shoulder_claim(jp: dict[str, float]) -> Claim:
    return Claim(
        "the shoulder joint delivers most of the power",
        jp["shoulder"] > jp["wrist"],
        f"joint power shoulder / wrist = {jp['shoulder']:.4f} / {jp['wrist']:.4f}",
    )


@HISTORY.add(
    87,
    "Fig 24: panel 2 carries more than half of Fz and most of Fx; most of the power is spent on "
    "panel 1 (the shoulder).",
)
def _eq87(h: HistoryView, cyc: dict) -> list[Claim]:
    arm, hand = h.cycle.panel_mean["arm"], h.cycle.panel_mean["hand"]
    rms = np.sqrt(np.mean(h.cycle.panel_force_earth[..., 0] ** 2, axis=-1))
    return [
        Claim(
            "panel 2 carries more than half of mean Fz",
            float(hand.Fz) / h.Fz > 0.5,
            f"hand share = {float(hand.Fz) / h.Fz:.0%}",
        ),
        Claim(
            "panel 2 carries most of the Fx oscillation",
            bool(rms[1] > rms[0]),
            f"rms Fx arm / hand = {rms[0]:.3f} / {rms[1]:.3f}",
        ),
        Claim(
            "most power on panel 1 (docs/conventions.md: no consistent reading gives this)",
            float(arm.P) > float(hand.P),
            f"mean P arm / hand = {float(arm.P):.4f} / {float(hand.P):.4f}",
        ),
        _shoulder_claim(_joint_power(h)),
    ]


@HISTORY.add(
    88,
    "Fig 25: panel 1 gives no net Fz, panel 2 does; panel 2 gives more Fx; the shoulder dominates "
    "the power.",
)
def _eq88(h: HistoryView, cyc: dict) -> list[Claim]:
    arm, hand = h.cycle.panel_mean["arm"], h.cycle.panel_mean["hand"]
    return [
        Claim(
            "no net Fz on panel 1", abs(float(arm.Fz)) < 1e-9, f"arm mean Fz = {float(arm.Fz):+.2g}"
        ),
        Claim(
            "net upward Fz on panel 2", float(hand.Fz) < 0, f"hand mean Fz = {float(hand.Fz):+.4f}"
        ),
        Claim(
            "panel 2 gives more Fx than panel 1",
            float(hand.Fx) > float(arm.Fx),
            f"mean Fx arm / hand = {float(arm.Fx):+.4f} / {float(hand.Fx):+.4f}",
        ),
        _shoulder_claim(_joint_power(h)),
    ]
