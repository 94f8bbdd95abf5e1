"""A turn's lateral recovery: a saturating, near time-optimal sideways acceleration for a
large side error, behind the bank's measured delay (reduced units: semispans, time 2 pi
per wingbeat; the offset ``y`` and its rate ``v`` to the left of the path, the
accelerations relative to the path's own centripetal one).

The turn's lateral loop (:func:`birdsim.flight.bank.lateral_acceleration`, a triple pole
of 6 wingbeats) answers a side velocity ``v0`` with an undershoot of ``0.080 v0 / w``
(``w = 1 / (2 pi LATERAL_BEATS)``) and rings behind the plant's delay of about
:data:`DELAY_BEATS` (the bank command's filter, the roll loop's response, the force's
magnitude: docs/turning.md, "Gust stage, fifth pass"); a side gust in the circle was not
back within 0.05 semispan in 8 wingbeats (23-34).  The time-optimal recovery within the
bank's bound takes 3.3-5.6 wingbeats behind that delay ("seventh pass").

This law acts only through the bank command: it replaces the linear loop's sideways
acceleration while the error is large (:class:`LateralRecovery`), as a proximate
time-optimal law (Workman's PTOS) on the state predicted :data:`DELAY_BEATS` ahead from
the accelerations already commanded: it asks the speed towards the path from which the
bank's authority (``AUTHORITY_FRACTION`` of the bound's) brakes to rest at the path,
``sqrt(2 a |y|)``, and approaches it at the bound; near the path that speed is linear in
the offset (critically damped), and inside the hand-back band it gives the offset back
to the linear loop.  The authority is the bound of the bank correction about the plan
(``turning.BANK_CORRECTION_MAX``) with the vertical force held:
``up (tan(phi0) - tan(phi0 -+ d))``.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field

TWO_PI = 2.0 * math.pi
#: The lateral plant's equivalent dead time (wingbeats): a step of the commanded
#: sideways acceleration reaches the flown one 2.5-3 wingbeats later, about 2 wingbeats
#: of delay (measured on the circle, docs/turning.md "Gust stage, fifth pass").
DELAY_BEATS = 2.0
#: The share of the bound's sideways acceleration the switching curve counts on for
#: braking (the flown acceleration reaches 0.35-0.5 of a step in its first two
#: wingbeats, 1.1-1.2 after: fifth pass).
AUTHORITY_FRACTION = 0.3
#: Time constant (wingbeats) of the approach speed's loop near the path (critically
#: damped: the offset's is four times it).
SPEED_BEATS = 3.0
#: The recovery engages when the predicted stopping point (the offset at which the
#: predicted state comes to rest braking at the authority) is farther than this from
#: the path (semispans): beyond the calm turning presets' largest side offset (0.18,
#: the circle's entry; docs/turning.md), so that calm turns never enter it.
ENGAGE = 0.25
MEASURED = False
WIDE = True
EXCESS = True
EXCESS_BEATS = 1.25
MEAS_LAG = 0.5
#: It hands back to the linear loop inside this band (semispans), at a speed the linear
#: loop's undershoot keeps within it (:func:`release_speed`).
RELEASE = 0.05


@dataclass
class LateralRecovery:
    """The recovery's state in one flight: whether it is engaged, the relative sideways
    accelerations commanded over the last :data:`DELAY_BEATS` (oldest first), and the
    control steps it was engaged (for the log)."""

    active: bool = False
    pipe: deque = field(default_factory=deque)
    engaged_steps: int = 0
    bank_excess: float = 0.0
    a_excess: float = 0.0

    def predict(
        self, y: float, v: float, dt: float, a_meas: float | None = None
    ) -> tuple[float, float]:
        """The offset and its rate :data:`DELAY_BEATS` ahead, the commands in the
        pipeline arriving then: each one ``dt`` long, arriving ``DELAY`` after it was
        commanded.  With ``a_meas`` (the wingbeat-mean sideways acceleration measured,
        lagging MEAS_LAG): that acceleration held, plus the commands' changes since
        the one arriving at the measurement."""
        d = DELAY_BEATS * TWO_PI
        pipe = list(self.pipe)
        k = max(1, int(round(d / dt)))
        recent, ref = pipe[-k:], 0.0
        yp, vp = y + v * d, v
        if a_meas is not None:
            ref = pipe[0] if len(pipe) > k else 0.0
            yp += 0.5 * a_meas * d * d
            vp += a_meas * d
        if EXCESS and self.bank_excess:  # the flown bank's excess, decaying over the roll loop
            tr, a_exc = EXCESS_BEATS * TWO_PI, self.a_excess
            decay = tr * (1.0 - math.exp(-d / tr))
            yp += a_exc * (tr * d - tr * decay)
            vp += a_exc * decay
        n = len(recent)
        for i, a in enumerate(recent):  # commanded (n - i) steps ago
            left = (n - i - 0.5) * dt  # time it acts before now + DELAY
            yp += (a - ref) * dt * left
            vp += (a - ref) * dt
        return yp, vp

    def step(
        self,
        y: float,
        v: float,
        phi0: float,
        up: float,
        bound: float,
        dt: float,
        a_meas: float = 0.0,
    ) -> float | None:
        """One control step ``dt`` from the wingbeat-mean offset ``y`` and rate ``v``
        about the planned bank ``phi0`` (the force carrying ``up``, the correction's
        bound ``bound``): the recovery's sideways acceleration (to the left, relative
        to the plan's) while engaged, else None (the linear loop's)."""
        from birdsim.flight.bank import LATERAL_BEATS

        a_left, a_right = authority(phi0, up, bound)
        self.a_excess = -up * self.bank_excess / math.cos(phi0) ** 2
        yp, vp = self.predict(y, v, dt, a_meas if MEASURED else None)
        a, stop = recovery_acceleration(yp, vp, a_left, a_right)
        if not self.active and abs(stop) > ENGAGE:
            self.active = True
        elif self.active and abs(yp) < RELEASE and abs(vp) < release_speed(LATERAL_BEATS):
            self.active = False
        self.engaged_steps += int(self.active)
        return a if self.active else None

    def record(self, a_rel: float, dt: float) -> None:
        self.pipe.append(a_rel)
        while len(self.pipe) > max(1, int(round((DELAY_BEATS + MEAS_LAG) * TWO_PI / dt))):
            self.pipe.popleft()


def bank_range(phi0: float, bound: float) -> tuple[float, float]:
    """The bank correction's range (rad) about the planned bank ``phi0``: +-``bound``,
    or with :data:`WIDE` the bird's bank limit (``TURN_ROLL_MAX`` into the turn, wings
    level out of it)."""
    if not WIDE:
        return -bound, bound
    from birdsim.flight.attitude_commands import TURN_ROLL_MAX

    if phi0 < 0.0:  # a left turn (left wing down)
        return -TURN_ROLL_MAX - phi0, -phi0
    return -phi0, TURN_ROLL_MAX - phi0


def authority(phi0: float, up: float, bound: float) -> tuple[float, float]:
    """The sideways acceleration (to the left, to the right; both > 0) relative to the
    plan's that a bank correction within :func:`bank_range` about the planned bank ``phi0``
    (seed: right wing down > 0) gives with the vertical force ``up`` held."""
    dlo, dhi = bank_range(phi0, bound)
    lo, hi = max(phi0 + dlo, -0.49 * math.pi), min(phi0 + dhi, 0.49 * math.pi)
    return up * (math.tan(phi0) - math.tan(lo)), up * (math.tan(hi) - math.tan(phi0))


def release_speed(lateral_beats: float) -> float:
    """The largest side speed the linear loop (triple pole of ``lateral_beats``) takes
    from the path without its undershoot ``0.080 v0 / w`` leaving :data:`RELEASE`."""
    w = 1.0 / (TWO_PI * lateral_beats)
    return RELEASE * w / 0.080


def recovery_acceleration(
    yp: float, vp: float, a_left: float, a_right: float
) -> tuple[float, float]:
    """The proximate time-optimal sideways acceleration (to the left, bounded by
    ``a_left`` / ``a_right``) for the predicted offset ``yp`` and rate ``vp``, and the
    predicted stopping point (where braking at the authority's fraction brings it to
    rest)."""
    brake = a_left if vp < 0.0 else a_right  # braking a leftward speed pushes right
    stop = yp + vp * abs(vp) / (2.0 * AUTHORITY_FRACTION * max(brake, 1e-12))
    towards = a_left if yp > 0.0 else a_right  # braking on the way back to the path
    ab = AUTHORITY_FRACTION * towards
    w = 1.0 / (SPEED_BEATS * TWO_PI)  # the linear part: k1 = w^2, k2 = 2 w
    e = abs(yp)
    if e <= 2.0 * ab / (w * w):  # linear near the path (slope and value continuous)
        speed = 0.5 * w * e
    else:
        speed = math.sqrt(2.0 * ab * e) - ab / w
    want = -math.copysign(speed, yp)
    a = 2.0 * w * (want - vp)
    return min(max(a, -a_right), a_left), stop


__all__ = [
    "AUTHORITY_FRACTION",
    "DELAY_BEATS",
    "ENGAGE",
    "LateralRecovery",
    "RELEASE",
    "SPEED_BEATS",
    "authority",
    "recovery_acceleration",
    "release_speed",
]
