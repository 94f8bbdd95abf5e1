"""The bird for the eye: visual-only geometry generated from the :class:`Bird`.

Every geom here has ``contype = conaffinity = 0``, ``mass = 0`` and group
:data:`VISUAL_GROUP` (2); the bodies keep their explicit inertia, so the physics, the
inertia and every force figure are exactly those of the physical model (group 1: the
aerodynamic panels as boxes, the collision body; the renderer hides group 1).

Wings: over each aerodynamic panel (the arm and the hand body of each wing) a bird's
planform of the SAME span and area as the panel, so what the viewer sees is where the
forces act.  The arm carries coverts (with dark bars where the plumage has them) and
secondaries along the trailing edge, ending in rounded tips; the hand tapers, its
leading edge sweeps back, its tip is rounded and its primaries fan from the wrist to
the tip, the outer ones slotted.  Each piece is a flat polygon in the panel's plane
(``u`` outward along the span, ``x`` forward along the chord, x = 0 the twist axis at
half chord); the polygons never overlap, so the planform area is their summed
(shoelace) area, scaled chordwise to the panel's area exactly.  They are extruded into
thin meshes, one mesh per body and colour (few geoms: cheap to draw).

Body: torso and belly, a glossy neck, head, beak, eyes with rings and a fanned tail
(tail feathers with a terminal band).  Colours: :mod:`birdsim.mujoco.plumage`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from birdsim.mujoco.plumage import Plumage

#: Geom group of the visual bird (MuJoCo draws groups 0-2 by default).
VISUAL_GROUP = 2
#: Geom group of the physical bird (panels as boxes, collision body).
PHYSICAL_GROUP = 1
#: Thickness of a wing piece as a fraction of the panel's chord.
WING_THICKNESS = 0.012
#: Secondaries along an arm panel, primaries on a hand panel, tail feathers.
SECONDARIES = 9
PRIMARIES = 10
TAIL_FEATHERS = 10
#: Outer primaries whose tips are narrowed (the slotted wing tip).
SLOTTED = 4


@dataclass(frozen=True)
class Piece:
    """One flat piece of a planform: ``kind`` names its colour, ``polygon`` (P, 2) its
    outline (u outward span, x forward), counter-clockwise or not."""

    kind: str
    polygon: np.ndarray


def polygon_area(p: np.ndarray) -> float:
    """Area of a simple polygon (P, 2) (shoelace)."""
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def _resample(curve: np.ndarray, n: int) -> np.ndarray:
    """``n + 1`` points evenly spaced by arc length along a polyline (P, 2)."""
    seg = np.linalg.norm(np.diff(curve, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    t = np.linspace(0.0, s[-1], n + 1)
    return np.column_stack([np.interp(t, s, curve[:, 0]), np.interp(t, s, curve[:, 1])])


def _feather(inner_a, inner_b, outer_a, outer_b, narrow: float, bulge: float) -> np.ndarray:
    """Quad from an inner edge to an outer edge, the outer end narrowed about its middle
    by ``narrow`` (1 = not) and rounded by an arc bulging ``bulge`` (fraction of its
    width) beyond it."""
    mid = 0.5 * (outer_a + outer_b)
    oa, ob = mid + narrow * (outer_a - mid), mid + narrow * (outer_b - mid)
    edge = ob - oa
    width = float(np.linalg.norm(edge))
    # outward normal of the outer edge: away from the inner edge's middle
    nrm = np.array([edge[1], -edge[0]]) / max(width, 1e-300)
    if np.dot(nrm, mid - 0.5 * (inner_a + inner_b)) < 0:
        nrm = -nrm
    arc = [
        oa + (ob - oa) * (0.5 - 0.5 * math.cos(a)) + nrm * bulge * width * math.sin(a)
        for a in np.linspace(0, math.pi, 7)[1:-1]
    ]
    return np.array([inner_a, inner_b, ob, *arc[::-1], oa])


def _strips(upper: np.ndarray, lower: np.ndarray) -> list[np.ndarray]:
    """Quads between two curves sampled at the same stations (P, 2) each."""
    return [
        np.array([upper[i], upper[i + 1], lower[i + 1], lower[i]]) for i in range(len(upper) - 1)
    ]


def arm_planform(bars: int = 2) -> list[Piece]:
    """Unit arm planform (span 1, chord about 1): coverts in chordwise bands (``bars``
    dark ones) and secondaries with rounded tips."""
    u = np.linspace(0.0, 1.0, 13)
    le = 0.5 + 0.05 * np.sin(np.pi * u)
    cv = le - 0.52  # the coverts' trailing edge
    pieces: list[Piece] = []
    cuts = [0.0, 0.52, 0.64, 0.74, 0.86, 1.0] if bars else [0.0, 1.0]
    for k in range(len(cuts) - 1):
        top, bot = le - cuts[k] * (le - cv), le - cuts[k + 1] * (le - cv)
        kind = "bars" if (bars and k in (1, 3)) else "coverts"
        pieces += [
            Piece(kind, q) for q in _strips(np.column_stack([u, top]), np.column_stack([u, bot]))
        ]
    inner = np.column_stack([u, cv])
    outer = np.column_stack([u, np.full_like(u, -0.46)])
    ii, oo = _resample(inner, SECONDARIES), _resample(outer, SECONDARIES)
    for k in range(SECONDARIES):
        kind = "secondaries" if k % 2 == 0 else "secondaries_alt"
        pieces.append(Piece(kind, _feather(ii[k], ii[k + 1], oo[k], oo[k + 1], 0.96, 0.35)))
    return pieces


def hand_planform() -> list[Piece]:
    """Unit hand planform (span 1): swept-back leading edge, coverts, primaries fanning
    from the wrist round the rounded tip, the outer :data:`SLOTTED` narrowed."""
    tip_u = 0.88
    u = np.linspace(0.0, tip_u, 12)
    le = 0.55 - 0.30 * (u / tip_u) ** 2
    inner = np.column_stack([u, le - 0.42 * (1.0 - u / tip_u) ** 1.2])
    te_u = np.linspace(0.0, tip_u, 10)
    te = -0.58 + 0.30 * (te_u / tip_u) ** 1.6
    # rounded tip: half an ellipse from the trailing edge round u = 1 to the leading edge
    x0, x1 = te[-1], le[-1]
    a = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 9)[1:]
    tip = np.column_stack(
        [tip_u + (1.0 - tip_u) * np.cos(a), 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * np.sin(a)]
    )
    outer = np.vstack([np.column_stack([te_u, te]), tip])
    pieces = [Piece("coverts", q) for q in _strips(np.column_stack([u, le]), inner)]
    ii, oo = _resample(inner, PRIMARIES), _resample(outer, PRIMARIES)
    for k in range(PRIMARIES):
        slotted = k >= PRIMARIES - SLOTTED
        kind = "primaries" if k % 2 == 0 else "primaries_alt"
        pieces.append(
            Piece(
                kind,
                _feather(
                    ii[k],
                    ii[k + 1],
                    oo[k],
                    oo[k + 1],
                    0.55 if slotted else 0.97,
                    0.5 if slotted else 0.3,
                ),
            )
        )
    return pieces


def panel_planform(kind: str, span: float, chord: float, bars: int = 2) -> list[Piece]:
    """The pieces dressing one panel of ``span`` x ``chord`` (bird length units):
    ``kind`` "arm" or "hand"; their summed area is exactly ``span * chord``."""
    pieces = arm_planform(bars) if kind == "arm" else hand_planform()
    u_max = max(float(p.polygon[:, 0].max()) for p in pieces)  # a rounded tip may reach past 1
    area = sum(polygon_area(p.polygon) for p in pieces)
    scale = np.array([span / u_max, chord * u_max / area])  # span exact, then area span * chord
    return [Piece(p.kind, p.polygon * scale) for p in pieces]


def extrude(
    polygons: list[np.ndarray], sign: float, thickness: float, z: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """A mesh (vertices (V, 3), faces (F, 3)) of flat polygons (u, x) in a body frame
    whose span runs along ``sign`` * y: each polygon a prism of ``thickness`` about
    ``z``, triangulated as a fan about its centroid (pieces are star-shaped)."""
    verts, faces = [], []
    for poly in polygons:
        xy = np.column_stack([poly[:, 1], sign * poly[:, 0]])
        signed = 0.5 * float(
            np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) - np.dot(xy[:, 1], np.roll(xy[:, 0], -1))
        )
        if signed < 0:
            xy = xy[::-1]
        n = len(xy)
        c = xy.mean(axis=0)
        base = len(verts)
        for zz in (z - thickness / 2, z + thickness / 2):
            verts.append([c[0], c[1], zz])
            verts += [[p[0], p[1], zz] for p in xy]
        bot, top = base, base + n + 1
        for i in range(n):
            j = (i + 1) % n
            faces.append([top, top + 1 + i, top + 1 + j])  # top, normal +z
            faces.append([bot, bot + 1 + j, bot + 1 + i])  # bottom, normal -z
            faces.append([bot + 1 + i, bot + 1 + j, top + 1 + j])  # side walls
            faces.append([bot + 1 + i, top + 1 + j, top + 1 + i])
    return np.asarray(verts, dtype=float), np.asarray(faces, dtype=int)


def _shade(rgba, factor: float) -> list[float]:
    return [min(1.0, c * factor) for c in rgba[:3]] + [rgba[3]]


def add_materials(spec: mujoco.MjSpec, plumage: Plumage) -> None:
    """One material per plumage part, named ``plumage_<part>`` (matte; the neck glossy)."""
    parts = {
        "body": plumage.body,
        "belly": plumage.belly,
        "head": plumage.head,
        "neck": plumage.neck,
        "beak": plumage.beak,
        "eye": plumage.eye,
        "eye_ring": plumage.eye_ring,
        "coverts": plumage.coverts,
        "bars": plumage.bars,
        "secondaries": plumage.secondaries,
        "secondaries_alt": _shade(plumage.secondaries, 0.88),
        "primaries": plumage.primaries,
        "primaries_alt": _shade(plumage.primaries, 0.82),
        "tail": plumage.tail,
        "tail_band": plumage.tail_band,
        "feet": plumage.feet,
    }
    for part, rgba in parts.items():
        glossy = part in ("neck", "eye", "beak")
        spec.add_material(
            name=f"plumage_{part}",
            rgba=list(rgba),
            specular=plumage.neck_specular if part == "neck" else (0.6 if glossy else 0.12),
            shininess=plumage.neck_shininess if part == "neck" else (0.6 if glossy else 0.15),
        )


def add_visual_default(spec: mujoco.MjSpec) -> None:
    """Default class ``visual``: no contacts, no mass, group :data:`VISUAL_GROUP`."""
    vis = spec.add_default("visual", spec.default)
    vis.geom.contype = 0
    vis.geom.conaffinity = 0
    vis.geom.group = VISUAL_GROUP
    vis.geom.mass = 0.0
    vis.geom.density = 0.0


def add_panel_dress(
    spec: mujoco.MjSpec,
    body,
    prefix: str,
    kind: str,
    span: float,
    chord: float,
    sign: float,
    bars: int,
    fan: bool = False,
) -> None:
    """Meshes ``<prefix>_<colour>`` dressing one panel (span along ``sign`` * y of
    ``body``); nothing for a panel of zero span.  ``fan`` (m5's hand): each primary is
    its own geom ``<prefix>_primary_<k>`` (inner to outer), so that it can turn
    (:mod:`birdsim.mujoco.fan`); the meshes are the same pieces."""
    if span <= 1e-9 * max(chord, 1e-300):
        return
    pieces = panel_planform(kind, span, chord, bars)
    vis = spec.find_default("visual")
    primaries = [p for p in pieces if p.kind.startswith("primaries")]
    groups = []  # (geom and mesh name, colour, polygons)
    for colour in dict.fromkeys(p.kind for p in pieces):
        if fan and colour.startswith("primaries"):
            groups += [
                (f"{prefix}_primary_{k}", colour, [p.polygon])
                for k, p in enumerate(primaries)
                if p.kind == colour
            ]
        else:
            groups.append(
                (f"{prefix}_{colour}", colour, [p.polygon for p in pieces if p.kind == colour])
            )
    for name, colour, polys in groups:
        z = (
            0.25 * WING_THICKNESS * chord if colour in ("coverts", "bars") else 0.0
        )  # coverts on top
        v, f = extrude(polys, sign, WING_THICKNESS * chord, z)
        mesh = spec.add_mesh(name=name, uservert=v.ravel().tolist(), userface=f.ravel().tolist())
        mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
        body.add_geom(
            name=name,
            default=vis,
            type=mujoco.mjtGeom.mjGEOM_MESH,
            meshname=mesh.name,
            material=f"plumage_{colour}",
        )


def tail_fan(s: float) -> dict[str, list[np.ndarray]]:
    """Tail feathers (torso frame x, y; semispan ``s``): a fan of wedges from a hub
    behind the body, each with its dark terminal band."""
    hub = np.array([-0.42 * s, 0.0])
    length, half_angle = 0.42 * s, math.radians(24.0)
    angles = np.linspace(-half_angle, half_angle, TAIL_FEATHERS + 1)
    out: dict[str, list[np.ndarray]] = {"tail": [], "tail_band": []}
    for a0, a1 in zip(angles[:-1], angles[1:]):
        d0, d1 = np.array([-math.cos(a0), math.sin(a0)]), np.array([-math.cos(a1), math.sin(a1)])
        r_in, r_band = 0.05 * s, 0.8 * length
        out["tail"].append(
            np.array([hub + r_in * d0, hub + r_band * d0, hub + r_band * d1, hub + r_in * d1])
        )
        dm = (d0 + d1) / np.linalg.norm(d0 + d1)
        out["tail_band"].append(
            np.array(
                [
                    hub + r_band * d0,
                    hub + length * d0,
                    hub + 1.04 * length * dm,
                    hub + length * d1,
                    hub + r_band * d1,
                ]
            )
        )
    return out


def add_body_dress(spec: mujoco.MjSpec, torso, s: float) -> None:
    """Torso, belly, neck, head, beak, eyes and tail of the visual bird (semispan ``s``)."""
    vis = spec.find_default("visual")
    E, S, M = (
        mujoco.mjtGeom.mjGEOM_ELLIPSOID,
        mujoco.mjtGeom.mjGEOM_SPHERE,
        mujoco.mjtGeom.mjGEOM_MESH,
    )

    def geom(name, gtype, size, pos, material, quat=(1.0, 0.0, 0.0, 0.0)):
        torso.add_geom(
            name=name,
            default=vis,
            type=gtype,
            size=list(size),
            pos=list(np.asarray(pos) * s),
            quat=list(quat),
            material=f"plumage_{material}",
        )

    geom("vis_torso", E, np.array([0.50, 0.15, 0.14]) * s, [0.0, 0.0, 0.0], "body")
    geom("vis_belly", E, np.array([0.40, 0.13, 0.10]) * s, [0.04, 0.0, -0.055], "belly")
    tilt = math.radians(-30.0)  # neck leans forward-up
    geom(
        "vis_neck",
        E,
        np.array([0.17, 0.105, 0.11]) * s,
        [0.42, 0.0, 0.05],
        "neck",
        (math.cos(tilt / 2), 0.0, math.sin(tilt / 2), 0.0),
    )
    geom("vis_head", S, [0.105 * s, 0, 0], [0.60, 0.0, 0.12], "head")
    droop = math.radians(12.0)
    geom(
        "vis_beak",
        E,
        np.array([0.085, 0.028, 0.024]) * s,
        [0.72, 0.0, 0.10],
        "beak",
        (math.cos(droop / 2), 0.0, math.sin(droop / 2), 0.0),
    )
    for side, y in (("l", 1.0), ("r", -1.0)):
        geom(f"vis_{side}_eye_ring", S, [0.030 * s, 0, 0], [0.645, y * 0.075, 0.145], "eye_ring")
        geom(f"vis_{side}_eye", S, [0.022 * s, 0, 0], [0.652, y * 0.085, 0.147], "eye")
    for colour, polys in tail_fan(s).items():
        v, f = extrude(
            [np.column_stack([q[:, 1], q[:, 0]]) for q in polys], 1.0, 0.012 * s, 0.03 * s
        )  # (u, x) = (y, x)
        mesh = spec.add_mesh(
            name=f"vis_{colour}", uservert=v.ravel().tolist(), userface=f.ravel().tolist()
        )
        mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
        torso.add_geom(
            name=f"vis_{colour}",
            default=vis,
            type=M,
            meshname=mesh.name,
            material=f"plumage_{colour}",
        )


__all__ = [
    "PHYSICAL_GROUP",
    "Piece",
    "VISUAL_GROUP",
    "add_body_dress",
    "add_materials",
    "add_panel_dress",
    "add_visual_default",
    "arm_planform",
    "extrude",
    "hand_planform",
    "panel_planform",
    "polygon_area",
    "tail_fan",
]
