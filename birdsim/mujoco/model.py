"""The articulated bird in MuJoCo, built from the :class:`~birdsim.physics.bird.Bird` with MjSpec.

One source of truth: spans, chords and control points come from ``bird.panels(model)``
and ``bird.cp_span_fraction``; ``models/bird.xml`` and ``models/scene.xml`` are written
by :func:`write_mjcf` (``python -m birdsim.mujoco.model models``) and a test checks that
they equal what this module builds.

Frames (MuJoCo world: x forward, y LEFT, z UP; seed axes -> MuJoCo is C = diag(1,-1,-1)):

* ``torso`` on the free joint ``root``; its frame is the seed body frame seen through C
  (x nose, y left wing, z up).  Body pitch theta (nose up) is a rotation by theta about
  MuJoCo -y.  Centre of mass at the torso origin; the shoulders sit at the origin too,
  exactly where the core's wing chains start.
* per wing (prefix ``r_`` right wing along MuJoCo -y, ``l_`` its mirror image):
  body ``X_arm`` with joints ``X_heave`` (slide, base model only) then ``X_shoulder``
  (ball: the composition sweep/stroke -> flap -> twist); body ``X_hand`` at the arm
  span with hinges ``X_wrist_flap`` (arm x) and ``X_wrist_twist`` (hand y), used by m4.
* a seed hinge about axis ``a`` (active rotation by +q) is a MuJoCo rotation by +q about
  ``C a`` on the right wing and about ``-M C a`` on the left (M = diag(1,-1,1), the
  mirror; rotation axes are pseudovectors).  The heave slide is along ``C z`` = MuJoCo
  -z on both wings (positive = down, as the seed's z).
* CP sites: ``X_cp_wing`` (single-panel models base..m3: one panel of span semispan),
  ``X_cp_arm`` and ``X_cp_hand`` (m4).  A site's frame is the panel frame: seed panel
  components ``u`` are ``C u`` in the right site's frame; the left site's frame is the
  mirrored rotation, whose x and z axes are the mirror images of the right ones.
* ``torso_cp``: where body drag acts (the torso origin); ``tail_cp``: the tail's
  centre of pressure (:mod:`birdsim.mujoco.tail`; sites and areas: :mod:`birdsim.mujoco.sites`).

MuJoCo's fluid model is off (density = viscosity = 0); ``opt.wind`` carries the
freestream for the aero callback.  Gravity is MuJoCo's default (0, 0, -9.81): a user
sets ``m.opt.gravity`` to what the bird's units mean (the cross-check turns it off).
"""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np

from birdsim.errors import BirdsimError
from birdsim.mujoco.arena import add_arena as _add_arena
from birdsim.mujoco.arena import camera_quat as _camera_quat
from birdsim.mujoco.fold import add_elbow, add_hand_joints
from birdsim.mujoco.legs import add_legs
from birdsim.mujoco.perches import Scene
from birdsim.mujoco.plumage import plumage_for
from birdsim.mujoco.sites import (  # noqa: F401 (re-exported)
    SIDES,
    AeroSite,
    aero_sites,
    pitch_quat,
    span_sign,
)
from birdsim.mujoco.visual import add_body_dress, add_materials, add_panel_dress, add_visual_default
from birdsim.physics.bird import Bird
from birdsim.physics.kinematics import get_model

#: Simulation steps per wingbeat: ``opt.timestep = bird.period / STEPS_PER_WINGBEAT``.
STEPS_PER_WINGBEAT = 512
#: Each wing panel's mass as a fraction of the bird's mass ("small": the wings are
#: driven kinematically, their inertia only matters in free flight).
PANEL_MASS_FRACTION = 0.01
#: Panel thickness as a fraction of its chord (visual and inertia only).
PANEL_THICKNESS = 0.02
#: Half-span (fraction of the chord) of the geom drawn for a panel of zero span.
ZERO_SPAN_HALF = 1e-6
#: Height of the torso above the floor in the default keyframe, in semispans.
KEY_HEIGHT = 2.0
#: Time constant of the weld ``hold`` in timesteps (MuJoCo's stable minimum is 2).
HOLD_TIMECONST_STEPS = 2.0
#: Offscreen framebuffer (the renderer needs 1280 x 720).
OFFSCREEN = (1280, 720)

