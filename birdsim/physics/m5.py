"""Model m5, the folding wing: m4's shoulder and wrist plus an elbow, a wrist that flexes
in the wing plane, and a hand that supinates in the upstroke (issue 24).

Per wing (docs/conventions.md, "Kinematic models"):

* arm: the shoulder of m3/m4 (``stroke``, ``flap``, ``twist``), then the elbow: an
  offset to the elbow (``Bird.elbow_span_fraction`` of the arm span), the ``elbow``
  hinge about the panel's z axis (in the wing plane; negative = the forearm's tip
  forward), and the offset back, so the arm's control point sits on the forearm, which
  carries the arm panel (one control point; the humerus part of the plate turns with
  the forearm, a simplification of a one-panel arm).
* hand: the same chain to the elbow, the forearm to the wrist, then ``wrist_sweep``
  about z (positive sweeps the hand's tip back), m4's ``wrist_flap`` (x) and
  ``wrist_twist`` (y), and ``supination`` (y, leading edge up).

The fold is one mode (one folding mode explains most of the wing's shape change,
Chang et al. 2020 Sci Robot 5:eaay1246): the elbow flexes by
``eps(t) = F (1 - cos(wt - phi_F)) / 2`` (0 extended, ``F`` = ``fold_amp`` at phase
``pi + phi_F``: mid-upstroke for phi_F = 0), the wrist by ``k eps`` with ``k`` =
``Bird.fold_coupling`` (elbow and wrist move together, Stowers, Matloff & Lentink 2017
J R Soc Interface 14:20170224; the value 1 is the planar "drawing parallels" reading, an
estimate: their six-bar fits are not read into a number).  The hand supinates by
``S (1 - cos(wt - phi_F)) / 2`` (``supination_amp``), in phase with the fold: the
tip-reversal upstroke.  Every joint is a sinusoid whose amplitude, phase and bias are
affine in the parameters (what the kernels' exact gradients need).

The hand's area follows the extension (primaries sliding over each other):
``area(t) = area_extended (1 - lambda sin^2(q_w / 2))`` with ``q_w`` the wrist flexion
and ``lambda`` = ``Bird.hand_fold_area_loss`` (:func:`area_factor`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from birdsim.physics.bird import Bird
from birdsim.physics.joints import JOINTS, ChainElement, Offset, ParamSpec, Sinusoid

PI = math.pi
NAME = "m5"

#: m5's new parameters (bounds in rad; the sources and reasoning: docs/conventions.md
#: and ``birdsim params m5``).
FOLD_PARAMS: tuple[ParamSpec, ...] = (
    ParamSpec(
        "fold_amp",
        "F",
        0.0,
        PI / 3,
        0.0,
        0.3,
        "elbow flexion at the fold's peak (the wrist flexes fold_coupling times as much); "
        "ESTIMATE of the range: 0-60 deg keeps the flexed wing well short of its folded "
        "resting pose (no measured in-flight pigeon elbow range read)",
    ),
    ParamSpec(
        "fold_phase",
        "phi_F",
        -PI / 2,
        PI / 2,
        0.0,
        0.0,
        "phase of the fold's peak after mid-upstroke; ESTIMATE of the range: +-1/4 "
        "wingbeat keeps the fold inside the upstroke, where pigeons flex (Tobalske & Dial "
        "1996 J Exp Biol 199:263: the wing is flexed in the upstroke)",
    ),
    ParamSpec(
        "supination_amp",
        "S",
        0.0,
        PI / 2,
        0.0,
        0.3,
        "hand supination (leading edge up) at the fold's peak: the tip-reversal upstroke "
        "(Crandell & Tobalske 2011 J Exp Biol 214:1867); ESTIMATE of the range: up to 90 "
        "deg, a hand flipped to vertical against the arm",
    ),
)

#: m5's stroke plane is bounded by the pigeon's range instead of m3's 0.35 rad.
STROKE_PLANE_UPPER = PI / 3
#: m5's shoulder flap is bounded as m1-m3's (pi/2), not m4's pi/4: with m4's bound the
#: pigeon cannot carry its weight below 6 m/s (docs/validation.md, "m5").
FLAP_UPPER = PI / 2

ARM_CHAIN: tuple[ChainElement, ...] = (
    JOINTS["stroke"],
    JOINTS["flap"],
    JOINTS["twist"],
    Offset(0.0, "elbow"),
    JOINTS["elbow"],
    Offset(0.0, "elbow_back"),
)
HAND_CHAIN: tuple[ChainElement, ...] = (
    JOINTS["stroke"],
    JOINTS["flap"],
    JOINTS["twist"],
    Offset(0.0, "elbow"),
    JOINTS["elbow"],
    Offset(0.0, "forearm"),
    JOINTS["wrist_sweep"],
    JOINTS["wrist_flap"],
    JOINTS["wrist_twist"],
    JOINTS["supination"],
)

#: Per panel (arm, hand): the joint whose angle sets the panel's area, or None.
AREA_FOLDS: tuple[str | None, ...] = (None, "wrist_sweep")


def offset_lengths(bird: Bird) -> dict[str, float]:
    """The length of every offset role for ``bird`` (the arm span split at the elbow)."""
    arm = bird.semispan * (1.0 - bird.hand_span_fraction)
    elbow = bird.elbow_span_fraction * arm
    return {"wrist": arm, "elbow": elbow, "elbow_back": -elbow, "forearm": arm - elbow}


def fold_motion(params: Mapping[str, np.ndarray], bird: Bird) -> dict[str, Sinusoid]:
    """The sinusoids of the elbow, the wrist flexion and the supination."""
    half_f = 0.5 * params["fold_amp"]
    phase = -params["fold_phase"] - PI / 2  # (1 - cos(wt - phi)) / 2 = (sin(wt + phase) + 1) / 2
    half_k = bird.fold_coupling * half_f
    half_s = 0.5 * params["supination_amp"]
    return {
        "elbow": Sinusoid(-half_f, phase, -half_f),
        "wrist_sweep": Sinusoid(half_k, phase, half_k),
        "supination": Sinusoid(half_s, phase, half_s),
    }


def area_factor(cos_q: np.ndarray | float, bird: Bird) -> np.ndarray | float:
    """The hand's area over its extended area at a wrist flexion with cosine ``cos_q``:
    ``1 - lambda (1 - cos q) / 2`` (1 extended, ``1 - lambda`` folded back on itself)."""
    return 1.0 - 0.5 * bird.hand_fold_area_loss * (1.0 - cos_q)


def fold_bird_error(bird: Bird) -> str | None:
    """Why ``bird`` cannot fly m5 (a one-line reason), or None."""
    if not 0.0 < bird.hand_span_fraction < 1.0:
        return (
            f"bird.hand_span_fraction={bird.hand_span_fraction!r} leaves no arm or no hand; "
            "allowed for model m5: a number in (0, 1)"
        )
    return None


#: Where each m5 bound comes from (``birdsim params m5``).  Measured pigeon ranges were
#: not read into numbers for any joint: every bound below is m4's (docs/design.md) or an
#: estimate with its reasoning.
BOUND_SOURCES: dict[str, str] = {
    "pitch": "m4's bound [0, pi/2] (design.md); not a pigeon range",
    "flap_amp": "ESTIMATE pi/2, m1-m3's bound (design.md; m4: pi/4): with pi/4 the pigeon "
    "cannot carry its weight below 6 m/s nor hover, and its m5 free flight saturates; pigeons' "
    "stroke amplitude is greatest in slow flight and take-off (Berg & Biewener 2010 J Exp Biol "
    "213:1651, Summary; their numbers were not read); trimmed at 4.46 m/s m5 uses 2 x 0.99-1.03 "
    "rad (docs/validation.md)",
    "twist_amp": "m4's bound (design.md)",
    "stroke_plane": "ESTIMATE pi/3 (m3/m4: 0.35 rad): m4's bound forced the body to 55-70 deg "
    "in slow flight to tilt the stroke plane (issue 24); Usherwood et al. 2005 (J Exp Biol "
    "208:355) give a stroke-plane inclination of 35 deg whose convention was not read",
    "wrist_amp": "m4's bound (design.md)",
    "wrist_bias": "m4's bound (design.md)",
    "wrist_lag": "m4's bound (design.md)",
    "fold_amp": "ESTIMATE, see the parameter's meaning",
    "fold_phase": "ESTIMATE, see the parameter's meaning",
    "supination_amp": "ESTIMATE, see the parameter's meaning",
}

#: The bird's skeleton constants of m5 and their status (``birdsim params m5``).
SKELETON_SOURCES: dict[str, str] = {
    "fold_coupling": "wrist flexion per radian of elbow flexion; 1 = the planar 'drawing "
    "parallels' coupling, an ESTIMATE (Stowers, Matloff & Lentink 2017 J R Soc Interface "
    "14:20170224 show elbow and wrist move together on 3-D paths; no slope read); allowed [0, 2]",
    "elbow_span_fraction": "the elbow's place along the arm, ESTIMATE 0.45 (humerus a little "
    "shorter than the forearm); allowed [0.05, 0.95]",
    "hand_fold_area_loss": "fraction of the hand's area lost folded back on itself, ESTIMATE 0.6 "
    "(primaries stacked); allowed [0, 1]",
}
