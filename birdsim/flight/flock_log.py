"""Reading a flock's flight log (``birdsim fly FLOCK --out``) for render, export and the
studio: the stacked log (every per-sample array with a leading bird axis, ``n_birds``)
and each bird's own log (:func:`birdsim.flight.flock_fly.bird_log`, with its ``bird_obj``)."""

from __future__ import annotations

import zipfile
from pathlib import Path
from typing import Any

import numpy as np

from birdsim.flight.flightlog import LOG_FORMAT, LOG_VERSION, REQUIRED, LogError
from birdsim.physics.bird import Bird


def is_flock_log(path: str | Path) -> bool:
    """Whether ``path`` is an .npz flight log of a flock (it has ``n_birds``)."""
    p = Path(path)
    if p.suffix.lower() != ".npz" or not p.is_file():
        return False
    try:
        with np.load(p, allow_pickle=False) as z:
            return "n_birds" in z.files
    except (OSError, ValueError, EOFError, zipfile.BadZipFile):
        return False


def load_flock_log(path: str | Path, arg: str = "LOG") -> tuple[dict[str, Any], list[dict]]:
    """The flock's log and each bird's own log (in bird order).

    Raises:
        LogError: one line: not a birdsim flight log, another version, not a flock's
            log, a bird's log incomplete or its bird unreadable (named with its index).
    """
    import tomllib

    from birdsim.flight.flock_fly import bird_log

    p = Path(path)
    try:
        with np.load(p, allow_pickle=False) as z:
            data = {k: z[k] for k in z.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:
        raise LogError(
            f"{arg} {str(p)!r} is not a readable .npz ({exc}); allowed: a flight log written by `birdsim fly --out`"
        ) from None
    if str(data.get("format", "")) != LOG_FORMAT or int(data.get("version", -1)) != LOG_VERSION:
        raise LogError(
            f"{arg} {str(p)!r} is not a birdsim flight log of version {LOG_VERSION}; allowed: a log written by `birdsim fly --out`"
        )
    if "n_birds" not in data:
        raise LogError(f"{arg} {str(p)!r} is a one-bird log; allowed: a flock's log")
    birds = []
    for i in range(int(data["n_birds"])):
        one = bird_log(data, i)
        missing = [k for k in REQUIRED if k not in one]
        if missing:
            raise LogError(f"{arg} {str(p)!r}: bird {i} lacks array {missing[0]!r}")
        try:
            one["bird_obj"] = Bird.from_dict(tomllib.loads(str(one["bird"])))
        except (ValueError, TypeError, tomllib.TOMLDecodeError) as exc:
            raise LogError(f"{arg} {str(p)!r}: bird {i}'s bird is unreadable: {exc}") from None
        birds.append(one)
    return data, birds


def per_bird_paths(out: Path, n: int) -> list[Path]:
    """One output file per bird beside ``out``: ``f.bvh`` -> ``f-bird00.bvh``, ..."""
    width = max(2, len(str(n - 1)))
    return [out.with_name(f"{out.stem}-bird{i:0{width}d}{out.suffix}") for i in range(n)]


__all__ = ["is_flock_log", "load_flock_log", "per_bird_paths"]
