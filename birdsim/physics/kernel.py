"""The fused wingbeat kernel: cycle means (and their exact gradients) in one pass per
sample, compiled by numba, spread over the cores in tasks of parameter sets.

The numpy path of :mod:`birdsim.physics.cycle` stays the readable reference and the test
oracle; this module evaluates the same physics sample by sample with scalars, no array
temporaries, on every core (tasks of :data:`CHUNK` parameter sets on a thread pool;
the compiled code releases the GIL).  The model is data: each
panel's chain (hinges, slides, the wrist offset) is encoded as small integer arrays and
walked at run time, so one compiled kernel serves every model, strip count and bird
(a panel whose area follows a joint, m5's folding hand, carries one more column: see
:func:`_fold_columns`).  The compiled code is in :mod:`birdsim.physics.kernel_means`.

:func:`means` returns the cycle means per panel; :func:`means_and_gradients` adds the
exact derivatives of the means with respect to every wingbeat parameter, by forward-mode
dual numbers carried through the same chain (:mod:`birdsim.physics.kernel_dual`).

Where numba is missing or its compilation fails, :func:`available` is False (one warning
line) and callers use the numpy path.  Compiled code is cached on disk (``cache=True``:
``__pycache__`` beside this file, or numba's user-wide cache where that is read-only).
"""

from __future__ import annotations

import functools
import multiprocessing
import os
import warnings
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from birdsim.errors import BirdsimError
from birdsim.physics.aero import RoboflyPolar, SeedPolar
from birdsim.physics.bird import Bird
from birdsim.physics.jit import numba
from birdsim.physics.kernel_means import (  # _polar_force, _rot: re-exported
    _means_kernel,
    _means_rate_kernel,
    _polar_force,  # noqa: F401
    _rot,  # noqa: F401
)
from birdsim.physics.kernel_shaft import NO_MASS, NO_MATRIX, shaft_arrays
from birdsim.physics.kinematics import Joint, KinematicModel, Offset, strip_positions
from birdsim.physics.m5 import fold_bird_error

_STATE = {"ok": numba is not None, "warned": False}

#: Parameter sets per task when a batch is spread over threads (each task is one call
#: of a compiled kernel, which releases the GIL).  Smaller batches run in the caller.
CHUNK = 128


def threads() -> int:
    """Threads a batch is spread over: ``BIRDSIM_THREADS`` if set, else every core;
    1 inside a worker process (a table build already runs one process per core)."""
    env = os.environ.get("BIRDSIM_THREADS", "")
    if env.isdigit() and int(env) > 0:
        return int(env)
    if multiprocessing.parent_process() is not None:
        return 1
    return max(1, os.cpu_count() or 1)


_POOL: dict[int, ThreadPoolExecutor] = {}


