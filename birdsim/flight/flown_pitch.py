"""The free body's pitch inputs chosen on the flight's own prediction where the attitude
loop's model stops holding (reduced units; docs/free-body.md, "a pitch plant from the
flown state", variant C of ``scripts/flown_pitch_study.py``).

The straight attitude loop's pitch model is the held body's wingbeat-mean one with the
tail's restoring stiffness at the command.  Where the body's estimated wingbeat-mean
pitch less the air path's angle puts the tail beyond ``ALPHA_MAX`` (its lift capped) while
the loop counts on that stiffness and the tail has air (above ``SLOW_SPEED``), the
model no longer holds (the pigeon's flare).  There, every control step, the flight is
predicted :data:`WINDOW` ``[1]`` wingbeats ahead from its state
(:func:`birdsim.flight.flown_prediction.predict_root`: the table's wingbeat, the stroke plane's
compensation and the wind the bird has now held) with the loop's shoulders and tail and
once more per input stepped by :data:`STEP`; the shoulders (sweep, dihedral) and the
tail's elevation are set to the least change (weight :data:`MU`, inputs scaled by their
bounds) that makes the predicted mean pitch over wingbeats ``WINDOW`` meet the command's
(its rate and acceleration carried) up to :data:`ALPHA` of the miss (:data:`ALPHA_DISTURBED`
where a gust or the body's error, not the plan, put the tail out of range) while the predicted
wingbeat-mean height stays the one the loop's own inputs fly (weight :data:`PATH_WEIGHT`
against the pitch's; the same predictions, no extra cost).  The gate is left
after :data:`CALM_STEPS` control steps with the stiffness back and the body in range.
Only the wing and tail targets change; no force or torque on the body.
"""

from __future__ import annotations

import math

import numpy as np

from birdsim.flight.attitude_jacobians import INPUTS
from birdsim.flight.bounded_lsq import bounded_lsq
from birdsim.flight.flown_prediction import SAMPLES, nose_up, predict_root
from birdsim.flight.pitch_section import SLOW_SPEED
from birdsim.mujoco.tail import ALPHA_MAX, TailControls

#: Switch for the whole module (freeflight reads it at each flight; tests turn it off).
ENABLED = True
#: The prediction's length and the part of it the mean pitch is taken over (wingbeats):
#: past the first quarter wingbeat (where the inputs have not acted yet), up to one.
WINDOW = (0.25, 1.0)
#: The inputs' step (rad) of a measured sensitivity.
STEP = 0.01
#: The fraction of the predicted miss left to the next step (0: dead-beat, marginal on a
#: double integrator; measured 0.3 / 0.5 in the study, docs/free-body.md; 0.5 without
#: the path row below).
ALPHA = 0.3
#: That fraction where the gate was entered disturbed: the tail's estimated angle more than
#: :data:`PITCH_BAND` beyond the command's on the bird's own (still-air) path, i.e. put
#: out of range by the body's error or the wind, not by the plan (the flare).  There the
#: prediction holds a wingbeat the path loop is still changing, and taking out 70 % of its
#: miss every control step pumped the pigeon's lightly damped period-two mode (its cruise
#: loses 9 % of a wingbeat-to-wingbeat alternation per wingbeat, the seed bird 22 %):
#: measured 0.6 / 0.75 / 0.85 / 0.9 / 0.95 over 20-35 % gusts (docs/free-body.md, "the
#: flown gate's share of the miss after a gust"; 0.85 let the pigeon's 100 % -x and down
#: gusts diverge).
ALPHA_DISTURBED = 0.75
#: The band (rad) of the entry's tail angle about the still-air command's within which the
#: gate counts as entered by the plan (the issue's 3-degree pitch target).
PITCH_BAND = math.radians(3.0)
#: The weight of the least change from the loop's own inputs (scaled by their bounds).
MU = 1e-3
#: Control steps (one wingbeat: the prediction's horizon) with the loop's model holding
#: again before the gate is left.
CALM_STEPS = 8
#: The root's world axes (here z) whose predicted wingbeat-mean position the choice keeps
#: as the loop's own inputs fly it: the path loop's demand is the table's force, and a
#: pitch input that moves the body off it is a path error that loop sees only after the
#: wingbeat (the pigeon's landing sank 3-5 cm below its path over the perch, the path
#: integral at its bound; docs/free-body.md, "the flare's path").
PATH_AXES = (2,)
#: That row's weight against the pitch row's (semispans against radians; measured 0.5 /
#: 1 / 2 / 10: a trade of path against pitch, 10 losing both).
PATH_WEIGHT = 2.0
NAMES = [name for name, _, _ in INPUTS]
SWEEP, DIHEDRAL, TAIL = (NAMES.index(n) for n in ("sweep", "dihedral", "tail_elevation"))


