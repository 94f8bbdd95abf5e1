"""Standing, the take-off jump and the touchdown, simulated with the feet in contact
(issue 25; :class:`birdsim.flight.contact.ContactBird`; docs/legs.md, "Legs,
contact, take-off and landing").  Reduced units throughout.

* Standing: the legs' spring-damper carries the weight at the standing length.
* Jump (:class:`JumpProfile`): from standing, a crouch (the spring's reference
  lowered by a cosine blend over ``crouch_beats``), then a push: each leg's force rises
  from half the weight to half of ``peak_over_weight`` times the weight and back as a
  half-sine over the push time ``T = sqrt(pi d / ((r - 1) g))`` -- the time in which a
  half-sine net force of peak ``(r - 1) m g`` moves the body by ``d``, 90 % of the legs'
  travel from the crouch to full extension -- then the legs tuck (spring to q = 0).
  Shape and peak: Earls (2000) J. Exp. Biol. 203:725 (starling: peak vertical force
  about 4 x body weight, a single-peaked push).
* Touchdown: the bird arrives at the touchdown speed with the legs at standing length
  and the spring-damper absorbs; the wings are held still (they stopped flapping).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from birdsim.flight.contact import ContactBird, beats_to_steps

TWO_PI = 2.0 * math.pi
#: Phases logged per sample (``phase`` column): index -> name.
PHASES = ("standing", "take-off", "flight", "landing")


#: Time constant of the hips' pitch trim during the rise, crouch and push (wingbeats).
PITCH_TRIM_BEATS = 0.5


@dataclass(frozen=True)
class JumpProfile:
    """The legs' take-off (times in wingbeats, forces in the bird's weights)."""

    settle_beats: float = 1.0
    #: the hips raise the body to the flight's first pitch over these wingbeats (the
    #: feet's grip, half the toe span times the weight, bounds the torque: the seed
    #: bird's torso needs about 4 wingbeats for 47 degrees)
    rise_beats: float = 5.0
    crouch_beats: float = 1.5
    crouch_depth: float = 0.6  # of the standing leg coordinate
    peak_over_weight: float = 4.0  # Earls 2000: starling about 4
    travel_used: float = 0.9


@dataclass
class Record:
    """Per sample (every step): time, qpos, qvel, foot normal force, world foot force,
    on the feet, phase index."""

    t: list = field(default_factory=list)
    qpos: list = field(default_factory=list)
    qvel: list = field(default_factory=list)
    foot_normal: list = field(default_factory=list)
    foot_force: list = field(default_factory=list)
    on_feet: list = field(default_factory=list)
    phase: list = field(default_factory=list)

    def add(self, cb: ContactBird, phase: int) -> None:
        self.t.append(cb.time)
        self.qpos.append(cb.d.qpos.copy())
        self.qvel.append(cb.d.qvel.copy())
        self.foot_normal.append(cb.foot_normal())
        self.foot_force.append(cb.foot_force())
        self.on_feet.append(cb.foot_normal() > 0.0)
        self.phase.append(phase)

    def arrays(self) -> dict[str, np.ndarray]:
        return {k: np.array(v) for k, v in self.__dict__.items()}


@dataclass(frozen=True)
class JumpResult:
    record: dict[str, np.ndarray]
    liftoff_time: float  # reduced
    liftoff_velocity: np.ndarray  # centre of mass, world
    leg_share: float  # leg impulse (feet + weight) along the lift-off momentum / momentum
    peak_foot_over_weight: float
    push_beats: float
    root_applied_max: float


def push_time(cb: ContactBird, prof: JumpProfile) -> float:
    """Reduced time of the push (module docstring)."""
    mu, g = cb.muscle, cb.red.gravity
    q_crouch = (1.0 - prof.crouch_depth) * mu.q_stand
    d = prof.travel_used * (cb.geom.q_max - q_crouch)
    return math.sqrt(math.pi * d / ((prof.peak_over_weight - 1.0) * g))


def jump(
    cb: ContactBird,
    prof: JumpProfile = JumpProfile(),
    after_beats: float = 0.5,
    pitch_to: float | None = None,
    unfold: tuple[dict, dict] | None = None,
) -> JumpResult:
    """Stand, crouch and jump from where ``cb`` stands (placed with
    ``place_standing``); stop ``after_beats`` after lift-off (the wings still held).
    ``pitch_to``: before the crouch the hips raise the body to this pitch (rad; the
    flight's first wingbeat's) over ``rise_beats``, the legs kept vertical.
    ``unfold``: (rest, first) core joint angles of the wings: they move from the rest
    pose to the first wingbeat's pose during the crouch and are held there for the push."""
    mu, w = cb.muscle, cb.weight
    rec = Record()
    stand = cb.standing_law()
    for _ in range(beats_to_steps(prof.settle_beats)):
        cb.step(stand, 0.0)
        rec.add(cb, 0)
    t_c = prof.crouch_beats * TWO_PI
    depth = prof.crouch_depth * mu.q_stand
    q0 = mu.q_ref_stand
    hip0 = cb.hip_ref
    # the hips' reference is trimmed by the body's pitch error (integral, over
    # PITCH_TRIM_BEATS): hip_for assumes vertical legs, the feet on the bar let them lean,
    # and the body reached 75 deg for a first wingbeat at 67 (the flight then started
    # 8-10 deg lower in one step at lift-off)
    trim = [0.0, cb.body_pitch(), pitch_to]  # correction (rad), pitch at start, target

    def trimmed(target: float) -> None:
        if pitch_to is not None:
            trim[0] += cb.h * (target - cb.body_pitch()) / (PITCH_TRIM_BEATS * TWO_PI)

    if pitch_to is not None:
        hip1 = cb.hip_for(pitch_to)
        t_r = prof.rise_beats * TWO_PI
        for k in range(beats_to_steps(prof.rise_beats)):
            blend = 0.5 * (1.0 - math.cos(math.pi * min(k * cb.h / t_r, 1.0)))
            trimmed(trim[1] + blend * (pitch_to - trim[1]))
            cb.hip_ref = hip0 + blend * (hip1 - hip0) + trim[0]
            cb.step(stand, 0.0)
            rec.add(cb, 0)
        cb.hip_ref = hip1 + trim[0]

    def crouch(t: float, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        blend = 0.5 * (1.0 - math.cos(math.pi * min(t / t_c, 1.0)))
        return mu.spring(q, qd, q0 - depth * blend)

    if unfold is not None:
        cb.wing_path = cb.wing_blend(unfold[0], unfold[1], cb.time, t_c)
    for k in range(beats_to_steps(prof.crouch_beats)):
        if pitch_to is not None:
            trimmed(pitch_to)
            cb.hip_ref = hip1 + trim[0]
        cb.step(crouch, k * cb.h)
        rec.add(cb, 1)
    if unfold is not None:  # held at the first wingbeat's pose for the push
        cb.hold_qpos = cb.wing_path(cb.time)[0]
        cb.wing_path = None
    t_p = push_time(cb, prof)
    half, extra = 0.5 * w, 0.5 * (prof.peak_over_weight - 1.0) * w

    def push(t: float, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        if t <= t_p:
            return np.full(2, half + extra * math.sin(math.pi * t / t_p))
        cb.set_leg_damping(True)
        return mu.spring(q, qd, 0.0)  # tuck

    _, v_start = cb.com()
    cb.set_leg_damping(False)  # the push: the muscle's force alone
    weight_vec = np.array([0.0, 0.0, -w])
    impulse = np.zeros(3)
    t_lo = None
    k = 0
    limit = beats_to_steps(prof.settle_beats + 4.0)
    while k < limit:
        if pitch_to is not None and t_lo is None:
            trimmed(pitch_to)
            cb.hip_ref = hip1 + trim[0]
        cb.step(push, k * cb.h)
        rec.add(cb, 1)
        k += 1
        if t_lo is None:
            impulse += cb.h * (cb.foot_force() + weight_vec)
            if k * cb.h > 0.25 * t_p and rec.foot_normal[-1] == 0.0:
                t_lo = cb.time
                _, v_lo = cb.com()
                stop = k + beats_to_steps(after_beats)
        elif k >= stop:
            break
    if t_lo is None:
        raise RuntimeError("the bird did not leave its perch")
    p = cb.mass * (v_lo - v_start)
    share = float(impulse @ p / (p @ p))
    arrays = rec.arrays()
    arrays["phase"][arrays["t"] > t_lo] = 2
    return JumpResult(
        arrays,
        t_lo,
        v_lo,
        share,
        float(np.max(arrays["foot_normal"]) / w),
        t_p / TWO_PI,
        cb.root_applied_max,
    )


__all__ = ["PHASES", "JumpProfile", "JumpResult", "Record", "jump", "push_time"]


#: Touchdown speed measured in small birds landing on a perch: about 1 m/s (Provini,
#: Tobalske, Crandell & Abourachid 2014, J. Exp. Biol. 217:2659, zebra finch and diamond
#: dove).  Taken as it is for the pigeon (not scaled up: a Froude scaling with the leg
#: growing as the cube root of mass, (m / m_ref)^(1/6) from the 50 g dove or the 15 g
#: finch, gives 1.5-1.8 m/s, which the braking stroke of the pigeon's estimated 4 cm leg
#: absorbs only at 5-7 x its weight, above the take-off's 4: against the measured
#: landing peak of about half the take-off's); the seed bird gets the same reduced speed.
TOUCHDOWN_SPEED_SI = 1.0
#: The pigeon's speed unit omega s in m/s (models/pigeon.toml: 2 pi 8.02 Hz x 0.33 m).
PIGEON_SPEED_UNIT = 16.63
#: Descent angle of the touchdown velocity below the horizontal (rad).
TOUCHDOWN_ANGLE = math.radians(90.0)
#: Fraction of the standing leg coordinate the legs may give way over while braking.
BRAKE_STROKE = 0.6
#: Rise time of the legs' braking force from touchdown (wingbeats; 16 ms for the pigeon).
ACTIVATION_BEATS = 0.125
#: Wingbeats over which the wings fold to their rest pose after the touchdown.
FOLD_BEATS = 1.0
#: Wingbeats over which the standing spring returns to its reference after braking.
SETTLE_BEATS = 0.5


@dataclass(frozen=True)
class TouchdownResult:
    record: dict[str, np.ndarray]
    touchdown_speed: float  # the centre of mass's speed at the first contact (omega s)
    rest_beats: float  # wingbeats from the first contact until the speed stays below 1 % of
    # the touchdown speed
    peak_foot_over_weight: float
    final_offset: np.ndarray  # the soles' mean point at the end minus the target (world)
    weight_carried: float  # feet's vertical force / weight, mean over the last wingbeat
    root_applied_max: float


def touchdown_speed(pigeon_speed_unit: float = PIGEON_SPEED_UNIT) -> float:
    """The touchdown speed in omega s: 1 m/s over the pigeon's speed unit omega s
    (16.63 m/s): 0.060.  Every bird lands at this reduced speed (the seed bird flies
    the pigeon's reduced values; another bird would scale it by its own leg)."""
    return TOUCHDOWN_SPEED_SI / pigeon_speed_unit


#: The standing bird's balance (``touchdown(..., balance=True)``): the hips turn the body
#: so that the centre of mass comes back over the soles (the hip angle that would put the
#: soles under it, as ``ContactBird.hip_for``, times BALANCE_GAIN), its speed damped
#: over BALANCE_DAMPING (reduced time).
BALANCE_GAIN = 1.0
BALANCE_DAMPING = 3.0
BALANCE_RAMP_BEATS = 0.25


def balance_hip(cb: ContactBird) -> float:
    """The hips' balance correction (rad): the centre of mass's offset behind the soles
    and its speed, over the leg's reach."""
    c, v = cb.com()
    sole_x = float(cb.d.geom_xpos[cb.feet, 0].mean())
    reach = cb.geom.length - cb.geom.foot_radius
    err = (sole_x - float(c[0])) - BALANCE_DAMPING * float(v[0])
    return BALANCE_GAIN * math.asin(max(-1.0, min(1.0, err / reach)))


def touchdown(
    cb: ContactBird,
    target: np.ndarray,
    speed: float | None,
    beats: float = 6.0,
    *,
    pitch_to: float | None = None,
    rise_beats: float = 5.0,
    fold: tuple[dict, dict] | None = None,
    balance: bool = False,
    stand_beats: float = SETTLE_BEATS,
) -> TouchdownResult:
    """The legs absorb a touchdown on ``target`` (world point on the perch or ground)
    and the bird stands.  ``speed`` (omega s): place the bird with its soles just
    touching ``target``, legs at standing length, moving at ``speed`` forward and down
    at :data:`TOUCHDOWN_ANGLE`; None: start from ``cb``'s current state (a flight's
    end).  ``pitch_to``: once stopped, the hips lower the body to this pitch over
    ``rise_beats``.  ``fold``: (stopped, rest) core joint angles of the wings: from the
    touchdown they fold to the rest pose over ``FOLD_BEATS``.  ``balance``: once stopped,
    the hips also keep the centre of mass over the soles (:func:`balance_hip`, brought in
    over BALANCE_RAMP_BEATS).  ``stand_beats``: once stopped, the legs stretch from where
    the braking left them to standing over this long.  Runs ``beats`` wingbeats."""
    d = cb.d
    if speed is not None:
        cb.place_standing(np.asarray(target, dtype=float))
        d.qvel[:3] = speed * np.array([math.cos(TOUCHDOWN_ANGLE), 0.0, -math.sin(TOUCHDOWN_ANGLE)])
        d.qpos[2] += 1e-4  # the soles a hair above the surface: contact begins in the step
    mu = cb.muscle
    # at contact the legs brake with a constant force that stops the body over
    # BRAKE_STROKE of the standing leg (eccentric work), the damper relaxed; then stand
    brake = [0.0]
    arrival = [0.0]  # the centre of mass's speed at the first contact
    braking = [True]
    settle = [0.0, 0.0, cb.hip_ref]  # time the braking ended, spring reference, hip then
    hip_to = None if pitch_to is None else cb.hip_for(pitch_to)
    contact = [-1.0]  # time the feet touched

    def land(t: float, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        if braking[0] and contact[0] >= 0.0 and cb.com()[1][2] >= 0.0:
            # stopped: the spring takes over from where the legs are, carrying the
            # weight there, and its reference returns to standing
            braking[0] = False
            settle[:] = [t, float(np.mean(q)) + 0.5 * cb.weight / mu.stiffness, cb.hip_ref]
            cb.set_leg_damping(True)
        if braking[0]:  # before contact the leg hangs relaxed at its standing length
            # (the force felt at the end of the last step: inside the step the
            # contact's force is not solved yet)
            if cb.felt_normal <= 0.0 and contact[0] < 0.0:
                return mu.spring(q, qd, mu.q_stand)
            if contact[0] < 0.0:
                contact[0] = t
                if fold is not None:
                    cb.wing_path = cb.wing_blend(fold[0], fold[1], cb.time, FOLD_BEATS * TWO_PI)
                v = cb.com()[1]
                arrival[0] = float(np.linalg.norm(v))
                v_down = max(-float(v[2]), 0.0)
                stroke = 2.0 * BRAKE_STROKE * mu.q_stand
                brake[0] = 0.5 * (cb.weight + cb.mass * v_down**2 / stroke)
            # the muscle's activation rises over ACTIVATION_BEATS (not a step)
            rise = min(1.0, (t - contact[0]) / (ACTIVATION_BEATS * TWO_PI))
            return np.full(2, brake[0] * rise)
        hip = settle[2]
        if hip_to is not None:
            b = min((t - settle[0]) / (rise_beats * TWO_PI), 1.0)
            hip = settle[2] + 0.5 * (1.0 - math.cos(math.pi * b)) * (hip_to - settle[2])
        # the balance's correction comes in over BALANCE_RAMP_BEATS (at once, its step
        # kicked the hips and the feet hopped off the bar for a tenth of a wingbeat)
        ramp = min(1.0, (t - settle[0]) / (BALANCE_RAMP_BEATS * TWO_PI))
        cb.hip_ref = hip + ramp * balance_hip(cb) if balance else hip
        blend = 0.5 * (1.0 - math.cos(math.pi * min((t - settle[0]) / (stand_beats * TWO_PI), 1.0)))
        return mu.spring(q, qd, settle[1] + blend * (mu.q_ref_stand - settle[1]))

    cb.set_leg_damping(False)
    rec = Record()
    speeds = []
    for k in range(beats_to_steps(beats)):
        cb.step(land, k * cb.h)
        rec.add(cb, 3 if braking[0] else 0)
        speeds.append(float(np.linalg.norm(cb.com()[1])))
    sp = np.array(speeds)
    arrays = rec.arrays()
    arrays["com_speed"] = sp  # the whole bird's centre of mass, every step
    first = int(np.argmax(arrays["foot_normal"] > 0.0))  # the touchdown's step
    above = np.nonzero(sp[first:] >= 0.01 * arrival[0])[0]
    rest = (above[-1] + 1 if len(above) else 0) / STEPS
    peak = float(np.max(arrays["foot_normal"]) / cb.weight)
    last = arrays["foot_force"][-STEPS:, 2]  # the vertical force: the bar's normal leans
    feet = d.geom_xpos[cb.feet].mean(axis=0)
    sole = np.array([feet[0], feet[1], feet[2] - cb.geom.foot_radius])
    return TouchdownResult(
        arrays,
        arrival[0],
        rest,
        peak,
        sole - np.asarray(target, dtype=float),
        float(np.mean(last) / cb.weight),
        cb.root_applied_max,
    )


STEPS = beats_to_steps(1.0)
