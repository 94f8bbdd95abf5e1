"""One wingbeat at a time: the optimiser's lean path to the fused kernel.

SLSQP asks for one parameter set at a time (a value at every line-search trial, a
gradient at every accepted iterate).  The batched path (:func:`birdsim.tables.cost.forces`)
rebuilds per call what does not change during a cell's solve: the joint sinusoids'
coefficients from the parameter dictionary, the sample phases, the output arrays, the
body drag's dependence on speed and climb.  :class:`PointForces` prepares all of that once
per (model, bird, speed, climb, samples) and then calls the compiled kernels
(:func:`birdsim.physics.kernel._means_kernel`, :func:`birdsim.physics.kernel_dual._grad_kernel`,
the same compiled code as the batched path, so nothing new is compiled) with one row.

The joint sinusoids are affine in the parameters (:func:`birdsim.physics.kernel.joint_derivatives`),
so a row's amplitudes, phases and biases are ``c0 + D x``; this is checked against the
model's own ``joint_motion`` when a :class:`PointForces` is made (at random rows, to
1e-12) and the lean path is refused where it does not hold.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from birdsim.physics import kernel
from birdsim.physics.bird import Bird
from birdsim.physics.cycle import sample_phases
from birdsim.physics.kernel_dual import _grad_kernel
from birdsim.physics.kernel_shaft import NO_MASS, NO_MATRIX, shaft_arrays
from birdsim.physics.kinematics import KinematicModel

_COMPILED = {"ok": False}  # both kernels ran once in this process
#: The gradient kernel's output rows of Fx, Fz and P (row 1 is Fy).
_ROWS = np.array([0, 2, 3])


@functools.lru_cache(maxsize=64)
def _joint_map(model: KinematicModel, bird: Bird) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(c0 3 x J, D 3 x J x d, const J)``: the joints' (amplitude, phase, bias) of a row
    ``x`` are ``c0 + D x``; ``const`` marks joints that never move."""
    a0, p0, b0, const = kernel.joint_coefficients(
        model, {k: np.zeros(1) for k in model.param_names}, bird
    )
    return np.stack([a0[0], p0[0], b0[0]]), np.stack(kernel.joint_derivatives(model, bird)), const


@functools.lru_cache(maxsize=64)
def _affine(model: KinematicModel, bird: Bird) -> bool:
    """True when :func:`_joint_map` reproduces the model's ``joint_motion`` (at random
    rows, to 1e-12)."""
    c0, D, _ = _joint_map(model, bird)
    lo, hi = model.bounds
    X = np.random.default_rng(0).uniform(lo, hi, size=(3, lo.size))
    a, p, b, _ = kernel.joint_coefficients(
        model, {k: X[:, i] for i, k in enumerate(model.param_names)}, bird
    )
    return bool(
        np.allclose(
            c0[:, None, :] + np.einsum("qjd,bd->qbj", D, X),
            np.stack([a, p, b]),
            rtol=0.0,
            atol=1e-12,
        )
    )