def _half(phases: np.ndarray) -> int:
    """N/2 when the samples are an even periodic grid (phase t + N/2 is phase t + pi),
    else 0 (the appendix grid with both end points)."""
    n = len(phases)
    if n % 2 or n < 2 or not np.isclose(phases[n // 2] - phases[0], np.pi, rtol=0, atol=1e-12):
        return 0
    return n // 2


def _run(kernel, B: int, args: tuple) -> bool:
    """Run ``kernel(lo, hi, *args)`` over rows [0, B) on :func:`threads` threads; False
    (after one warning line) if the JIT fails."""
    try:
        n = threads()
        if n == 1 or B <= CHUNK:
            kernel(0, B, *args)
            return True
        pool = _POOL.get(n) or _POOL.setdefault(
            n, ThreadPoolExecutor(n, thread_name_prefix="birdsim-kernel")
        )
        bounds = range(0, B, CHUNK)
        for f in [pool.submit(kernel, lo, min(lo + CHUNK, B), *args) for lo in bounds]:
            f.result()
        return True
    except Exception as exc:  # noqa: BLE001 - a JIT failure must not stop the simulator
        first = str(exc).splitlines()[0] if str(exc) else ""
        _disable(f"{type(exc).__name__}: {first}")
        return False


# chain element codes
_OFFSET, _HINGE, _SLIDE, _FOLD = 0, 1, 2, 3  # _FOLD: after a chain's last element
_AXES = {"x": 0, "y": 1, "z": 2}
_GROUPS = ("shoulder", "wrist")
# polar codes
_SEED, _ROBOFLY = 0, 1


@dataclass(frozen=True)
class Setup:
    """A model and a bird as the kernel's arrays (see :func:`setup`)."""

    kind: np.ndarray  # K x L chain element codes, body -> panel order
    joint: np.ndarray  # K x L joint index
    axis: np.ndarray  # K x L axis 0, 1, 2
    group: np.ndarray  # K x L group 0 (shoulder), 1 (wrist)
    span: np.ndarray  # K x L offset along y (offsets only)
    length: np.ndarray  # K chain lengths
    radius: np.ndarray  # K x S span positions of the elements
    area: np.ndarray  # K x S element areas
    strips: np.ndarray  # K number of elements
    polar: int
    coeffs: np.ndarray  # polar coefficients
    groups: tuple[str, ...]  # group names present in the model
    joint_names: tuple[str, ...]


def supported(bird: Bird) -> bool:
    """True when the kernel knows the bird's polar (seed or robofly, exact types)."""
    return type(bird.polar) in (SeedPolar, RoboflyPolar)


@functools.lru_cache(maxsize=64)
def setup(m: KinematicModel, bird: Bird) -> Setup:
    """Encode the chains of ``m`` for ``bird`` (geometry, strips, polar) as arrays.

    Raises:
        BirdsimError: m5 for a bird without m5's geometry (one line, as evaluate_cycle).
    """
    if m.area_folds and (why := fold_bird_error(bird)) is not None:
        raise BirdsimError(f"bird: {why}")  # a direct means() call gets evaluate_cycle's guard
    panels = m.chain_with_geometry(bird)
    names = tuple(j.name for j in m.joints)
    K, L = len(panels), max(len(c) for c, _, _ in panels)
    kind, joint, axis, group = (np.zeros((K, L), dtype=np.int64) for _ in range(4))
    span = np.zeros((K, L))
    length = np.zeros(K, dtype=np.int64)
    elems = [strip_positions(s, bird.cp_span_fraction, bird.strips) for _, s, _ in panels]
    S = max(len(r) for r, _ in elems)
    radius, area = np.zeros((K, S)), np.zeros((K, S))
    strips = np.zeros(K, dtype=np.int64)
    present = set()
    for k, (chain, _, chord) in enumerate(panels):
        length[k] = len(chain)
        for i, el in enumerate(chain):
            if isinstance(el, Offset):
                kind[k, i], span[k, i] = _OFFSET, el.span
                continue
            assert isinstance(el, Joint)
            kind[k, i] = _HINGE if el.kind == "hinge" else _SLIDE
            joint[k, i], axis[k, i] = names.index(el.name), _AXES[el.axis]
            group[k, i] = _GROUPS.index(el.group)
            present.add(el.group)
        r, w = elems[k]
        strips[k] = len(r)
        radius[k, : len(r)] = r
        area[k, : len(r)] = w * chord
    if any(name is not None for name in m.area_folds):  # one more column: the area fold
        kind, joint, axis, group, span = _fold_columns(
            m, bird, names, length, kind, joint, axis, group, span
        )
    if isinstance(bird.polar, SeedPolar):
        polar, coeffs = _SEED, np.array([bird.polar.cl_max, bird.polar.cd0, bird.polar.cd_max])
    else:
        polar, coeffs = _ROBOFLY, np.zeros(3)
    groups = tuple(g for g in _GROUPS if g in present)
    return Setup(
        kind, joint, axis, group, span, length, radius, area, strips, polar, coeffs, groups, names
    )


def _fold_columns(m, bird, names, length, kind, joint, axis, group, span) -> tuple:
    """The chain arrays with one more column, where a panel whose area follows a joint
    (``m.area_folds``) has code :data:`_FOLD` at index ``length[k]``: the joint in
    ``joint``, the hand's area loss ``lambda`` in ``span``.  Models without a fold keep
    their arrays as they are (and so their numbers, bit for bit)."""
    wide = [np.pad(a, ((0, 0), (0, 1))) for a in (kind, joint, axis, group, span)]
    for k, name in enumerate(m.area_folds):
        if name is not None:
            n = length[k]
            wide[0][k, n], wide[1][k, n] = _FOLD, names.index(name)
            wide[4][k, n] = bird.hand_fold_area_loss
    return tuple(wide)


def joint_coefficients(
    m: KinematicModel, flat: dict[str, np.ndarray], bird: Bird
) -> tuple[np.ndarray, ...]:
    """Per parameter set (B) and joint (J): amplitude, phase, bias of the joint's sinusoid
    (exactly the values the numpy path uses) and whether the joint is constant."""
    names = tuple(j.name for j in m.joints)
    b = len(flat["pitch"])
    motion = m.joint_motion(flat, bird)
    amp, phase, bias = (np.zeros((b, len(names))) for _ in range(3))
    const = np.zeros(len(names), dtype=np.bool_)
    for j, name in enumerate(names):
        s = motion[name]
        amp[:, j], phase[:, j], bias[:, j] = s.amp, s.phase, s.bias
        const[j] = isinstance(s.amp, float) and s.amp == 0.0
    return amp, phase, bias, const


@functools.lru_cache(maxsize=64)
def joint_derivatives(m: KinematicModel, bird: Bird) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """d(amp, phase, bias)/d(param), J x d: every joint's sinusoid is affine in the parameters."""
    names = m.param_names
    d = len(names)

    def at(x: np.ndarray) -> tuple[np.ndarray, ...]:
        a, p, b, _ = joint_coefficients(m, {n: x[i : i + 1] for i, n in enumerate(names)}, bird)
        return a[0], p[0], b[0]

    zero = at(np.zeros(d))
    out = [np.zeros((len(zero[0]), d)) for _ in range(3)]
    for i in range(d):
        e = np.zeros(d)
        e[i] = 1.0
        for q, (v1, v0) in enumerate(zip(at(e), zero)):
            out[q][:, i] = v1 - v0
    return out[0], out[1], out[2]


def available() -> bool:
    """True while the compiled kernel can be used."""
    return _STATE["ok"]


def _disable(reason: str) -> None:
    _STATE["ok"] = False
    if not _STATE["warned"]:
        _STATE["warned"] = True
        warnings.warn(
            f"birdsim: the fused kernel is unavailable ({reason}); using the numpy path",
            RuntimeWarning,
            stacklevel=3,
        )


def means(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    air_earth: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
    *,
    body_rate: np.ndarray | None = None,
    positive: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Cycle means per panel for flat (B,) parameter arrays, or None where the kernel
    cannot run (the caller then uses numpy).  ``body_rate`` (B x 3, body axes, or None
    for none) adds ``omega x r`` to every element's air velocity.  ``positive`` (B, or
    None) receives each row's positive shaft power (the bird's wing mass; the periodic
    grid: :mod:`birdsim.physics.kernel_shaft`).

    Returns:
        ``(force_earth B x K x 3, power B x K, joint_power B x G)`` (groups in
        :attr:`Setup.groups` order; seed earth axes, no body drag).
    """
    if not _STATE["ok"] or not supported(bird):
        return None
    st = setup(m, bird)
    amp, phase, bias, const = joint_coefficients(m, flat, bird)
    c = np.ascontiguousarray
    B, K = len(speed), len(st.length)
    F, P, JP = np.zeros((B, K, 3)), np.zeros((B, K)), np.zeros((B, 2))
    shaft = (NO_MASS, NO_MASS, NO_MATRIX, False)
    if positive is not None:
        shaft = (positive, *shaft_arrays(m, bird, len(phases)), True)
    args = (
        c(flat["pitch"], dtype=float),
        c(speed, dtype=float),
        c(climb, dtype=float),
        c(air_earth, dtype=float),
        amp,
        phase,
        bias,
        const,
        c(phases, dtype=float),
        _half(phases),
        float(bird.omega),
        float(bird.rho),
        st.kind,
        st.joint,
        st.axis,
        st.group,
        st.span,
        st.length,
        st.radius,
        st.area,
        st.strips,
        st.polar,
        st.coeffs,
        F,
        P,
        JP,
        *shaft,
    )
    if body_rate is not None:  # the rotating body: same kernel, omega x r added
        args, fn = args + (c(body_rate, dtype=float), True), _means_rate_kernel
    else:
        fn = _means_kernel
    if not _run(fn, B, args):
        return None
    return F, P, JP[:, [_GROUPS.index(g) for g in st.groups]]


def means_and_gradients(
    m: KinematicModel,
    flat: dict[str, np.ndarray],
    speed: np.ndarray,
    climb: np.ndarray,
    bird: Bird,
    phases: np.ndarray,
    *,
    positive: bool = False,
) -> tuple[np.ndarray, np.ndarray] | None:
    """Right-wing mean force and power with their exact parameter gradients (no induced
    velocity, no body drag), or None where the kernel cannot run.  ``positive``: the
    power row is the positive shaft power instead (:mod:`birdsim.physics.kernel_shaft`).

    Returns:
        ``(values B x 4, gradients B x 4 x d)``: rows Fx, Fy, Fz, P of the right wing
        (seed earth axes), columns of the gradient in ``m.param_names`` order.
    """
    if not _STATE["ok"] or not supported(bird) or bird.induced_velocity:
        return None
    st = setup(m, bird)
    amp, phase, bias, const = joint_coefficients(m, flat, bird)
    from birdsim.physics.kernel_dual import _grad_kernel

    damp, dphase, dbias = joint_derivatives(m, bird)
    ip = m.param_names.index("pitch")
    c = np.ascontiguousarray
    B, d = len(speed), len(m.param_names)
    out = np.zeros((B, 4, d + 1))
    args = (
        c(flat["pitch"], dtype=float),
        c(speed, dtype=float),
        c(climb, dtype=float),
        amp,
        phase,
        bias,
        const,
        damp,
        dphase,
        dbias,
        ip,
        c(phases, dtype=float),
        float(bird.omega),
        float(bird.rho),
        st.kind,
        st.joint,
        st.axis,
        st.group,
        st.span,
        st.length,
        st.radius,
        st.area,
        st.strips,
        st.polar,
        st.coeffs,
        out,
        *(shaft_arrays(m, bird, len(phases)) if positive else (NO_MASS, NO_MATRIX)),
        positive,
    )
    if not _run(_grad_kernel, B, args):
        return None
    return out[:, :, 0], out[:, :, 1:]
