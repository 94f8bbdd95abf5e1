"""One wingbeat: force and power histories of the right wing and their means.

``evaluate_cycle`` is vectorised over time *and* over any batch of parameter sets:
pass arrays (all broadcastable to one batch shape ``B``) instead of floats and every
result gains the leading axes ``B``.  The means come from the fused kernel
(:mod:`birdsim.physics.kernel`, the default backend) or from this module's numpy path
(``backend="numpy"``, the readable reference; it also gives the histories).  MuJoCo's
passive callback calls the polar of :func:`element_forces`' path, so both share one
implementation of the aerodynamics.  The result types live in
:mod:`birdsim.physics.cycle_result`.

Forces follow docs/design.md's "which force": the histories are those of ONE wing (the
right) in seed earth axes; ``mean`` adds the body drag to Fx (the dissertation's
flapcost force); ``whole_bird_mean`` is two mirrored wings plus the body.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from birdsim.errors import BirdsimError, check_numbers
from birdsim.physics.aero import body_drag, induced_velocity
from birdsim.physics.bird import Bird
from birdsim.physics.cycle_result import Cycle, MeanForces, PanelMeans, _Histories, cycle_mean  # noqa: F401 (re-exported)
from birdsim.physics.frames import Vec3, _is_zero, body_to_earth, earth_to_body
from birdsim.physics.inputs import _check_climb, check_body_rate, cross
from birdsim.physics.kinematics import (
    Joint,
    KinematicModel,
    _add,
    body_to_panel,
    get_model,
    joint_states,
    panel_to_body,
    points_in_body,
    strip_positions,
    validate_params,
)
from birdsim.physics.m5 import fold_bird_error

#: Samples per wingbeat of :func:`evaluate_cycle` (and of the CLI's ``forces`` and a table
#: build's final check): the smallest even n that puts the mean force within 1e-7 of the
#: converged mean (n -> infinity) for 99.9 % of random parameter sets of every model, with
#: 95 % confidence (measured on 131 072 sets per model, confirmed on 131 072 more: the
#: slowest model, m3, 99.947 %; docs/performance.md "Samples per wingbeat",
#: ``tests/test_samples_accuracy.py``).  Sets that pass near flow reversal converge only
#: as n^-3, the rest spectrally.
DEFAULT_SAMPLES = 238


def sample_phases(n: int, endpoint: bool) -> np.ndarray:
    """Phases omega*t of the samples: N uniform on [0, 2 pi) (exact periodic mean), or
    with the end point included (the appendix grid, n = 11)."""
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 2:
        raise BirdsimError(f"n={n!r} is invalid; allowed: an integer >= 2 samples per wingbeat")
    return _phases(int(n), bool(endpoint))


@lru_cache(maxsize=32)
def _phases(n: int, endpoint: bool) -> np.ndarray:
    out = np.linspace(0.0, 2.0 * np.pi, n, endpoint=endpoint)
    out.setflags(write=False)  # shared between calls
    return out


@dataclass(frozen=True)
class ElementForces:
    """Forces on the elements of one panel (body axes) and their flapping velocities."""

    force_body: Vec3
    position_body: Vec3
    velocity_body: dict[str, Vec3]


def element_forces(
    chain,
    states,
    span_positions: np.ndarray,
    widths: np.ndarray,
    chord: float,
    air_velocity_body: Vec3,
    bird: Bird,
    body_rate: Vec3 | None = None,
) -> ElementForces:
    """Blade-element force on each element of a panel, in body axes.

    ``air_velocity_body`` is the velocity of the body relative to the air (the
    freestream seen from the body, e.g. ``(V cos theta, 0, V sin theta)``).  The element
    moves relative to the air at that plus its flapping velocity (plus ``omega x r`` for
    a ``body_rate`` omega, body axes, r from the torso origin); its velocity is rotated
    into panel axes, the polar gives the panel-axes force, and it is rotated back.  This
    is the one implementation of the aerodynamics (MuJoCo uses it too).
    """
    pos, vel_groups = points_in_body(chain, states, span_positions)
    v_flap = _sum_groups(vel_groups)
    v_rel = tuple(_add(a, b) for a, b in zip(air_velocity_body, v_flap))
    if body_rate is not None:
        v_rel = tuple(_add(a, b) for a, b in zip(v_rel, cross(body_rate, pos)))
    vx, _, vz = body_to_panel(chain, states, v_rel)
    fx, fz = bird.polar.force_panel(vx, vz, widths * chord, bird.rho)
    force = panel_to_body(chain, states, (fx, 0.0, fz))
    return ElementForces(force, pos, vel_groups)


def _sum_groups(groups: dict[str, Vec3]) -> Vec3:
    total: Vec3 = (0.0, 0.0, 0.0)
    for v in groups.values():
        total = tuple(_add(a, b) for a, b in zip(total, v))  # type: ignore[assignment]
    return total


def _over_strips(c: np.ndarray | float) -> np.ndarray | float:
    """Sum over the trailing strip axis (a plain view for the one-control-point default)."""
    c = np.asarray(c)
    if c.ndim == 0:
        return c
    return c[..., 0] if c.shape[-1] == 1 else c.sum(axis=-1)


def _first_strip(c: np.ndarray | float) -> np.ndarray | float:
    c = np.asarray(c)
    return c if c.ndim == 0 else c[..., 0]


def _dot(a: Vec3, b: Vec3) -> np.ndarray:
    out: np.ndarray | float = 0.0
    for x, y in zip(a, b):
        if not (_is_zero(x) or _is_zero(y)):
            out = _add(out, x * y)
    return out


def evaluate_cycle(
    model: str | KinematicModel,
    params: Mapping[str, object],
    speed: object,
    *,
    climb: object = 0.0,
    bird: Bird | None = None,
    n: int = DEFAULT_SAMPLES,
    endpoint: bool = False,
    check_bounds: bool = True,
    backend: str = "kernel",
    body_rate: object = (0.0, 0.0, 0.0),
) -> Cycle:
    """Force and power histories of one wingbeat and their means.

    Args:
        model: a model name or :class:`KinematicModel`.
        params: every parameter name of the model (``birdsim.MODELS[m].param_names``)
            to a float or an array [rad]; arrays broadcast to one batch shape ``B`` and
            every result gains it.
        speed: flight speed V >= 0 relative to the air, along seed earth +X.
        climb: vertical speed relative to the air, positive up (any sign): the body
            moves at ``(V, 0, -climb)`` in seed earth axes; 0 is level flight.
        bird: the bird (default: the seed bird).
        n: samples per wingbeat (default :data:`DEFAULT_SAMPLES`: the mean force within
            1e-7 of the converged mean for 99.9 % of parameter sets; the histories, when
            read, have the same n, so the mean is the mean of the histories);
            ``endpoint=True, n=11`` is the appendix grid.
        check_bounds: refuse parameters outside the model's bounds.
        body_rate: the body's angular velocity (p, q, r) in body axes [rad per unit
            time], shape (3,) or ``B + (3,)``: every element's air velocity gains
            ``omega x r`` (r from the torso origin: shoulders and centre of mass).  Zero
            (the default) is today's result bit for bit.  Power stays ``-F . v_flap``.
        backend: ``"kernel"`` (default: the fused, compiled kernel of
            :mod:`birdsim.physics.kernel` computes the means; histories, when read, come
            from the numpy path) or ``"numpy"`` (the readable reference, everything
            numpy).  Without a working JIT the kernel falls back to numpy (one warning).

    Returns:
        A :class:`Cycle`.

    Raises:
        BirdsimError: bad speed, climb, parameters or shapes (one line).
    """
    m = model if isinstance(model, KinematicModel) else get_model(model)
    bird = Bird() if bird is None else bird
    if not isinstance(bird, Bird):
        raise BirdsimError(
            f"bird={bird!r} is invalid; allowed: a birdsim.Bird (Bird.from_toml(path) reads a bird file) or None"
        )
    if m.area_folds and (why := fold_bird_error(bird)) is not None:
        raise BirdsimError(f"bird: {why}")
    p = validate_params(m, params, check_bounds=check_bounds)
    v = check_numbers("speed", speed, "a finite number >= 0", minimum=0.0)
    vc = _check_climb(climb)
    rate = check_body_rate(body_rate)
    try:
        batch = np.broadcast_shapes(
            v.shape, vc.shape, rate.shape[:-1], *(a.shape for a in p.values())
        )
    except ValueError:
        named = {"speed": v, "climb": vc, "body_rate[..., 0]": rate[..., 0], **p}
        shapes = ", ".join(f"{k} {a.shape}" for k, a in named.items())
        raise BirdsimError(
            f"parameter shapes do not broadcast ({shapes}); allowed: arrays of one common shape"
        ) from None
    flat = {k: np.broadcast_to(a, batch).reshape(-1) for k, a in p.items()}
    v_flat = np.broadcast_to(v, batch).reshape(-1)
    climb_flat = np.broadcast_to(vc, batch).reshape(-1)
    phases = sample_phases(n, endpoint)
    climbing = bool(np.any(climb_flat != 0.0))
    rate_flat = np.broadcast_to(rate, batch + (3,)).reshape(-1, 3)
    rates = rate_flat if np.any(rate_flat != 0.0) else None  # None: bit for bit today's path
    vc_or_none = climb_flat if climbing else None

    def shaped(a: np.ndarray) -> np.ndarray:
        return a.reshape(batch + a.shape[1:])

    def histories() -> _Histories:
        air_earth = np.zeros(v_flat.shape + (3,))
        hist = _histories(m, flat, v_flat, bird, phases, air_earth, vc_or_none, rates)
        if bird.induced_velocity:
            # Actuator disc (appendix 1A): the disc pushes the air against the mean force of
            # both wings (seed earth axes); iterate the coupling to a fixed point (damped by
            # 1/2, which roughly halves the step each time: 8 steps left ~1e-4 in the force)
            for _ in range(INDUCED_MAX_ITERATIONS):
                f = 2.0 * hist.force_earth.sum(axis=1).mean(axis=-2)  # two wings, B x 3
                f[:, 1] = 0.0
                vi = induced_velocity(
                    f, v_flat, bird.rho, bird.disc_area, climb=climb_flat if climbing else None
                )
                norm = np.linalg.norm(f, axis=-1, keepdims=True)
                f_hat = np.divide(f, norm, out=np.zeros_like(f), where=norm > 0)
                target = -vi[:, None] * f_hat
                if np.max(np.abs(target - air_earth), initial=0.0) < INDUCED_TOL:
                    break
                air_earth = 0.5 * air_earth + 0.5 * target
                hist = _histories(m, flat, v_flat, bird, phases, air_earth, vc_or_none, rates)
        return _Histories(
            shaped(hist.force_earth),
            shaped(hist.power),
            {g: shaped(a) for g, a in hist.joint_power.items()},
            shaped(hist.cp_position),
            shaped(hist.cp_velocity),
        )

    if backend not in BACKENDS:
        raise BirdsimError(f"backend={backend!r} is unknown; allowed: {', '.join(BACKENDS)}")
    means = None
    if backend == "kernel":
        means = _kernel_means(m, flat, v_flat, climb_flat, climbing, bird, phases, rates)
        if means is not None:
            means = PanelMeans(
                shaped(means.force_earth),
                shaped(means.power),
                {g: shaped(a) for g, a in means.joint_power.items()},
            )
    dx, dz = body_drag(v_flat, climb_flat, flat["pitch"], bird.rho, bird.body_drag_area)
    cyc = Cycle(
        model=m.name,
        speed=shaped(v_flat),
        params={k: shaped(a) for k, a in flat.items()},
        time=phases / bird.omega,
        endpoint=endpoint,
        panel_names=tuple(panel.name for panel in bird.panels(m.name)),
        body_drag_x=shaped(dx),
        climb=shaped(climb_flat),
        body_drag_z=shaped(dz),
        histories=histories,
        panel_means=means,
    )
    if means is None:
        _ = cyc._hist  # the numpy path computes its histories now (errors surface here)
    return cyc


BACKENDS = ("kernel", "numpy")


def _kernel_means(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    v: np.ndarray,
    climb: np.ndarray,
    climbing: bool,
    bird: Bird,
    phases: np.ndarray,
    rate: np.ndarray | None = None,
) -> PanelMeans | None:
    """Panel means from the fused kernel (flat batch), the induced-velocity coupling
    iterated exactly as the numpy path does; None where the kernel cannot run."""
    from birdsim.physics import kernel

    air = np.zeros(v.shape + (3,))
    out = kernel.means(m, flat, v, climb, air, bird, phases, body_rate=rate)
    if out is None:
        return None
    if bird.induced_velocity:
        for _ in range(INDUCED_MAX_ITERATIONS):
            f = 2.0 * out[0].sum(axis=1)  # two wings, B x 3
            f[:, 1] = 0.0
            vi = induced_velocity(f, v, bird.rho, bird.disc_area, climb=climb if climbing else None)
            norm = np.linalg.norm(f, axis=-1, keepdims=True)
            f_hat = np.divide(f, norm, out=np.zeros_like(f), where=norm > 0)
            target = -vi[:, None] * f_hat
            if np.max(np.abs(target - air), initial=0.0) < INDUCED_TOL:
                break
            air = 0.5 * air + 0.5 * target
            out = kernel.means(m, flat, v, climb, air, bird, phases, body_rate=rate)
            if out is None:
                return None
    groups = kernel.setup(m, bird).groups
    return PanelMeans(out[0], out[1], {g: out[2][:, i] for i, g in enumerate(groups)})


#: The induced-velocity coupling stops when the disc's inflow changes by less than this
#: (the bisection in :func:`birdsim.physics.aero.induced_velocity` resolves ~1e-16).
INDUCED_TOL = 1e-10
INDUCED_MAX_ITERATIONS = 100

#: Parameter sets evaluated together: their (chunk x samples) arrays stay in the CPU
#: cache, which measured faster than one pass over a large batch (make bench).
CHUNK = 256


def _histories(
    m: KinematicModel,
    p: dict[str, np.ndarray],
    speed: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
    air_earth: np.ndarray,
    climb: np.ndarray | None = None,
    body_rate: np.ndarray | None = None,
) -> _Histories:
    """Histories for flat (B,) parameter arrays, evaluated chunk by chunk (``body_rate``
    B x 3 or None for a body that does not rotate)."""
    panels = m.chain_with_geometry(bird)
    groups = sorted({el.group for chain, _, _ in panels for el in chain if isinstance(el, Joint)})
    b, k, n = speed.shape[0], len(panels), len(phases)
    out = _Histories(
        np.empty((b, k, n, 3)),
        np.empty((b, k, n)),
        {g: np.zeros((b, n)) for g in groups},
        np.empty((b, k, n, 3)),
        np.empty((b, k, n, 3)),
    )
    for lo in range(0, b, CHUNK):
        sl = slice(lo, min(lo + CHUNK, b))
        vc = None if climb is None else climb[sl]
        w = None if body_rate is None else tuple(body_rate[sl, i][:, None, None] for i in range(3))
        _chunk(
            {name: a[sl] for name, a in p.items()},
            speed[sl],
            vc,
            air_earth[sl],
            m,
            panels,
            bird,
            phases,
            out,
            sl,
            w,
        )
    return out


def _chunk(
    p, speed, climb, air_earth, m, panels, bird, phases, out: _Histories, sl: slice, rate=None
) -> None:
    pitch_b = p["pitch"][:, None, None]
    states = joint_states(m, p, bird, phases, trailing=1)
    # the body relative to the air, in body axes: ((V, 0, -climb) - w_air) rotated by the pitch
    rel_z = -air_earth[:, 2] if climb is None else -climb - air_earth[:, 2]
    rel_earth = tuple(c[:, None, None] for c in (speed - air_earth[:, 0], -air_earth[:, 1], rel_z))
    air_body = earth_to_body(pitch_b, rel_earth)
    for k, (chain, span, chord) in enumerate(panels):
        r, w = strip_positions(span, bird.cp_span_fraction, bird.strips)
        el = element_forces(
            chain, states, r, w, chord * m.area_scale(k, states, bird), air_body, bird, rate
        )
        v_flap = _sum_groups(el.velocity_body)
        f_earth = body_to_earth(pitch_b, el.force_body)
        for i in range(3):
            out.force_earth[sl, k, :, i] = _over_strips(f_earth[i])
            out.cp_position[sl, k, :, i] = _first_strip(el.position_body[i])
            out.cp_velocity[sl, k, :, i] = _first_strip(v_flap[i])
        out.power[sl, k, :] = -_over_strips(_dot(el.force_body, v_flap))
        for g, vg in el.velocity_body.items():
            out.joint_power[g][sl] -= _over_strips(_dot(el.force_body, vg))
