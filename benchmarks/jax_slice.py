"""The numba-vs-JAX measurement behind the kernel choice (docs/performance.md).

An m4 slice (seed polar, one control point per panel, level flight) written in
jax.numpy, jit-compiled, against the fused numba kernel and the numpy path on the same
parameter sets; also the forward-mode gradients (jax.jacfwd vs the kernel's dual numbers).
JAX is not a dependency: ``pip install jax`` first; without it this script says so.
"""

from __future__ import annotations

import sys
import time

import numpy as np

import birdsim
from birdsim.physics import kernel
from birdsim.physics.cycle import sample_phases


def _jax_m4(jnp, n: int):
    wt = jnp.linspace(0.0, 2 * jnp.pi, n, endpoint=False)

    def rot(axis, c, s, v):
        x, y, z = v
        if axis == "y":
            return (c * x - s * z, y, s * x + c * z)
        if axis == "x":
            return (x, c * y + s * z, -s * y + c * z)
        return (c * x + s * y, -s * x + c * y, z)

    def cross(axis, p):
        x, y, z = p
        return {"x": (0.0 * x, -z, y), "y": (z, 0.0 * x, -x), "z": (-y, x, 0.0 * x)}[axis]

    def wingbeat(x, speed):  # x: pitch, flap, twist, stroke, wrist_amp, wrist_bias, wrist_lag
        pitch, flap, twist, sp, wa, wb, wl = (x[i] for i in range(7))
        q = {
            "stroke": (sp + 0 * wt, 0 * wt),
            "flap": (flap * jnp.sin(wt), flap * jnp.cos(wt)),
            "twist": (twist * jnp.sin(wt - jnp.pi / 2), twist * jnp.cos(wt - jnp.pi / 2)),
            "wrist_flap": (wa * jnp.sin(wt - wl) + wb, wa * jnp.cos(wt - wl)),
            "wrist_twist": (
                0.25 * twist * jnp.sin(wt - jnp.pi / 2),
                0.25 * twist * jnp.cos(wt - jnp.pi / 2),
            ),
        }
        cs = {k: (jnp.cos(a), jnp.sin(a), r) for k, (a, r) in q.items()}
        axes = {"stroke": "y", "flap": "x", "twist": "y", "wrist_flap": "x", "wrist_twist": "y"}
        cp, spn = jnp.cos(pitch), jnp.sin(pitch)
        air = (cp * speed, 0.0 * wt, spn * speed)
        total = jnp.zeros(4)
        for chain, r, offset, area in (
            (("stroke", "flap", "twist"), 1 / 3, 0.0, 2 / 3),
            (("stroke", "flap", "twist", "|", "wrist_flap", "wrist_twist"), 1 / 6, 2 / 3, 1 / 3),
        ):
            p = (0.0 * wt, r + 0.0 * wt, 0.0 * wt)
            vel = (0.0 * wt,) * 3
            for name in reversed(chain):
                if name == "|":
                    p = (p[0], p[1] + offset, p[2])
                    continue
                c, s, rate = cs[name]
                p = rot(axes[name], c, -s, p)
                vel = rot(axes[name], c, -s, vel)
                vel = tuple(a + rate * b for a, b in zip(vel, cross(axes[name], p)))
            v = tuple(a + b for a, b in zip(air, vel))
            for name in chain:
                if name != "|":
                    c, s, _ = cs[name]
                    v = rot(axes[name], c, s, v)
            vx, vz = v[0], v[2]
            u2 = vx * vx + vz * vz
            inv_u = 0.5 * area / jnp.sqrt(u2)
            drag = 0.05 * u2 + vz * vz
            fx, fz = inv_u * vx * (4.0 * vz * vz - drag), -inv_u * vz * (4.0 * vx * vx + drag)
            f = (fx, 0.0 * wt, fz)
            for name in reversed(chain):
                if name != "|":
                    c, s, _ = cs[name]
                    f = rot(axes[name], c, -s, f)
            fe = (cp * f[0] + spn * f[2], f[1], -spn * f[0] + cp * f[2])
            pw = -(f[0] * vel[0] + f[1] * vel[1] + f[2] * vel[2])
            total = total + jnp.stack([fe[0].mean(), fe[1].mean(), fe[2].mean(), pw.mean()])
        return total

    return wingbeat


def main() -> int:
    try:
        import jax
        import jax.numpy as jnp
    except ImportError:
        print("JAX is not installed (pip install jax): nothing measured")
        return 0
    jax.config.update("jax_enable_x64", True)
    n, B = 64, 4096
    m = birdsim.get_model("m4")
    rng = np.random.default_rng(0)
    lo, hi = m.bounds
    X = lo + (hi - lo) * rng.uniform(0.05, 0.95, (B, 7))
    V = 0.2 + 0.8 * rng.random(B)
    wingbeat = _jax_m4(jnp, n)
    batched = jax.jit(jax.vmap(wingbeat))
    grad = jax.jit(jax.vmap(jax.jacfwd(wingbeat)))
    t = time.perf_counter()
    out = np.asarray(batched(X, V))
    t_compile = time.perf_counter() - t
    t = time.perf_counter()
    np.asarray(grad(X, V))
    t_compile_g = time.perf_counter() - t
    ref = birdsim.evaluate_cycle(
        "m4", {k: X[:, i] for i, k in enumerate(m.param_names)}, V, backend="numpy"
    )
    err = np.abs(out[:, 2] - np.asarray(ref.mean.Fz)).max()

    def rate(fn, reps=3):
        best = 0.0
        for _ in range(reps):
            t0 = time.perf_counter()
            fn()
            best = max(best, B / (time.perf_counter() - t0))
        return best

    flat = {k: X[:, i] for i, k in enumerate(m.param_names)}
    ph = sample_phases(n, False)
    rows = {
        "numpy (reference)": rate(
            lambda: birdsim.evaluate_cycle("m4", flat, V, backend="numpy").mean
        ),
        "numba kernel, means": rate(
            lambda: kernel.means(m, flat, V, np.zeros(B), np.zeros((B, 3)), birdsim.Bird(), ph)
        ),
        "jax jit(vmap), means": rate(lambda: np.asarray(batched(X, V))),
        "numba kernel, means + gradients": rate(
            lambda: kernel.means_and_gradients(m, flat, V, np.zeros(B), birdsim.Bird(), ph)
        ),
        "jax jit(vmap(jacfwd))": rate(lambda: np.asarray(grad(X, V))),
    }
    print(
        f"m4 slice, {B} wingbeats x {n} samples; JAX {jax.__version__}; |Fz jax - numpy| = {err:.1e}"
    )
    print(f"jax compile: means {t_compile:.1f} s, gradients {t_compile_g:.1f} s")
    for k, v in rows.items():
        print(f"{k:34s} {v:10.0f} wingbeats/s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
