"""Issue 22's pigeon side gust: the sideslip's share of the roll moment the held-body model
misses (docs/free-body.md, "The pigeon's side gust and the sideslip").

    python scripts/side_gust_study.py [--bird FILE] [--beats 10]

Prints (reduced units: moments in weight x semispan, seed body axes about the torso):

1. at the cruise start, the held body's wingbeat-mean roll / pitch / yaw moment against
   the sideslip (the air turned in the body's x-y plane, ``bank.sideslip_of``'s sign),
   every input at zero; the lateral Jacobian rows at +-10 and +-20 degrees of sideslip;
   the per-phase roll sensitivity dMx/dbeta(t) (64 phases; its mean is the held
   derivative);
2. the cruise's 30 % side gust (+y, wingbeat 3, m3) per wingbeat 4..: the flown mean
   moment; the same samples re-posed with the sideslip removed (the air's body-y
   component turned into x, |v| and the body-z component kept): the sideslip's share;
   its prediction ``dMx/dbeta(inputs, beta) beta_mean + mean_t dMx/dbeta(t) (beta(t) -
   beta_mean)`` (the held body at the wingbeat's mean inputs, wingbeat, pitch and
   airspeed); the held body at the wingbeat's mean air (angle of attack, sideslip,
   speed), rates, wingbeat and inputs; and that held body beating the flown wings
   (the logged wing joints per sample), i.e. the inputs' timing within the wingbeat.
"""

from __future__ import annotations

import argparse
import math

import mujoco
import numpy as np

from birdsim.commands.fly import load_table_for
from birdsim.flight.attitude_jacobians import INPUTS, SEED_AXES, _hold, held_prescription
from birdsim.flight.bank import sideslip_of
from birdsim.flight.freeflight import fly
from birdsim.flight.gust import parse_gust
from birdsim.flight.presets import DEMO_MODEL, PATH_PRESETS, demo_bird
from birdsim.flight.simulate import FreeBird, SimConfig
from birdsim.mujoco.sites import pitch_quat
from birdsim.mujoco.tail import TailControls
from birdsim.physics.bird import Bird

#: phases per wingbeat of the held measurements (the log's 64: one per sample)
PHASES = 64
#: sideslip step of the per-phase derivative (rad, central)
BETA_STEP = 0.02


def held_quat(alpha: float, beta: float) -> np.ndarray:
    """MuJoCo quaternion of a body held in air along world x at angle of attack ``alpha``
    (nose up) and sideslip ``beta`` (air from the right > 0): pitched, then turned about
    its own z axis."""
    q = np.zeros(4)
    yaw = np.array([math.cos(beta / 2), 0.0, 0.0, math.sin(beta / 2)])
    mujoco.mju_mulQuat(q, pitch_quat(alpha), yaw)
    return q


def phase_moments(fb, params, u, quat, speed, omega_seed=None, h=None) -> np.ndarray:
    """(PHASES, 3) moments of the held body (``quat``, air ``speed`` along world x, turning
    at ``omega_seed``) beating ``params`` with the inputs ``u`` in still air; the wings'
    angular momentum relative to the torso into ``h`` (PHASES, 3) where given."""
    pres, tail = held_prescription(fb, params, u, PHASES)
    m, d = fb.m, mujoco.MjData(fb.m)
    wind, saved = m.opt.wind.copy(), fb.cb.tail_controls
    m.opt.wind[:], fb.cb.tail_controls = 0.0, tail
    om = np.zeros(3) if omega_seed is None else np.asarray(omega_seed) * SEED_AXES
    out = np.zeros((PHASES, 3))
    try:
        for k in range(PHASES):
            _hold(m, d, pres.qpos[k], pres.qvel[k], quat, speed, om)
            out[k] = d.qfrc_passive[3:6] * SEED_AXES
            if h is not None:
                vec, res = d.qvel.copy(), np.zeros(m.nv)
                vec[:6] = 0.0
                mujoco.mj_mulM(m, d, res, vec)
                h[k] = res[3:6] * SEED_AXES
    finally:
        m.opt.wind[:], fb.cb.tail_controls = wind, saved
    return out


def slip_sensitivity(fb, params, u, alpha, speed, beta=0.0) -> np.ndarray:
    """(PHASES, 3): d moment / d sideslip per phase (central step :data:`BETA_STEP`)."""
    lo = phase_moments(fb, params, u, held_quat(alpha, beta - BETA_STEP), speed)
    hi = phase_moments(fb, params, u, held_quat(alpha, beta + BETA_STEP), speed)
    return (hi - lo) / (2 * BETA_STEP)


