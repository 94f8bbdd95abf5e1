"""Inverse dynamics: from a path's acceleration to the table's force demand.

Newton for the whole bird in the sagittal plane, reduced units (issue 9, item 3):
``m a = F_aero,whole + m g`` with ``m`` the mass ratio ``mu = m / (rho s^2 c)`` and ``g``
the reduced gravity ``g / (omega^2 s)`` (:func:`birdsim.physics.units.reduced_bird`).
The whole bird's aerodynamic force is two mirrored wings plus the body drag ``D``; the
table's force is the dissertation's, ONE (right) wing plus the body drag, in seed earth
axes (X forward, Z down, Fz < 0 up)::

    F_whole = 2 F_wing + D            F_table = F_wing + D_table

``D`` follows the climb contract (docs/flight.md): ``1/2 rho Vt^2 A_b |sin(theta - gamma)|``
opposite the velocity relative to the air ``(V, 0, -climb)``, ``gamma = atan2(climb, V)``;
``D_table`` is the drag the table's cycles carry (climb 0: eq. 7 along X,
``-1/2 rho V^2 sin(theta) A_b``). In level flight (climb 0) the two are equal and

    Fx_table = (Fx_whole + D) / 2,      Fz_table = Fz_whole / 2,

so unaccelerated level flight needs ``Fz_table = -w / 2`` (w: the weight in table units)
and a whole-bird ``Fx = 0``. The table's ``V`` is the horizontal airspeed ``vx`` (no wind
on a path).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from birdsim.flight.path import FlightPath
from birdsim.physics.bird import Bird
from birdsim.physics.units import reduced_bird

#: Fixed-point steps for the body drag's pitch in :func:`path_demands`, and when to stop [rad].
PITCH_ITERATIONS = 8
PITCH_TOL = 1e-6


def body_drag_earth(bird: Bird, V: Any, climb: Any, pitch: Any) -> tuple[np.ndarray, np.ndarray]:
    """Body drag in seed earth axes (X forward, Z down) for airspeed ``(V, 0, -climb)``.

    Args:
        bird: the bird (its own units; reduced bird -> reduced force).
        V: horizontal speed relative to the air [omega s], array-like.
        climb: vertical speed relative to the air, positive up [omega s].
        pitch: body pitch theta, nose up [rad].

    Returns:
        (Dx, Dz): ``1/2 rho Vt^2 A_b |sin(theta - gamma)|`` opposite the velocity. With
        ``climb = 0`` Dx equals eq. 7 (``aero.body_drag_x``) and Dz = 0.
    """
    if not (isinstance(V, float) and isinstance(climb, float) and isinstance(pitch, float)):
        V, climb, pitch = (np.asarray(a, dtype=float) for a in (V, climb, pitch))
    # (floats: the same operations on Python floats and numpy scalars, the same bits)
    vt = np.hypot(V, climb)
    gamma = np.arctan2(climb, V)
    mag = 0.5 * bird.rho * vt * np.abs(np.sin(pitch - gamma)) * bird.body_drag_area  # |D| / Vt
    return -mag * V, mag * climb


def demand_from_acceleration(
    ax_up: Any, az_up: Any, vx: Any, vz: Any, bird: Bird, pitch: Any, *, table_climb: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """The table force (one wing + body drag, seed axes) that gives the bird an acceleration.

    Args:
        ax_up: acceleration forward [omega^2 s] (x forward, z up), array-like.
        az_up: acceleration up [omega^2 s].
        vx: horizontal speed relative to the air [omega s] (the table's V).
        vz: vertical speed relative to the air, up [omega s] (the climb).
        bird: the bird; reduced here (:func:`reduced_bird`), so the SI bird and its
            reduced bird give the same answer. Its ``mass`` and ``gravity`` are used.
        pitch: body pitch for the body drag [rad] (the table's, see :func:`path_demands`).
        table_climb: the table is read at climb ``vz`` (a table with a climb axis): its
            cycles carry the climbing body drag ``D``, so ``F_table = (F_whole + D) / 2``
            in both components. False: a level table (``D_table`` at climb 0).

    Returns:
        (Fx_table, Fz_table) in table force units ``rho omega^2 s^3 c``; Fz < 0 is up.
        Level, unaccelerated flight: ``Fz_table = -w / 2`` and a whole-bird Fx of 0.
    """
    rb = reduced_bird(bird)
    ax, az = ax_up, az_up
    if not all(isinstance(a, float) for a in (ax_up, az_up, vx, vz, pitch)):
        ax, az, vx, vz = (np.asarray(a, dtype=float) for a in (ax_up, az_up, vx, vz))
    fx_whole = rb.mass * ax  # seed X = world x
    fz_whole = -rb.mass * (az + rb.gravity)  # seed Z = -world z; gravity pulls down
    dx, dz = body_drag_earth(rb, vx, vz, pitch)
    wing_x, wing_z = 0.5 * (fx_whole - dx), 0.5 * (fz_whole - dz)
    if table_climb:  # the table's cycles climb at vz and carry the same drag
        return wing_x + dx, wing_z + dz
    dx_table, _ = body_drag_earth(rb, vx, 0.0, pitch)  # the table's cycles fly level
    return wing_x + dx_table, wing_z


#: Airspeed [omega s] above which :func:`air_path_demand` turns the table by the whole
#: flight-path angle; below it the turn fades out quadratically (at hover the direction of
#: the flow means nothing).
CLIMB_SPEED = 0.2


def air_path_angle(vx: Any, vz: Any, climb_speed: float = CLIMB_SPEED) -> Any:
    """The angle [rad] by which a level table is turned into the air path: the flight-path
    angle ``atan2(vz, vx)`` faded out quadratically below a *forward* airspeed of
    ``climb_speed`` (none at hover, none when flying backwards through the air: hovering up
    or down is not level flight turned by 90 degrees as far as the table's reach goes).
    ``vx``, ``vz``: velocity relative to the air [omega s], floats or arrays."""
    if isinstance(vx, float) and isinstance(vz, float):  # one demand (the controller's)
        return _air_path_angle_float(vx, vz, climb_speed)
    vx, vz = np.asarray(vx, dtype=float), np.asarray(vz, dtype=float)
    gamma = np.where(np.hypot(vx, vz) > 0, np.arctan2(vz, vx), 0.0)
    return gamma * np.minimum(1.0, (np.maximum(vx, 0.0) / climb_speed) ** 2)


def _air_path_angle_float(vx: float, vz: float, climb_speed: float) -> np.float64:
    """:func:`air_path_angle` of two floats, the same bits: numpy's ``hypot`` and
    ``arctan2`` (they differ from the C library's in the last bit), numpy's maximum
    ``vx if vx >= 0 or vx is NaN else 0``, the power of the numpy scalar that makes (the C
    library's ``pow``, as Python's ``**``: not always ``f * f``) and numpy's minimum ``1
    if 1 <= f else f`` in Python floats."""
    gamma = np.arctan2(vz, vx) if np.hypot(vx, vz) > 0 else np.float64(0.0)
    f = vx if (vx >= 0.0 or vx != vx) else 0.0
    f = (f / climb_speed) ** 2
    return gamma * (1.0 if 1.0 <= f else f)


def air_path_demand(
    ax_up: Any,
    az_up: Any,
    vx: Any,
    vz: Any,
    bird: Bird,
    pitch: Any,
    *,
    climb_speed: float = CLIMB_SPEED,
) -> tuple[Any, Any, Any, Any]:
    """The table demand for climbing or descending flight read in the air-path frame.

    Tables are built for level flight. Flying along an air path inclined by
    ``gamma = atan2(vz, vx)`` is level flight turned by gamma: the wings see the same flow
    when the body pitch is the table's plus gamma. So the needed aerodynamic force
    ``m (a - g)`` is turned into the air-path frame and looked up at the airspeed
    ``hypot(vx, vz)`` (gamma from :func:`air_path_angle`, the rule the controller flies).
    In level flight this is :func:`demand_from_acceleration` exactly.

    Args (floats, or arrays that broadcast):
        ax_up, az_up: acceleration [omega^2 s], x forward, z up.
        vx, vz: velocity relative to the air [omega s].
        bird: the bird (reduced internally).
        pitch: the body pitch the table would give [rad] (gamma is taken off it for the
            body drag, which the table computes at the table's own pitch).
        climb_speed: the fade-out speed of the turn [omega s].

    Returns:
        (Fx_table, Fz_table, V_table, gamma): the table force (one wing + body drag, seed
        axes), the table's speed and the turn angle [rad] to add to the table's pitch;
        floats for scalar arguments, else arrays.
    """
    rb = reduced_bird(bird)
    m, grav = rb.mass, rb.gravity
    scalar = all(np.ndim(a) == 0 for a in (ax_up, az_up, vx, vz, pitch))
    ax, az, vx, vz, pitch = (np.asarray(a, dtype=float) for a in (ax_up, az_up, vx, vz, pitch))
    speed = np.hypot(vx, vz)
    gamma = air_path_angle(vx, vz, climb_speed)
    f_x, f_z = m * ax, m * (az + grav)  # aerodynamic force needed, world (z up)
    c, s = np.cos(gamma), np.sin(gamma)
    w_x, w_z = c * f_x + s * f_z, -s * f_x + c * f_z  # in the air-path frame
    v_table = np.where(gamma != 0.0, speed, vx)
    fx, fz = demand_from_acceleration(w_x / m, w_z / m - grav, v_table, 0.0, rb, pitch - gamma)
    if scalar:
        return float(fx), float(fz), float(v_table), float(gamma)
    return fx, fz, v_table, gamma


def path_demands(path: FlightPath, bird: Bird, table: Any, t: Any) -> dict[str, np.ndarray]:
    """The feed-forward schedule of a path: the table demands at reduced times ``t``.

    The body drag needs the pitch, which the table gives for the demand: fixed-point steps
    from pitch 0 (demand -> the table's pitch there -> demand with the drag at that pitch),
    at most :data:`PITCH_ITERATIONS`, until the pitch moves less than :data:`PITCH_TOL`;
    lookups clip to the table's grid.

    Args:
        path: the flight path.
        bird: the bird (reduced internally).
        table: a LookupTable (``lookup_many``) whose parameters include ``pitch``.
        t: reduced times (array-like, one wingbeat = 2 pi).

    Returns:
        Arrays of t's shape: ``Fx``, ``Fz`` (table force), ``V`` (= vx, the table's
        speed), ``climb`` (= vz), ``pitch`` (the table's, used for the drag), and the path's
        ``x``, ``z``, ``vx``, ``vz``, ``ax``, ``az``.
    """
    s = path.sample(t)
    V, climb = s["vx"], s["vz"]
    pitch = np.zeros(np.shape(V))
    for _ in range(PITCH_ITERATIONS):
        fx, fz = demand_from_acceleration(s["ax"], s["az"], V, climb, bird, pitch)
        new = table.lookup_many(Fx=fx, Fz=fz, V=np.maximum(V, 0.0), clip=True)["pitch"]
        done = np.max(np.abs(new - pitch), initial=0.0) < PITCH_TOL
        pitch = new
        if done:
            break
    fx, fz = demand_from_acceleration(s["ax"], s["az"], V, climb, bird, pitch)
    return {"Fx": fx, "Fz": fz, "V": V, "climb": climb, "pitch": pitch, **s}


def path_schedule(path: FlightPath, bird: Bird, table: Any, *, per_beat: int = 4) -> Any:
    """A path's feed-forward demands as a force-keyframe manoeuvre, for the kinematic
    playback (``birdsim render --kinematic``) and open-loop flight of today's format.

    Keyframes every ``1 / per_beat`` wingbeat carry :func:`path_demands` (Fx, Fz, V
    clipped at 0) and the path's height; the playback's perch convention (perched height
    ``manoeuvre.PERCH_HEIGHT``, shifted onto the scene's perch) is applied to z.

    Returns:
        A :class:`birdsim.flight.manoeuvre.Manoeuvre` with the path's name and duration.
    """
    from birdsim.flight.manoeuvre import PERCH_HEIGHT, Keyframe, Manoeuvre
    from birdsim.flight.path import PERCH_Z

    n = int(math.ceil(path.duration_beats * per_beat)) + 1
    tb = np.linspace(0.0, path.duration_beats, n)
    d = path_demands(path, bird, table, tb * 2.0 * math.pi)
    perch = "start" if path.perch_start else ("end" if path.perch_end else "")
    dz = PERCH_HEIGHT - PERCH_Z if perch else 0.0
    keyframes, last = [], None
    for i, t in enumerate(tb):
        label = path.regime(float(t))
        keyframes.append(
            Keyframe(
                float(t),
                float(d["Fx"][i]),
                float(d["Fz"][i]),
                max(float(d["V"][i]), 0.0),
                float(d["z"][i]) + dz,
                label if label != last else "",
            )
        )
        last = label
    return Manoeuvre(path.name, tuple(keyframes), path.duration_beats, path.description, perch)


__all__ = [
    "CLIMB_SPEED",
    "air_path_angle",
    "air_path_demand",
    "body_drag_earth",
    "demand_from_acceleration",
    "path_demands",
    "path_schedule",
]