WING_JOINTS = ("heave", "shoulder", "wrist_flap", "wrist_twist")
#: Seed axes of the core's hinge joints (kinematics.JOINTS) -- repeated here only as
#: MuJoCo axes; tests compare them with the core's joint table.
SEED_AXIS = {
    "x": np.array([1.0, 0.0, 0.0]),
    "y": np.array([0.0, 1.0, 0.0]),
    "z": np.array([0.0, 0.0, 1.0]),
}
C = np.diag([1.0, -1.0, -1.0])
MIRROR = np.diag([1.0, -1.0, 1.0])


def hinge_axis(side: str, seed_axis: str) -> np.ndarray:
    """MuJoCo axis (parent-body frame) of a seed hinge about ``seed_axis`` on wing ``side``."""
    a = C @ SEED_AXIS[seed_axis]
    return a if side == "r" else -(MIRROR @ a)


def slide_axis(side: str, seed_axis: str) -> np.ndarray:
    """MuJoCo axis of a seed slide along ``seed_axis`` (a true vector: plain mirror)."""
    a = C @ SEED_AXIS[seed_axis]
    return a if side == "r" else MIRROR @ a


def _box_inertia(mass: float, size: np.ndarray) -> np.ndarray:
    """Diagonal inertia of a solid box with half-sizes ``size``."""
    a, b, c = 2.0 * np.asarray(size)
    return mass / 12.0 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])


def _add_defaults(spec: mujoco.MjSpec) -> None:
    bird = spec.add_default("bird", spec.default)
    # bird geoms collide with the floor and the perch, never with each other
    bird.geom.contype = 2
    bird.geom.conaffinity = 1
    bird.geom.group = 1
    bird.geom.rgba = [0.55, 0.45, 0.35, 1.0]
    panel = spec.add_default("panel", bird)
    panel.geom.type = mujoco.mjtGeom.mjGEOM_BOX
    panel.geom.rgba = [0.85, 0.8, 0.7, 1.0]
    panel.geom.mass = 0.0  # inertia is explicit on the body
    cp = spec.add_default("cp", bird)
    cp.site.type = mujoco.mjtGeom.mjGEOM_SPHERE
    cp.site.size = [0.03, 0.0, 0.0]
    cp.site.rgba = [0.9, 0.1, 0.1, 1.0]
    cp.site.group = 3
    arena = spec.add_default("arena", spec.default)
    arena.geom.contype = 1
    arena.geom.conaffinity = 2
    arena.geom.group = 0


#: Torso-relative positions of the tracking cameras (mode trackcom: they follow the
#: bird's centre of mass without turning with it).
CAMERAS = {
    "track": np.array([-3.0, -3.0, 1.5]),
    "side": np.array([0.0, -4.5, 0.0]),
    "top": np.array([0.0, 0.0, 5.0]),
}


