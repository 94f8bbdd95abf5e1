"""Blade-element forces on the MuJoCo bird through MuJoCo's passive-force callback.

For every control-point site of the kinematic model (both wings) the callback reads the
site's velocity (``mj_objectVelocity``, world frame) and frame (``site_xmat``),
subtracts the wind (``opt.wind`` = the air's velocity in the world: the freestream),
rotates the velocity into panel axes (seed convention: panel x = site x, panel z = -site
z) and calls the core's element force, ``bird.polar.force_panel`` -- the one
implementation of the aerodynamics.  The panel force is rotated back and ADDED to
``qfrc_passive`` with ``mj_applyFT`` at the site (strips, when ``bird.strips > 1``, are
points along the site's span axis; their force and moment are applied at the site).
Body drag (``aero.body_drag_magnitude``: ``rho/2 Vt^2 |sin(theta - gamma)|``, with Vt the
torso's speed through the air and theta - gamma its angle of attack in its pitch plane,
the climb-aware reading of eq. 7 that ``evaluate_cycle(..., climb=)`` uses) acts on the
torso opposite its air-relative velocity, so a climbing or sinking free body meets the
same drag as the core's.

``mujoco.set_mjcb_passive`` is process-wide: install the callback with the context
manager :func:`aero_forces` AFTER compiling every model you need (compiling while it is
installed fails) and it is removed on exit, also when an exception is raised.  The
callback acts only on the MjModel it was made for and ignores any other.  Under RK4 it
runs four times per step.  Do not disable both spring and damper
(``mjDSBL_SPRING | mjDSBL_DAMPER``): MuJoCo then skips the passive stage and the callback.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.fold import fold_area_joints, fold_area_scale
from birdsim.mujoco.model import aero_sites, span_sign
from birdsim.mujoco.tail import TailControls, tail_force, tail_frame
from birdsim.physics.aero import body_drag_magnitude
from birdsim.physics.bird import Bird

_SITE = mujoco.mjtObj.mjOBJ_SITE


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a x b`` over the last axis (np.cross costs ~20 us on tiny arrays)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


class AeroCallback:
    """The passive-force callback for one compiled model and one kinematic model.

    Call it as ``cb(m, d)``; MuJoCo does so inside ``mj_passive`` once installed.
    ``enabled`` switches the forces off without uninstalling (e.g. an aero-off run).
    """

    def __init__(
        self,
        m: mujoco.MjModel,
        model_name: str,
        bird: Bird | None = None,
        *,
        body_drag: bool = True,
        tail: bool = False,
    ):
        self.bird = bird or Bird()
        self.model = m
        self.enabled = True
        self.body_drag = body_drag
        sites = aero_sites(model_name, self.bird)
        try:
            self.site_ids = np.array([m.site(s.site).id for s in sites])
            self.torso_site = m.site("torso_cp").id
        except KeyError as exc:
            raise BirdsimError(
                f"model lacks site {exc}; allowed: a model built by birdsim.mujoco.model"
            ) from None
        self.body_ids = m.site_bodyid[self.site_ids].copy()
        self.torso_body = int(m.site_bodyid[self.torso_site])
        # element offsets from the site along its local y axis, (K, S)
        self.offsets = np.array([[span_sign(s.side) * o for o in s.strip_offsets] for s in sites])
        self.areas = np.array([[w * s.chord for w in s.strip_widths] for s in sites])
        # m5: the hand's area follows the wrist flexion (physics.m5.area_factor)
        self.fold_qpos = fold_area_joints(m, model_name, sites)
        self._vel = np.zeros((len(sites), 6))
        # per-site arguments of the MuJoCo calls, made once (the callback runs every step)
        self._site_list = [int(i) for i in self.site_ids]
        self._body_list = [int(i) for i in self.body_ids]
        self._vel_rows = [self._vel[k] for k in range(len(sites))]
        self._wind = m.opt.wind  # a view of the model's wind (written in place by its users)
        self._zero3 = np.zeros(3)
        self._force = np.zeros(3)
        #: the per-element arithmetic on Python floats: a polar whose force_scalar is
        #: defined with the force_panel it uses (a subclass that overrides force_panel
        #: only gets the array path)
        cls = type(self.bird.polar)
        owner = next((c for c in cls.__mro__ if "force_scalar" in c.__dict__), None)
        self._scalar = owner is not None and cls.force_panel is owner.__dict__.get("force_panel")
        self._tvel = np.zeros(6)
        self.single = bool(np.all(self.offsets == 0.0))
        self._zero_torque = np.zeros((len(sites), 3))
        self.calls = 0
        #: the tail (birdsim.mujoco.tail) acts only when asked for (free flight): the
        #: cross-check compares the wings and the body with the core, which has no tail
        self.tail = bool(tail)
        self.tail_controls = TailControls()
        #: the tail's last force (MuJoCo body axes) and angle of attack (rad)
        self.tail_force_body = np.zeros(3)
        self.tail_alpha = 0.0
        if self.tail:
            try:
                self.tail_site = m.site("tail_cp").id
            except KeyError:
                raise BirdsimError(
                    "model lacks site 'tail_cp'; allowed: a model built by birdsim.mujoco.model"
                ) from None
            self._tailvel = np.zeros(6)
            self._tail_frame_for: TailControls | None = None
            self._tail_frame = np.eye(3)

    def __call__(self, m: mujoco.MjModel, d: mujoco.MjData) -> None:
        if not self.enabled or m._address != self.model._address:
            return
        self.calls += 1
        object_velocity = mujoco.mj_objectVelocity
        for sid, row in zip(self._site_list, self._vel_rows):
            object_velocity(m, d, _SITE, sid, row, 0)
        areas = self.areas
        if self.fold_qpos is not None:
            areas = self.areas * fold_area_scale(d.qpos, self.fold_qpos, self.bird)[:, None]
        if self.single and self._scalar:
            self._wings_scalar(m, d, areas)
        else:
            self._wings(m, d, areas)
        if self.body_drag:
            self._apply_body_drag(m, d)
        if self.tail:
            self._apply_tail(m, d)

    def _wings_scalar(self, m: mujoco.MjModel, d: mujoco.MjData, areas: np.ndarray) -> None:
        """The one-element-per-panel wings on Python floats: the numpy path's operations
        in its order (``xmat^T v`` summed as numpy's small stacked matmul sums it), so
        the same forces (``tests/test_step_kernel.py``), at a third of the cost."""
        force_scalar, rho = self.bird.polar.force_scalar, self.bird.rho
        w0, w1, w2 = self._wind.tolist()
        xl = d.site_xmat[self.site_ids].tolist()
        pos = d.site_xpos[self.site_ids]
        apply_ft, passive, buf, zero = mujoco.mj_applyFT, d.qfrc_passive, self._force, self._zero3
        for k, (v, x, area) in enumerate(zip(self._vel.tolist(), xl, areas[:, 0].tolist())):
            l0, l1, l2 = v[3] - w0, v[4] - w1, v[5] - w2
            # seed panel axes = C (site axes): vx = local x, vz = -local z
            vx = l0 * x[0] + l1 * x[3] + l2 * x[6]
            vz = -(l0 * x[2] + l1 * x[5] + l2 * x[8])
            fx, fz = force_scalar(vx, vz, area, rho)
            buf[0] = fx * x[0] - fz * x[2]
            buf[1] = fx * x[3] - fz * x[5]
            buf[2] = fx * x[6] - fz * x[8]
            apply_ft(m, d, buf, zero, pos[k], self._body_list[k], passive)

    def _wings(self, m: mujoco.MjModel, d: mujoco.MjData, areas: np.ndarray) -> None:
        polar, rho = self.bird.polar, self.bird.rho
        xmat = d.site_xmat[self.site_ids].reshape(-1, 3, 3)  # columns: site axes in world
        lin = self._vel[:, 3:] - self._wind
        if self.single:  # one element per panel, at the site
            local = (lin[:, None, :] @ xmat)[:, 0, :]  # (K, 3) = xmat^T v
            # seed panel axes = C (site axes): vx = local x, vz = -local z
            fx, fz = polar.force_panel(local[:, 0], -local[:, 2], areas[:, 0], rho)
            force = fx[:, None] * xmat[:, :, 0] - fz[:, None] * xmat[:, :, 2]
            torque = self._zero_torque
        else:
            ang = self._vel[:, :3]
            r = xmat[:, None, :, 1] * self.offsets[:, :, None]  # (K, S, 3) site -> element
            v = lin[:, None, :] + _cross(ang[:, None, :], r)  # element velocity rel. to air
            local = np.einsum("kji,ksj->ksi", xmat, v)
            fx, fz = polar.force_panel(local[..., 0], -local[..., 2], areas, rho)
            f = fx[..., None] * xmat[:, None, :, 0] - fz[..., None] * xmat[:, None, :, 2]
            force = f.sum(axis=1)
            torque = _cross(r, f).sum(axis=1)
        pos = d.site_xpos[self.site_ids]
        apply_ft, passive = mujoco.mj_applyFT, d.qfrc_passive
        for k, body in enumerate(self._body_list):
            apply_ft(m, d, force[k], torque[k], pos[k], body, passive)

    def _apply_tail(self, m: mujoco.MjModel, d: mujoco.MjData) -> None:
        mujoco.mj_objectVelocity(m, d, _SITE, self.tail_site, self._tailvel, 1)
        xmat = d.site_xmat[self.tail_site].reshape(3, 3)  # the torso's axes
        # the velocity in the local frame (flg_local=1): v - xmat^T wind, summed as
        # numpy's matmul of a transposed matrix sums it
        x, (w0, w1, w2), v = xmat.tolist(), self._wind.tolist(), self._tailvel.tolist()
        vel_body = [v[3 + i] - (x[0][i] * w0 + x[1][i] * w1 + x[2][i] * w2) for i in range(3)]
        b = self.bird
        ctl = self.tail_controls
        if self._tail_frame_for is not ctl:  # the frame changes only with the controls
            self._tail_frame = tail_frame(ctl.clipped()).tolist()
            self._tail_frame_for = ctl
        f_body, self.tail_alpha = tail_force(
            vel_body,
            ctl,
            span=b.tail_span,
            length=b.tail_length,
            rho=b.rho,
            frame=self._tail_frame,
        )
        self.tail_force_body = f_body
        mujoco.mj_applyFT(
            m,
            d,
            xmat @ f_body,
            self._zero3,
            d.site_xpos[self.tail_site],
            self.torso_body,
            d.qfrc_passive,
        )

    def _apply_body_drag(self, m: mujoco.MjModel, d: mujoco.MjData) -> None:
        mujoco.mj_objectVelocity(m, d, _SITE, self.torso_site, self._tvel, 0)
        w0, w1, w2 = self._wind.tolist()
        v = self._tvel.tolist()
        u0, u1, u2 = v[3] - w0, v[4] - w1, v[5] - w2
        # |u| and xmat^T u summed as np.linalg.norm and numpy's matmul sum them
        speed = math.sqrt(u0 * u0 + u1 * u1 + u2 * u2)
        if speed == 0.0:
            return
        x = d.site_xmat[self.torso_site].tolist()
        loc0 = x[0] * u0 + x[3] * u1 + x[6] * u2
        loc2 = x[2] * u0 + x[5] * u1 + x[8] * u2
        attack = np.arctan2(-loc2, loc0)  # theta - gamma (seed body axes: z down)
        # |sin| keeps it a drag (never a thrust) when the body meets the air nose-down or backwards
        drag = body_drag_magnitude(speed, attack, self.bird.rho, self.bird.body_drag_area)
        mujoco.mj_applyFT(
            m,
            d,
            np.array([-drag * u0 / speed, -drag * u1 / speed, -drag * u2 / speed]),
            self._zero3,
            d.site_xpos[self.torso_site],
            self.torso_body,
            d.qfrc_passive,
        )


@contextmanager
def aero_forces(
    m: mujoco.MjModel, model_name: str, bird: Bird | None = None, *, body_drag: bool = True
) -> Iterator[AeroCallback]:
    """Install the aero callback for ``m`` while the ``with`` block runs.

    Refuses to replace a passive callback someone else installed; always restores
    ``None`` on exit (exceptions propagate).
    """
    cb = AeroCallback(m, model_name, bird, body_drag=body_drag)
    if mujoco.get_mjcb_passive() is not None:
        raise BirdsimError(
            "a MuJoCo passive callback is already installed; allowed: one aero_forces block at a time"
        )
    mujoco.set_mjcb_passive(cb)
    try:
        yield cb
    finally:
        mujoco.set_mjcb_passive(None)
