"""Table builds on a Dask cluster (``birdsim tables build --dask SCHEDULER``).

The build already submits its tasks (V slices, V lines, climb lines, regularising
batches; each a top-level function of picklable frozen dataclasses and arrays, about a
hundred cells) to a :class:`concurrent.futures.Executor`; dask.distributed's
``Client.get_executor()`` is one, so the cluster runs exactly the tasks of a local build
and the table is bitwise the same.  Checkpoints are written by the submitting process, as
locally.  A worker that dies takes only its running tasks with it: the scheduler gives
them to another worker (up to ``distributed.scheduler.allowed-failures`` times).

``SCHEDULER`` is ``tcp://HOST:PORT`` (a running ``dask scheduler``) or ``local:N`` (a
LocalCluster of N single-threaded worker processes, started and stopped here).  Dask is
an optional extra (``pip install 'birdsim[cluster]'``) imported only here.
"""

from __future__ import annotations

import logging
import re
from collections.abc import Iterator
from concurrent.futures import Executor
from contextlib import contextmanager
from dataclasses import dataclass

from birdsim.errors import BirdsimError

#: Seconds to wait for a scheduler that does not answer (8: with the start-up of the
#: command, the one-line error arrives within 10 s).
CONNECT_TIMEOUT = 8.0
#: At most this many local worker processes.
MAX_LOCAL_WORKERS = 256
EXTRA_HINT = "pip install 'birdsim[cluster]' (dask.distributed)"


@dataclass(frozen=True)
class Scheduler:
    """A parsed ``--dask`` value: ``address`` (tcp://...) or ``local_workers`` (N)."""

    spec: str
    address: str | None = None
    local_workers: int | None = None


def parse_scheduler(spec: str) -> Scheduler:
    """``tcp://HOST:PORT`` or ``local:N`` (1 <= N <= 256).

    Raises:
        BirdsimError: anything else (one line naming ``--dask``).
    """
    spec = str(spec).strip()
    m = re.fullmatch(r"local:(\S+)", spec)
    if m:
        try:
            n = int(m.group(1))
        except ValueError:
            n = -1
        if not 1 <= n <= MAX_LOCAL_WORKERS:
            raise BirdsimError(
                f"--dask {spec!r} is invalid; allowed: local:N with N worker processes, 1 <= N <= {MAX_LOCAL_WORKERS}"
            )
        return Scheduler(spec, local_workers=n)
    if re.fullmatch(r"(tcp|tls)://[^\s:/]+:\d{1,5}", spec):
        return Scheduler(spec, address=spec)
    raise BirdsimError(
        f"--dask {spec!r} is invalid; allowed: tcp://HOST:PORT (a running dask scheduler) or local:N"
    )


def _import_distributed():  # type: ignore[no-untyped-def]
    try:
        import distributed
    except ImportError:
        raise BirdsimError(
            f"--dask needs dask.distributed, which is not installed; allowed: {EXTRA_HINT}"
        ) from None
    return distributed


@contextmanager
def dask_executor(spec: str, connect_timeout: float = CONNECT_TIMEOUT) -> Iterator[Executor]:
    """A concurrent.futures executor on the cluster ``spec`` (see :func:`parse_scheduler`).

    Args:
        spec: ``tcp://HOST:PORT`` or ``local:N``.
        connect_timeout: seconds to wait for a remote scheduler.
    Yields:
        ``Client.get_executor(pure=False)``; the client (and a local cluster) are closed
        on exit.
    Raises:
        BirdsimError: a bad spec, dask not installed, or a scheduler that does not answer
            within ``connect_timeout`` (one line naming it).
    """
    sched = parse_scheduler(spec)
    distributed = _import_distributed()
    cluster = None
    try:
        if sched.local_workers is not None:
            cluster = distributed.LocalCluster(
                n_workers=sched.local_workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",
                silence_logs=logging.ERROR,
            )
            client = distributed.Client(cluster, set_as_default=False)
        else:
            try:
                client = distributed.Client(
                    sched.address, timeout=connect_timeout, set_as_default=False
                )
            except (OSError, TimeoutError) as exc:
                raise BirdsimError(
                    f"--dask {sched.address!r}: no scheduler answered within {connect_timeout:g} s ({type(exc).__name__}); "
                    "allowed: the address of a running `dask scheduler` (tcp://HOST:8786), or local:N"
                ) from None
    except BaseException:
        if cluster is not None:
            cluster.close()
        raise
    try:
        yield client.get_executor(pure=False)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def worker_pids(executor: Executor) -> dict[str, int]:
    """{worker address: process id} of the cluster behind a :func:`dask_executor`."""
    import os

    return dict(executor._client.run(os.getpid))  # type: ignore[attr-defined]