def _add_bird(
    spec: mujoco.MjSpec, model_name: str, bird: Bird, body_pitch: float, visuals: bool = True
) -> None:
    km = get_model(model_name)
    plumage = plumage_for(bird.name)
    if visuals:
        add_visual_default(spec)
        add_materials(spec, plumage)
    panels = bird.panels(model_name)
    # geometry of the two MuJoCo panels: m4 uses the bird's arm and hand; the
    # single-panel models draw their one panel split at the same wrist (kept straight)
    hand_span = bird.semispan * bird.hand_span_fraction
    arm_span = bird.semispan - hand_span
    if km.name in ("m4", "m5"):
        arm_chord, hand_chord = panels[0].chord, panels[1].chord
    else:
        arm_chord = hand_chord = panels[0].chord
    wing_mass = PANEL_MASS_FRACTION * bird.mass

    torso = spec.worldbody.add_body(name="torso", childclass="bird")
    torso.pos = [0.0, 0.0, KEY_HEIGHT * bird.semispan]
    torso.quat = pitch_quat(body_pitch)
    torso.add_freejoint(name="root")
    s = bird.semispan
    # the dissertation leaves the body's shape open (sec. 3.2.1); a torso about as long as
    # the chord keeps the bird recognisable next to its square seed wings
    body_size = np.array([0.55, 0.13, 0.13]) * s
    torso.explicitinertial = True
    torso.mass = bird.mass
    torso.ipos = [0.0, 0.0, 0.0]
    # the bird file's principal moments (seed = MuJoCo axes: C is diagonal), else a box
    torso.inertia = (
        list(bird.body_inertia) if bird.body_inertia else _box_inertia(bird.mass, body_size)
    )
    torso.add_geom(
        name="torso_body", type=mujoco.mjtGeom.mjGEOM_ELLIPSOID, size=body_size, mass=0.0
    )
    torso.add_geom(
        name="head",
        type=mujoco.mjtGeom.mjGEOM_SPHERE,
        size=[0.11 * s, 0, 0],
        pos=[0.6 * s, 0, 0.08 * s],
        mass=0.0,
    )
    torso.add_geom(
        name="tail",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[0.22 * s, 0.14 * s, 0.008 * s],
        pos=[-0.7 * s, 0, 0.02 * s],
        mass=0.0,
    )
    torso.add_site(name="torso_cp", default=spec.find_default("cp"), pos=[0, 0, 0])
    torso.add_site(  # the tail's centre of pressure: two thirds along the fan
        name="tail_cp",
        default=spec.find_default("cp"),
        pos=[-(bird.tail_root + 2.0 / 3.0 * bird.tail_length), 0.0, 0.0],
    )
    if visuals:
        add_body_dress(spec, torso, s)
    for name, pos in CAMERAS.items():
        torso.add_camera(
            name=name,
            pos=pos * s,
            quat=_camera_quat(pos),
            mode=mujoco.mjtCamLight.mjCAMLIGHT_TRACKCOM,
        )

    panel_cls = spec.find_default("panel")
    cp_cls = spec.find_default("cp")

    def panel(body, name: str, span: float, chord: float, sign: float, kind: str) -> None:
        """Box geom of span x chord along the body's y axis, with its mass and inertia."""
        size = np.array([chord / 2, span / 2, PANEL_THICKNESS * chord / 2])
        body.explicitinertial = True
        body.mass = wing_mass
        body.ipos = [0.0, sign * span / 2, 0.0]
        body.inertia = _box_inertia(wing_mass, size)
        # MuJoCo refuses a box of zero size: a zero-span panel (hand_span_fraction 0 or 1,
        # which the Bird allows) keeps its named geom as an invisible sliver
        drawn = np.array([size[0], max(size[1], ZERO_SPAN_HALF * chord), size[2]])
        body.add_geom(name=name, default=panel_cls, size=drawn, pos=[0.0, sign * span / 2, 0.0])
        if visuals:  # the bird's planform over the panel: same span and area, no mass
            add_panel_dress(
                spec,
                body,
                f"vis_{name.removesuffix('_panel')}",
                kind,
                span,
                chord,
                sign,
                plumage.wing_bars,
                fan=km.name == "m5" and kind == "hand",  # m5's primaries fan (mujoco/fan.py)
            )

    for side in SIDES:
        sg = span_sign(side)
        arm = torso.add_body(name=f"{side}_arm")
        arm.add_joint(
            name=f"{side}_heave", type=mujoco.mjtJoint.mjJNT_SLIDE, axis=slide_axis(side, "z")
        )
        arm.add_joint(name=f"{side}_shoulder", type=mujoco.mjtJoint.mjJNT_BALL)
        if km.name == "m5":  # the elbow: the arm panel rides on the forearm (mujoco/fold.py)
            arm = add_elbow(arm, side, bird, arm_span, sg, hinge_axis, wing_mass)
        panel(arm, f"{side}_arm_panel", arm_span, arm_chord, sg, "arm")
        arm.add_site(
            name=f"{side}_cp_wing", default=cp_cls, pos=[0.0, sg * bird.cp_span_fraction * s, 0.0]
        )
        arm.add_site(
            name=f"{side}_cp_arm",
            default=cp_cls,
            pos=[0.0, sg * bird.cp_span_fraction * arm_span, 0.0],
        )
        hand = arm.add_body(name=f"{side}_hand", pos=[0.0, sg * arm_span, 0.0])
        add_hand_joints(hand, side, km.name, hinge_axis)  # m4's two hinges; m5 adds two
        panel(hand, f"{side}_hand_panel", hand_span, hand_chord, sg, "hand")
        hand.add_site(
            name=f"{side}_cp_hand",
            default=cp_cls,
            pos=[0.0, sg * bird.cp_span_fraction * hand_span, 0.0],
        )

    # hold the torso to the world where it was built (used by the cross-check)
    weld = spec.add_equality(
        name="hold", type=mujoco.mjtEq.mjEQ_WELD, objtype=mujoco.mjtObj.mjOBJ_BODY
    )
    weld.name1 = "torso"
    # anchor (in body2 = world coordinates) at the torso origin, so that the held force
    # has no lever arm; relpose "0 1 0 0 0 0 0" = MJCF's sentinel for "the pose at
    # qpos0" (the build pose); torque scale 1.  (MjSpec's default data in MuJoCo 4.0
    # puts (0, 1, 0) into the anchor, so set every entry.)
    weld.data = [*torso.pos, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0]
    weld.solref = [HOLD_TIMECONST_STEPS * bird.period / STEPS_PER_WINGBEAT, 1.0]
    weld.solimp = [0.99, 0.9999, 0.001, 0.5, 2.0]
    weld.active = False