class PointForces:
    """Mean (Fx, Fz, P) of ONE parameter row, and their exact gradients, at a fixed
    speed V and climb (the dissertation's force: right wing + body drag, seed earth
    axes; P the right wing's mean power, or its positive shaft power for a bird with
    ``power_cost = "positive"``).  Make one with :meth:`create`."""

    def __init__(
        self, model: KinematicModel, bird: Bird, speed: float, climb: float, n: int
    ) -> None:
        st = kernel.setup(model, bird)
        names = model.param_names
        d = len(names)
        self.c0, self.D, const = _joint_map(model, bird)
        damp, dphase, dbias = self.D
        self.dim, self.ip = d, names.index("pitch")
        phases = np.ascontiguousarray(sample_phases(n, False), dtype=float)
        self.pitch, self.speed, self.climb = (
            np.zeros(1),
            np.full(1, float(speed)),
            np.full(1, float(climb)),
        )
        J = const.size
        # the joints' (amplitude, phase, bias) of the row: one buffer, one (1 x J) view each
        self._coef = np.zeros((3, 1, J))
        self.amp, self.phase, self.bias = self._coef
        K = len(st.length)
        self.F, self.P, self.JP = np.zeros((1, K, 3)), np.zeros((1, K)), np.zeros((1, 2))
        self.out = np.zeros((1, 4, d + 1))
        # the positive shaft power (bird.power_cost): P+ into PP, and the gradient kernel's
        # power row (birdsim.physics.kernel_shaft)
        self.positive = bird.power_cost == "positive"
        self.PP = np.zeros(1)
        masses, dmat = shaft_arrays(model, bird, n) if self.positive else (NO_MASS, NO_MATRIX)
        geometry = (
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
        )
        omega, rho = float(bird.omega), float(bird.rho)
        self._means_args = (
            self.pitch,
            self.speed,
            self.climb,
            np.zeros((1, 3)),
            self.amp,
            self.phase,
            self.bias,
            const,
            phases,
            kernel._half(phases),
            omega,
            rho,
            *geometry,
            self.F,
            self.P,
            self.JP,
            self.PP,
            masses,
            dmat,
            self.positive,
        )
        self._grad_args = (
            self.pitch,
            self.speed,
            self.climb,
            self.amp,
            self.phase,
            self.bias,
            const,
            damp,
            dphase,
            dbias,
            self.ip,
            phases,
            omega,
            rho,
            *geometry,
            self.out,
            masses,
            dmat,
            self.positive,
        )
        # body drag (aero.body_drag) as a function of pitch alone: level flight
        # D = (k sin(pitch), 0); climbing D = |sin(pitch - gamma)| (kx, kz)
        v, vc, area = float(speed), float(climb), bird.body_drag_area
        self.level = vc == 0.0
        if self.level:
            self.kx, self.kz, self.gamma = -0.5 * bird.rho * v * v * area, 0.0, 0.0
        else:
            vt = math.hypot(v, vc)
            half = 0.5 * bird.rho * vt * vt * area
            self.kx, self.kz, self.gamma = -half * v / vt, half * vc / vt, math.atan2(vc, v)

    @classmethod
    def create(
        cls, model: KinematicModel, bird: Bird, speed: float, climb: float, n: int
    ) -> PointForces | None:
        """A :class:`PointForces`, or None where the kernel cannot serve it (no JIT, a
        polar it does not know, induced velocity on, or joint motions not affine)."""
        if (
            not kernel.available()
            or not kernel.supported(bird)
            or bird.induced_velocity
            or not _affine(model, bird)
        ):
            return None
        pf = cls(model, bird, speed, climb, n)
        if not _COMPILED["ok"]:
            try:  # the first call compiles (or loads from the disk cache)
                pf.values(np.mean(model.bounds, axis=0))
                pf.gradients(np.mean(model.bounds, axis=0))
            except Exception as exc:  # noqa: BLE001 - a JIT failure must not stop a build
                kernel._disable(
                    f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"
                )
                return None
            _COMPILED["ok"] = True
        return pf

    def _load(self, x: np.ndarray) -> None:
        np.add(self.c0, self.D @ x, out=self._coef[:, 0])  # c0 + D x, 3 x J
        self.pitch[0] = x[self.ip]

    def _drag(self, pitch: float) -> tuple[float, float]:
        if self.level:
            return self.kx * math.sin(pitch), 0.0
        s = abs(math.sin(pitch - self.gamma))
        return self.kx * s, self.kz * s

    def values(self, x: np.ndarray) -> tuple[float, float, float]:
        """Mean (Fx, Fz, P) of the row ``x`` (d,), columns in ``model.param_names`` order
        (P the positive shaft power for a bird with ``power_cost = "positive"``)."""
        self._load(x)
        kernel._means_kernel(0, 1, *self._means_args)
        dx, dz = self._drag(float(x[self.ip]))
        panels = self.F[0].tolist()  # panel sums in the batched path's order
        return (
            sum([f[0] for f in panels]) + dx,
            sum([f[2] for f in panels]) + dz,
            float(self.PP[0]) if self.positive else sum(self.P[0].tolist()),
        )

    def gradients(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(r, J)``: (Fx, Fz, P) of the row ``x`` (3,) and their gradients (3 x d)."""
        self._load(x)
        _grad_kernel(0, 1, *self._grad_args)
        o = self.out[0]
        vals = o[_ROWS, 0]  # fancy indexing: copies
        jac = o[_ROWS, 1:]
        pitch = float(x[self.ip])
        dx, dz = self._drag(pitch)
        vals[0] += dx
        vals[1] += dz
        if self.level:
            jac[0, self.ip] += self.kx * math.cos(pitch)
        else:
            a = pitch - self.gamma
            ds = math.copysign(1.0, math.sin(a)) * math.cos(a) if math.sin(a) != 0.0 else 0.0
            jac[0, self.ip] += self.kx * ds
            jac[1, self.ip] += self.kz * ds
        return vals, jac