class FlownPitch:
    """One flight's gate state (engaged, calm steps) and its predictive pitch choice."""

    def __init__(self) -> None:
        self.engaged = False
        self.calm = 0
        self.steps = 0  # control steps engaged (for tests and logs)
        self.alpha = ALPHA  # this engagement's share of the miss left
        #: This step's flown inputs where they differ from the loop's: (columns of
        #: ``INPUTS``, values), or None (the log's ``u_*``: :func:`flown_inputs`).
        self.flown_u: tuple[list[int], np.ndarray] | None = None

    def gate(self, att, fb, pitch_cmd: float, err_pitch: float, wind: np.ndarray) -> bool:
        """Whether the prediction chooses this step's inputs (updates the gate): ``att``
        the attitude loop (straight, Jacobians measured), ``err_pitch`` (rad) its
        wingbeat-mean pitch error (command minus body), ``wind`` the world wind now."""
        if not (att.enabled and att.straight and att._jac is not None):
            return False
        v = fb.d.qvel  # the air path in the sagittal plane (world x, z)
        air = (float(v[0] - wind[0]), float(v[2] - wind[2]))
        alpha = pitch_cmd - err_pitch - math.atan2(air[1], air[0])  # the tail's, estimated
        out_of_range = alpha > ALPHA_MAX
        if not self.engaged:  # in: the loop counts on the tail, which has air, beyond range
            fast = math.hypot(*air) > SLOW_SPEED
            self.engaged = att.stiffness[1] > 0.0 and out_of_range and fast
            self.calm = 0
            planned = pitch_cmd - math.atan2(float(v[2]), float(v[0]))  # in still air
            self.alpha = ALPHA if abs(alpha - planned) <= PITCH_BAND else ALPHA_DISTURBED
        else:  # out: CALM_STEPS steps with the stiffness back and the body within range
            held = out_of_range or att.stiffness[1] <= 0.0
            self.calm = 0 if held else self.calm + 1
            self.engaged = self.calm < CALM_STEPS
        return self.engaged

    def step(self, att, fb, args: tuple, ref3: tuple, params: np.ndarray, err_pitch: float) -> None:
        """Gate and, engaged, set ``fb``'s shoulder target and tail elevation for the
        interval about to be flown: ``args`` (right, left wingbeat targets, stroke-plane
        offset, wind now) as that interval has them, ``ref3`` the command's pitch (rad),
        rate and acceleration (rad per reduced time), ``params`` the table's wingbeat."""
        self.flown_u = None
        if not self.gate(att, fb, ref3[0], err_pitch, args[3]):
            return
        self.steps += 1
        tail = fb.cb.tail_controls
        lo, hi = att.bounds(params)
        idx = [SWEEP, DIHEDRAL, TAIL]
        x0 = np.array([*fb.schedule.shoulder_target, tail.elevation], dtype=float)

        def flown(x: np.ndarray) -> np.ndarray:  # the root's coordinates with inputs x
            tl = TailControls(float(x[2]), tail.spread, tail.roll)
            return predict_root(fb, args, x[:2], tl, WINDOW[1])[1]

        base = flown(x0)
        t = np.arange(len(base)) * (fb.red.period / SAMPLES)
        last = t >= WINDOW[0] * fb.red.period - 1e-9
        th0 = float(nose_up(base[:, 3:7])[last].mean())
        ref = ref3[0] + ref3[1] * t[last] + 0.5 * ref3[2] * t[last] ** 2
        miss = float(np.mean(ref)) - th0
        sens = np.zeros((1 + len(PATH_AXES), len(x0)))
        for j in range(len(x0)):
            moved = x0.copy()
            moved[j] += STEP
            q = flown(moved)
            sens[0, j] = float(nose_up(q[:, 3:7], base[:, 3:7])[last].mean()) / STEP
            for i, ax in enumerate(PATH_AXES):  # the path's change (semispans, window mean)
                sens[1 + i, j] = PATH_WEIGHT * float((q[last, ax] - base[last, ax]).mean()) / STEP
        s = (hi[idx] - lo[idx]) / 2
        a = np.vstack([sens * s, math.sqrt(MU) * np.eye(len(x0))])
        b = np.concatenate([[(1.0 - self.alpha) * miss], np.zeros(len(PATH_AXES) + len(x0))])
        dx, _ = bounded_lsq(a, b, (lo[idx] - x0) / s, (hi[idx] - x0) / s)
        x = x0 + dx * s
        fb.schedule.shoulder_target = x[:2]
        self.flown_u = (idx, x)
        fb.cb.tail_controls = TailControls(float(x[2]), tail.spread, tail.roll)


def flown_pitch_for(free: bool, straight: bool) -> FlownPitch | None:
    """A flight's :class:`FlownPitch`: free, straight flights with :data:`ENABLED`."""
    return FlownPitch() if ENABLED and free and straight else None


__all__ = [
    "ALPHA",
    "ALPHA_DISTURBED",
    "CALM_STEPS",
    "MU",
    "PATH_AXES",
    "PATH_WEIGHT",
    "PITCH_BAND",
    "STEP",
    "WINDOW",
    "FlownPitch",
    "flown_pitch_for",
]