def rocking_mean(fb, params, alpha, speed, beta, inertia) -> np.ndarray:
    """The wingbeat-mean moment (3,) of the body rocking within the wingbeat, every input
    at zero: the held mean plus ``mean_t (D(t) w(t) + K(t) th(t))``, ``th`` the periodic
    rocking of ``I th'' - D th' - K th = (M(t) - mean M) - h'(t)`` (``D``, ``K`` the
    per-phase derivatives with respect to the body rates and to small body-axis
    rotations, their means in the equation; solved per wingbeat harmonic), as
    ``attitude_jacobians.measured_with_rocking`` does for the rates alone."""
    zero, n, step = np.zeros(len(INPUTS)), PHASES, 0.01
    q0 = held_quat(alpha, beta)
    h = np.zeros((n, 3))
    mom = phase_moments(fb, params, zero, q0, speed, None, h)
    d_ph, k_ph = np.zeros((n, 3, 3)), np.zeros((n, 3, 3))
    for ax in range(3):
        d_ph[:, :, ax] = (
            phase_moments(fb, params, zero, q0, speed, step * np.eye(3)[ax]) - mom
        ) / step
        turn = np.array([math.cos(step / 2), 0.0, 0.0, 0.0])
        turn[1 + ax] = SEED_AXES[ax] * math.sin(step / 2)
        q = np.zeros(4)
        mujoco.mju_mulQuat(q, q0, turn)
        k_ph[:, :, ax] = (phase_moments(fb, params, zero, q, speed) - mom) / step
    w0 = 2.0 * math.pi / fb.red.period
    spec_m, spec_h = np.fft.rfft(mom, axis=0), np.fft.rfft(h, axis=0)
    spec_th = np.zeros_like(spec_m)
    for j in range(1, n // 2):
        jw = 1j * j * w0
        a = jw * jw * np.diag(inertia) - jw * d_ph.mean(0) - k_ph.mean(0)
        spec_th[j] = np.linalg.solve(a, spec_m[j] - jw * spec_h[j])
    th = np.fft.irfft(spec_th, n=n, axis=0)
    w = np.fft.irfft(spec_th * (1j * w0 * np.arange(len(spec_th)))[:, None], n=n, axis=0)
    rect = (np.einsum("kab,kb->a", d_ph, w) + np.einsum("kab,kb->a", k_ph, th)) / n
    return mom.mean(0) + rect


def start_table(fb, params, alpha, speed) -> None:
    """Part 1 (see the module)."""
    zero = np.zeros(len(INPUTS))
    print(f"held body at the cruise start: pitch {math.degrees(alpha):.2f} deg, speed {speed:.3f}")
    for deg in (-20, -10, -5, 0, 5, 10, 20):
        mm = phase_moments(fb, params, zero, held_quat(alpha, math.radians(deg)), speed).mean(0)
        print(f"  sideslip {deg:+4d} deg: roll {mm[0]:+.2e} pitch {mm[1]:+.5f} yaw {mm[2]:+.2e}")
    print("  lateral Jacobian rows per input", [i[0] for i in INPUTS])
    for deg in (-20, -10, 0, 10, 20):
        q = held_quat(alpha, math.radians(deg))
        base = phase_moments(fb, params, zero, q, speed).mean(0)
        cols = []
        for i in range(len(INPUTS)):
            u = zero.copy()
            u[i] = 0.05
            cols.append((phase_moments(fb, params, u, q, speed).mean(0) - base) / 0.05)
        jac = np.array(cols).T
        print(f"  sideslip {deg:+4d}: roll", jac[0].round(4), "yaw", jac[2].round(4))
    k = slip_sensitivity(fb, params, zero, alpha, speed)
    print(
        "  dMx/dbeta per phase (every 4th of 64):",
        k[::4, 0].round(3),
        "mean",
        f"{k[:, 0].mean():.1e}",
    )
    print("  dMz/dbeta per phase (every 4th of 64):", k[::4, 2].round(3))
    full = np.zeros((fb.m.nv, fb.m.nv))
    mujoco.mj_fwdPosition(fb.m, fb.d)
    mujoco.mj_fullM(fb.m, fb.d, full)
    inertia = np.diag(full[3:6, 3:6]).copy()
    db = 0.1
    hi = rocking_mean(fb, params, alpha, speed, db, inertia)
    lo = rocking_mean(fb, params, alpha, speed, -db, inertia)
    print(
        "  rocking body (inertia", inertia.round(3), "): dM/dbeta", ((hi - lo) / (2 * db)).round(4)
    )


def flown_table(bird, model: str, beats: float) -> None:
    """Part 2 (see the module)."""
    v = 0.5 * bird.semispan * 2.0 * math.pi / bird.period
    gust = parse_gust(f"3:1:0:{0.3 * v:g}:0")
    table = load_table_for(bird, model, None)
    cfg = SimConfig(attitude="free")
    r = fly(PATH_PRESETS["cruise"], table, bird, model, beats=beats, gusts=[gust], config=cfg)
    a, n = r.arrays, cfg.log_per_beat
    nb = len(a["t"]) // n
    params = np.stack([a[nm] for nm in r.param_names], 1)
    inputs = np.stack([a["u_" + i[0]] for i in INPUTS], 1)
    slip = sideslip_of(a["quat"], a["qvel"][:, :3])  # still air after the gust's wingbeat
    phase = np.round(a["t"] % (2 * math.pi) / (2 * math.pi) * PHASES).astype(int) % PHASES
    with FreeBird(model, bird, params[0], config=cfg) as fb:
        m, cb = fb.m, fb.cb
        d = mujoco.MjData(m)
        print("side gust 30 %, per wingbeat: mean sideslip (deg), roll moment: flown / share of")
        print(
            "  the sideslip (re-posed) / its prediction / held at the mean state / held + flown wings"
        )
        for b in range(4, nb):
            s = slice(b * n, (b + 1) * n)
            share = np.zeros(3)
            air = np.zeros(3)
            rows = range(s.start, s.stop)
            for k in rows:
                cb.tail_controls = TailControls(
                    a["tail_elevation"][k], a["tail_spread"][k], a["tail_roll"][k]
                )
                mat = np.zeros(9)
                mujoco.mju_quat2Mat(mat, a["quat"][k])
                rot = mat.reshape(3, 3)
                vb = rot.T @ a["qvel"][k, :3]
                air += vb / n
                for sign, body_v in ((1, vb), (-1, np.array([math.hypot(vb[0], vb[1]), 0, vb[2]]))):
                    d.qpos[:], d.qvel[:] = a["qpos"][k], a["qvel"][k]
                    d.qvel[:3] = rot @ body_v
                    mujoco.mj_fwdPosition(m, d)
                    mujoco.mj_fwdVelocity(m, d)
                    share += sign * d.qfrc_passive[3:6] * SEED_AXES / n
            speed = float(np.linalg.norm(air))
            alpha = math.atan2(-air[2], math.hypot(air[0], air[1]))
            beta = math.atan2(-air[1], air[0])
            p_mean, u_mean = params[s].mean(0), inputs[s].mean(0)
            kb = slip_sensitivity(fb, p_mean, u_mean, alpha, speed, beta)
            swing = slip[s] - slip[s].mean()
            pred = kb[:, 0].mean() * beta + float((kb[phase[s], 0] * swing).mean())
            omega = a["omega_body"][s].mean(0)
            q0 = held_quat(alpha, beta)
            held = phase_moments(fb, p_mean, u_mean, q0, speed, omega).mean(0)
            wings = 0.0
            for k in rows:  # the held body beating the logged wings
                cb.tail_controls = TailControls(
                    a["tail_elevation"][k], a["tail_spread"][k], a["tail_roll"][k]
                )
                d.qpos[:], d.qvel[:] = a["qpos"][k], a["qvel"][k]
                d.qpos[:3], d.qpos[3:7] = (0.0, 0.0, 6.0), q0
                d.qvel[:3], d.qvel[3:6] = (speed, 0.0, 0.0), omega * SEED_AXES
                mujoco.mj_fwdPosition(m, d)
                mujoco.mj_fwdVelocity(m, d)
                wings += d.qfrc_passive[3] * SEED_AXES[0] / n
            flown = a["moment_aero"][s].mean(0)[0]
            print(
                f"  {b:2d} {math.degrees(slip[s].mean()):+6.1f} (swing {math.degrees(np.ptp(slip[s])):4.1f})"
                f"  {flown:+.4f}  {share[0]:+.4f}  {pred:+.4f}  {held[0]:+.4f}  {wings:+.4f}"
            )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--bird", default=None)
    ap.add_argument("--model", default=DEMO_MODEL)
    ap.add_argument("--beats", type=float, default=10.0)
    args = ap.parse_args()
    bird = Bird.from_toml(args.bird) if args.bird else demo_bird()
    table = load_table_for(bird, args.model, None)
    cfg = SimConfig(attitude="free")
    r = fly(PATH_PRESETS["cruise"], table, bird, args.model, beats=1.0, config=cfg)
    a = r.arrays
    p0 = np.array([a[nm][0] for nm in r.param_names])
    with FreeBird(args.model, bird, p0, config=cfg) as fb:
        start_table(fb, p0, float(a["pitch_command"][0]), float(np.linalg.norm(a["qvel"][0, :3])))
    flown_table(bird, args.model, args.beats)


if __name__ == "__main__":
    main()
