"""Saying so when a flight saturated: one line on stderr (how many wingbeats, when, what
was asked, where to see what the bird can reach), or an error with ``--strict``.

A saturated sample is one whose demand lay outside the table's reach (the log's
``saturated``); a flight that saturates is not the flight its path asked for.
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np

from birdsim.errors import BirdsimError

TWO_PI = 2.0 * math.pi


def saturation_note(log: dict[str, Any], *, bird_arg: str | None, model: str) -> str | None:
    """The line describing the log's saturated wingbeats, or None when there are none.

    Args:
        log: flight log arrays (``t``, ``omega``, ``saturated``, ``Fx_demand``, ``Fz_demand``).
        bird_arg: the ``--bird`` given (for the envelope command it suggests), or None.
        model: the kinematic model flown.
    """
    sat = np.asarray(log["saturated"], dtype=bool)
    if not sat.any():
        return None
    t_beats = np.asarray(log["t"], dtype=float) * float(log["omega"]) / TWO_PI
    beats = sorted(set(np.floor(t_beats[sat] + 1e-9).astype(int).tolist()))
    fx = np.asarray(log["Fx_demand"], dtype=float)[sat]
    fz = np.asarray(log["Fz_demand"], dtype=float)[sat]
    bird = f" --bird {bird_arg}" if bird_arg else ""
    return (
        f"saturated in {len(beats)} wingbeat(s), from wingbeat {t_beats[sat][0]:.1f} to "
        f"{t_beats[sat][-1]:.1f}: the path asked Fx {fx.min():+.3g}..{fx.max():+.3g}, "
        f"Fz {fz.min():+.3g}..{fz.max():+.3g} (table units), beyond the table's reach; "
        f"what the bird can reach: birdsim envelope{bird} --model {model}"
    )


def report_saturation(
    log: dict[str, Any], *, command: str, bird_arg: str | None, model: str, strict: bool
) -> None:
    """Print the saturation line on stderr (``birdsim COMMAND: warning: ...``), or raise
    it with ``strict``.

    Raises:
        BirdsimError: ``strict`` and the flight saturated (the CLI exits 2).
    """
    note = saturation_note(log, bird_arg=bird_arg, model=model)
    if note is None:
        return
    if strict:
        raise BirdsimError(f"--strict: {note}; allowed: a flight without saturated wingbeats")
    print(f"birdsim {command}: warning: {note}", file=sys.stderr)


__all__ = ["report_saturation", "saturation_note"]
