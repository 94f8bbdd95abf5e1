"""The world around the bird: floor, sky, sun, perch and the overview camera, added to an
MjSpec by :func:`add_arena` (``models/scene.xml`` is its output).

Textures and materials are for the eye only; the floor and the perch's post and bar
are the collision geometry (class ``arena``), the perch's foot, knot and twigs are
visual (no contacts, no mass).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from birdsim.mujoco.perches import BAR_HALF_LENGTH, DEFAULT_SCENE, POST_RADIUS, Perch, Scene
from birdsim.physics.bird import Bird


def camera_quat(position: np.ndarray) -> np.ndarray:
    """Quaternion of a camera at ``position`` (torso-relative) looking at the torso,
    horizon level."""
    z = position / np.linalg.norm(position)  # MuJoCo cameras look along -z
    x = np.cross([0.0, 0.0, 1.0], z)
    if np.linalg.norm(x) < 1e-9:  # straight above: image x = forward
        x = np.array([0.0, -1.0, 0.0]) if z[2] < 0 else np.array([1.0, 0.0, 0.0])
        x = np.array([1.0, 0.0, 0.0]) if z[2] > 0 else x
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.column_stack([x, y, z]).ravel())
    return quat


#: Side of one ground checker square, in semispans (so that speed reads off the ground).
GROUND_SPACING = 1.0


def add_arena(spec: mujoco.MjSpec, bird: Bird, scene: Scene | None = None) -> None:
    """Floor (checker of :data:`GROUND_SPACING` semispans), sky gradient, sun, the
    scene's perches (each a post and a branch with twigs; the first named ``perch``,
    ``perch_post``, ``perch_bar``, ``perch_top``, the k-th ``perchk``, ``perchk_post``
    ...), overview camera.  Textures and materials are for the eye only; the floor and
    perch geoms are the collision geometry."""
    s = bird.semispan
    arena = spec.find_default("arena")
    world = spec.worldbody
    tex = mujoco.mjtTexture
    spec.add_texture(
        name="sky",
        type=tex.mjTEXTURE_SKYBOX,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_GRADIENT,
        rgb1=[0.36, 0.56, 0.84],
        rgb2=[0.86, 0.91, 0.96],
        width=256,
        height=1536,
    )
    spec.add_texture(
        name="ground",
        type=tex.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        rgb1=[0.55, 0.66, 0.42],
        rgb2=[0.47, 0.59, 0.36],
        mark=mujoco.mjtMark.mjMARK_EDGE,
        markrgb=[0.40, 0.50, 0.30],
        width=256,
        height=256,
    )
    spec.add_texture(
        name="bark",
        type=tex.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_FLAT,
        rgb1=[1.0, 0.95, 0.9],
        rgb2=[1.0, 0.95, 0.9],
        mark=mujoco.mjtMark.mjMARK_RANDOM,
        markrgb=[0.6, 0.55, 0.5],
        random=0.3,
        width=64,
        height=64,
    )
    ground = spec.add_material(
        name="ground",
        texuniform=True,
        texrepeat=[1.0 / (2.0 * GROUND_SPACING * s)] * 2,
        specular=0.05,
        shininess=0.05,
    )
    ground.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "ground"
    bark = spec.add_material(name="bark", texrepeat=[2.0, 2.0], specular=0.05, shininess=0.05)
    bark.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "bark"
    spec.visual.headlight.ambient = [0.35, 0.35, 0.35]
    spec.visual.headlight.diffuse = [0.35, 0.35, 0.35]
    spec.visual.headlight.specular = [0.05, 0.05, 0.05]
    spec.visual.map.haze = 0.35
    world.add_light(
        name="sun",
        pos=[0, 0, 10 * s],
        dir=[0.3, 0.2, -1.0],
        type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
        diffuse=[0.65, 0.63, 0.58],
        specular=[0.2, 0.2, 0.2],
        castshadow=True,
    )
    world.add_geom(
        name="floor",
        default=arena,
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        size=[50 * s, 50 * s, 0.1],
        rgba=[1, 1, 1, 1],
        material="ground",
    )
    for k, p in enumerate((scene or DEFAULT_SCENE).perches, 1):
        _add_perch(world, s, p, "perch" if k == 1 else f"perch{k}")
    world.add_camera(
        name="overview", pos=[3 * s, -12 * s, 4 * s], quat=camera_quat(np.array([-3.0, -12.0, 2.0]))
    )


def _add_perch(world: mujoco.MjsBody, s: float, p: Perch, name: str) -> None:
    """One perch: a post and a bar (collision), a foot, a knot and twigs (the eye only)."""
    perch = world.add_body(name=name, pos=[p.x * s, p.y * s, 0.0], childclass="arena")
    perch.add_geom(
        name=f"{name}_post",
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[POST_RADIUS * s, 0.5 * p.height * s, 0],
        pos=[0, 0, 0.5 * p.height * s],
        rgba=[0.5, 0.38, 0.26, 1],
        material="bark",
    )
    perch.add_geom(
        name=f"{name}_bar",
        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
        size=[p.radius * s, BAR_HALF_LENGTH * s, 0],
        pos=[0, 0, p.height * s],
        quat=[math.sqrt(0.5), math.sqrt(0.5), 0, 0],
        rgba=[0.5, 0.38, 0.26, 1],
        material="bark",
    )
    # for the eye only: a flared foot, a knot and twigs off the branch (no contacts, no mass)
    decor = dict(
        contype=0, conaffinity=0, group=2, mass=0.0, material="bark", rgba=[0.5, 0.38, 0.26, 1]
    )
    perch.add_geom(
        name=f"{name}_foot",
        type=mujoco.mjtGeom.mjGEOM_ELLIPSOID,
        size=[0.11 * s, 0.11 * s, 0.08 * s],
        pos=[0, 0, 0],
        **decor,
    )
    perch.add_geom(
        name=f"{name}_knot",
        type=mujoco.mjtGeom.mjGEOM_SPHERE,
        size=[1.625 * p.radius * s, 0, 0],
        pos=[0, 0, p.height * s],
        **decor,
    )
    for k, (y, angle, length) in enumerate(
        ((0.45, 0.7, 0.28), (-0.35, 2.3, 0.22), (0.1, 1.2, 0.18))
    ):
        half = 0.5 * length * s
        d = np.array([math.cos(angle) * 0.4, 0.0, math.sin(angle)])
        d /= np.linalg.norm(d)
        perch.add_geom(
            name=f"{name}_twig{k}",
            type=mujoco.mjtGeom.mjGEOM_CAPSULE,
            size=[0.012 * s, 0, 0],
            fromto=[
                *(np.array([0.0, y * s, p.height * s])),
                *(np.array([0.0, y * s, p.height * s]) + 2 * half * d),
            ],
            **decor,
        )
    perch.add_site(name=f"{name}_top", pos=[0, 0, p.top * s], size=[0.02 * s, 0, 0], group=3)


__all__ = ["GROUND_SPACING", "add_arena", "camera_quat"]