def _add_options(spec: mujoco.MjSpec, bird: Bird) -> None:
    spec.compiler.degree = False  # radians
    spec.compiler.autolimits = True
    spec.option.timestep = bird.period / STEPS_PER_WINGBEAT
    spec.option.density = 0.0  # MuJoCo's own fluid model off: the callback is the aero
    spec.option.viscosity = 0.0
    spec.option.wind = [0.0, 0.0, 0.0]
    spec.visual.global_.offwidth, spec.visual.global_.offheight = OFFSCREEN


def _add_key(spec: mujoco.MjSpec, m: mujoco.MjModel) -> None:
    key = spec.add_key(name="rest")
    key.qpos = m.qpos0.copy()
    key.qvel = np.zeros(m.nv)


def build_spec(
    model_name: str = "m4",
    bird: Bird | None = None,
    *,
    scene: bool = True,
    body_pitch: float = 0.0,
    visuals: bool = True,
    legs: bool = False,
    perches: Scene | None = None,
) -> mujoco.MjSpec:
    """The MjSpec of the bird for kinematic ``model_name`` (base, m1..m4).

    ``scene`` adds the arena (floor, light, perch, overview camera).  ``body_pitch``
    (rad, nose up) is the torso's build pose: the weld ``hold`` keeps it there.
    Every model has the same joints (nq = 7 + 2 * 8, nv = 6 + 2 * 7); a kinematic model
    only moves the ones it uses (see :mod:`birdsim.mujoco.driver`).  ``visuals`` adds
    the bird for the eye (:mod:`birdsim.mujoco.visual`: massless, contact-free geoms
    in group 2; the dynamics are identical without them).  ``legs``: legs and feet;
    ``perches``: the scene (:mod:`birdsim.mujoco.perches`; default the presets' perch).
    """
    bird = bird or Bird()
    spec = mujoco.MjSpec()
    spec.modelname = f"birdsim_{get_model(model_name).name}"
    _add_options(spec, bird)
    _add_defaults(spec)
    _add_bird(spec, model_name, bird, body_pitch, visuals)
    if legs:  # after the wings: their DOF come last, the wings' addresses are unchanged
        add_legs(spec, spec.body("torso"), bird, visuals)
    if scene:
        _add_arena(spec, bird, perches)
    m = spec.compile()
    _add_key(spec, m)
    return spec


def build_model(
    model_name: str = "m4",
    bird: Bird | None = None,
    *,
    scene: bool = True,
    body_pitch: float = 0.0,
    visuals: bool = True,
    legs: bool = False,  # birdsim.mujoco.legs
    perches: Scene | None = None,  # birdsim.mujoco.perches
) -> mujoco.MjModel:
    """Compiled MjModel of the bird (see :func:`build_spec`).

    Names: bodies ``torso``, ``{r,l}_arm``, ``{r,l}_hand``, ``perch``; joints ``root``
    (free), ``{r,l}_heave`` (slide), ``{r,l}_shoulder`` (ball), ``{r,l}_wrist_flap``,
    ``{r,l}_wrist_twist``; CP sites ``{r,l}_cp_wing|arm|hand``, ``torso_cp``; cameras
    ``track``, ``side``, ``top`` (follow the torso) and ``overview``; keyframe ``rest``;
    weld ``hold`` (inactive).  Timestep ``bird.period / 512``; offscreen 1280 x 720.
    """
    if not isinstance(body_pitch, (int, float)) or not math.isfinite(body_pitch):
        raise BirdsimError(f"body_pitch={body_pitch!r} is invalid; allowed: a finite angle (rad)")
    opts = dict(scene=scene, body_pitch=body_pitch, visuals=visuals, legs=legs)
    return build_spec(model_name, bird, perches=perches, **opts).compile()


SCENE_INCLUDE = '  <include file="bird.xml"/>\n'


def mjcf_texts(bird: Bird | None = None, model_name: str = "m4") -> dict[str, str]:
    """``bird.xml`` (the bird alone) and ``scene.xml`` (arena including bird.xml) as text."""
    bird = bird or Bird()
    bird_xml = build_spec(model_name, bird, scene=False).to_xml()
    arena = mujoco.MjSpec()
    arena.modelname = "birdsim_scene"
    _add_defaults(arena)
    _add_arena(arena, bird)
    text = arena.to_xml()
    # the arena's defaults repeat the bird's; keep the scene to its own elements
    start = text.index("<default>")
    end = text.index("</default>", start) + len("</default>")
    # the outermost <default> block closes last: find the matching end
    depth, i = 0, start
    while True:
        o = text.find("<default", i)
        c = text.find("</default>", i)
        if o != -1 and o < c:
            depth += 1
            i = o + 1
        else:
            depth -= 1
            i = c + 1
            if depth == 0:
                end = c + len("</default>")
                break
    text = text[:start].rstrip() + "\n" + text[end:].lstrip("\n")
    head_end = text.index(">", text.index("<mujoco")) + 1
    scene_xml = text[:head_end] + "\n" + SCENE_INCLUDE + text[head_end:].lstrip("\n")
    return {"bird.xml": bird_xml, "scene.xml": scene_xml}


def write_mjcf(directory: str | Path, bird: Bird | None = None) -> list[Path]:
    """Write ``bird.xml`` and ``scene.xml`` (m4 layout, default bird unless given)."""
    from birdsim.io import write_atomic

    out = []
    for name, text in mjcf_texts(bird).items():
        path = Path(directory) / name
        write_atomic(path, text.encode())
        out.append(path)
    return out


if __name__ == "__main__":  # python -m birdsim.mujoco.model models
    import sys

    for p in write_mjcf(sys.argv[1] if len(sys.argv) > 1 else "models"):
        print(p)
