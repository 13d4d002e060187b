"""The batch runner: one pure evaluation function over batches of items, serial or on Ray.

Domain packages supply ``fn(context, batch) -> one result per item``, a module-level
(picklable) function; the runner cuts the items into batches, runs them, and puts each
result back at its item's index. It knows nothing of what the items are.

- ``engine="serial"``: a plain loop in this process.
- ``engine="ray"``: every batch is one Ray task, all submitted up front; Ray schedules
  them. The context goes to the object store once (``ray.put``) and every task gets it
  by reference. Without an ``address`` an embedded local Ray is started for the run and
  shut down after; a Ray already initialised in this process is reused and left running.

Both engines report progress after each finished batch and stop on ``cancel()`` or a
time limit, keeping the results finished so far. Ray is imported only by the Ray engine.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from workbench.errors import InputError, PlanningError, WorkbenchError
from workbench.ray_session import access as ray_access
from workbench.ray_session import check_ray_version, start_ray, stop_ray

if TYPE_CHECKING:
    from ray.exceptions import RayTaskError

__all__ = [
    "ENGINES",
    "BatchRun",
    "BatchStats",
    "batches_of",
    "check_engine",
    "engine_session",
    "run_batches",
]

T = TypeVar("T")
R = TypeVar("R")
C = TypeVar("C")

ENGINES = ("serial", "ray")

_TICK_S = 0.1  # how often the Ray engine polls cancel() and the time limit [s]


def batches_of(items: Sequence[T], size: int) -> list[list[T]]:
    """Return `items` cut into consecutive lists of `size` items (the last may be shorter).

    Order is kept: concatenating the batches gives `items` back.
    """
    if isinstance(size, bool) or not isinstance(size, int) or size <= 0:
        raise InputError(f"batch_size must be a positive integer, got {size!r}")
    return [list(items[i : i + size]) for i in range(0, len(items), size)]


@dataclass(frozen=True)
class BatchStats:
    """How a batch run went: engine, workers, counts and times [s]."""

    engine: str
    """``"serial"`` or ``"ray"``."""
    address: str | None
    """The Ray cluster attached to; None for an embedded local Ray (or serial)."""
    workers: int
    """Serial: 1; Ray: the CPUs the cluster reports (``ray.cluster_resources()["CPU"]``)."""
    batches: int
    """Batches finished."""
    items: int
    """Items evaluated (in finished batches)."""
    wall_s: float
    """Wall time of the run [s], Ray start-up excluded."""
    startup_s: float
    """Time to start or attach Ray [s]; 0 for serial or a reused Ray."""
    compute_s: float
    """Sum over finished batches of the time `fn` itself took inside the task [s]."""
    overhead_per_batch_s: float
    """``(wall_s * min(workers, batches) - compute_s) / batches``, at least 0 [s]:
    scheduling and transfer per batch."""
    access: str = ""
    """Ray only: who may use the Ray the run used (`workbench.ray_session.access`: token
    authentication, or a warning that any client may attach); empty for serial."""

    def describe(self) -> str:
        """Return one line for a log or a status bar, e.g.

        ``ray (local, 2 workers): 12 batches, 480 items in 3.1 s; overhead 0.004 s per
        batch (1.2 % of a batch)``.
        """
        where = "" if self.engine == "serial" else f"{self.address or 'local'}, "
        workers = f"{self.workers} worker{'s' if self.workers != 1 else ''}"
        guard = f", {self.access}" if self.access else ""
        line = (
            f"{self.engine} ({where}{workers}{guard}): {self.batches} batches, {self.items} items "
            f"in {self.wall_s:.3g} s; overhead {self.overhead_per_batch_s:.3g} s per batch"
        )
        if self.batches and self.compute_s > 0:
            share = 100.0 * self.overhead_per_batch_s / (self.compute_s / self.batches)
            line += f" ({share:.1f} % of a batch)"
        return line


@dataclass(frozen=True)
class BatchRun(Generic[R]):
    """The results of a batch run, one per item in item order, and how the run went."""

    results: list[R | None]
    """One per item; None for an item not evaluated (cancelled or past the time limit)."""
    stats: BatchStats
    cancelled: bool
    """The run stopped because ``cancel()`` returned True."""
    timed_out: bool
    """The run stopped because its time limit passed."""

    _done: tuple[bool, ...] = field(default=(), repr=False, kw_only=True)

    def done(self) -> list[bool]:
        """Return, per item, whether it was evaluated (its batch finished).

        A run built without the flags (by hand) counts the non-None results as done.
        """
        if len(self._done) == len(self.results):
            return list(self._done)
        return [r is not None for r in self.results]


def _timed_call(
    fn: Callable[[Any, list[Any]], Any], context: Any, batch: list[Any]
) -> tuple[Any, float]:
    """Return ``fn(context, batch)`` and the seconds the call took [s] (fn only)."""
    start = time.perf_counter()
    out = fn(context, batch)
    return out, time.perf_counter() - start


def run_batches(
    fn: Callable[[C, list[T]], list[R]],
    items: Sequence[T],
    *,
    context: C = None,  # type: ignore[assignment]
    engine: str = "serial",
    address: str | None = None,
    batch_size: int = 32,
    progress: Callable[[float, str], None] | None = None,
    cancel: Callable[[], bool] | None = None,
    time_limit: float | None = None,
    connect_timeout: float = 10.0,
) -> BatchRun[R]:
    """Return ``fn``'s result for every item, in item order, with the run's stats.

    Args:
        fn: pure, module-level (picklable) function ``(context, batch) -> results``, one
            result per item of the batch, in order.
        items: the items; cut into consecutive batches of `batch_size`.
        context: shared read-only data passed to every call (Ray: put in the object store
            once and passed by reference).
        engine: ``"serial"`` (a loop in this process) or ``"ray"``.
        address: Ray only: ``host:port`` of a running cluster's head (GCS) to attach to;
            None starts an embedded local Ray on all cores for this run and shuts it down
            after. A Ray already initialised in this process is reused and left running.
        batch_size: items per batch (> 0); one batch is one Ray task.
        progress: called after each finished batch with the fraction of items done in
            [0, 1] and a message.
        cancel: polled between batches (serial) or every 0.1 s while waiting (Ray); when it
            returns True the pending batches are cancelled and the run returns.
        time_limit: wall-clock limit of the run [s], Ray start-up excluded; when it passes,
            pending batches are cancelled and the run returns. A batch already running in
            the serial engine is finished first.
        connect_timeout: how long to wait for `address` to answer [s].

    Items of unfinished batches have result None (see `BatchRun.done`).

    Raises:
        InputError: an unknown engine, a bad argument, or a Ray address that does not
            answer (the message names it and how to fix it).
        PlanningError: `fn` returned a number of results other than its batch's size.
        Exception: an exception raised inside `fn` is re-raised as its own type (a
            `WorkbenchError` as itself; others, on Ray, as Ray's dual
            ``RayTaskError``/cause instance carrying the remote traceback).
    """
    _check_arguments(fn, engine, address, batch_size, time_limit, connect_timeout)
    batches = batches_of(items, batch_size)
    tally: _Tally[R] = _Tally(len(items), batch_size, len(batches), progress)
    if not batches:
        return tally.finish(engine, address, 1, 0.0, 0.0, cancelled=False, timed_out=False)
    if engine == "serial":
        return _run_serial(fn, batches, context, tally, cancel, time_limit)
    return _run_ray(fn, batches, context, tally, address, cancel, time_limit, connect_timeout)


def _check_arguments(
    fn: object,
    engine: str,
    address: str | None,
    batch_size: int,
    time_limit: float | None,
    connect_timeout: float,
) -> None:
    """Raise InputError naming the first bad argument of `run_batches`."""
    if engine not in ENGINES:
        allowed = ", ".join(repr(e) for e in ENGINES)
        raise InputError(f"engine must be one of {allowed}, got {engine!r}")
    if not callable(fn):
        raise InputError(f"fn must be a function (context, batch) -> results, got {fn!r}")
    if isinstance(batch_size, bool) or not isinstance(batch_size, int) or batch_size <= 0:
        raise InputError(f"batch_size must be a positive integer, got {batch_size!r}")
    if time_limit is not None and not time_limit > 0:
        raise InputError(f"time_limit must be > 0 s or None, got {time_limit!r}")
    if not connect_timeout > 0:
        raise InputError(f"connect_timeout must be > 0 s, got {connect_timeout!r}")
    if address is not None and engine != "ray":
        raise InputError(
            f"address is for engine='ray' only, got address={address!r} with engine={engine!r}"
        )


class _Tally(Generic[R]):
    """Results placed by item index, counts and compute time of the finished batches."""

    def __init__(
        self,
        n_items: int,
        batch_size: int,
        n_batches: int,
        progress: Callable[[float, str], None] | None,
    ) -> None:
        self.results: list[R | None] = [None] * n_items
        self.done = [False] * n_items
        self.batch_size = batch_size
        self.n_batches = n_batches
        self.progress = progress
        self.batches = 0
        self.items = 0
        self.compute_s = 0.0

    def add(self, k: int, size: int, out: Any, seconds: float) -> None:
        """Place batch `k`'s results (it held `size` items) and report progress."""
        first = k * self.batch_size
        if not hasattr(out, "__len__") or len(out) != size:
            got = f"{len(out)} results" if hasattr(out, "__len__") else repr(type(out))
            raise PlanningError(
                f"batch {k} (items {first}..{first + size - 1}): the evaluation function "
                f"returned {got} for {size} items; it must return one result per item"
            )
        for j, result in enumerate(out):
            self.results[first + j] = result
            self.done[first + j] = True
        self.batches += 1
        self.items += size
        self.compute_s += seconds
        if self.progress is not None:
            total = len(self.results)
            self.progress(
                self.items / total,
                f"{self.batches} of {self.n_batches} batches, {self.items} of {total} items",
            )

    def finish(
        self,
        engine: str,
        address: str | None,
        workers: int,
        wall_s: float,
        startup_s: float,
        *,
        cancelled: bool,
        timed_out: bool,
        access: str = "",
    ) -> BatchRun[R]:
        """Return the run: results so far and stats."""
        overhead = 0.0
        if self.batches:
            used = min(workers, self.batches)
            overhead = max(0.0, (wall_s * used - self.compute_s) / self.batches)
        if not self.results and self.progress is not None:
            self.progress(1.0, "no items")
        stats = BatchStats(
            engine=engine,
            address=address,
            workers=workers,
            batches=self.batches,
            items=self.items,
            wall_s=wall_s,
            startup_s=startup_s,
            compute_s=self.compute_s,
            overhead_per_batch_s=overhead,
            access=access,
        )
        return BatchRun(self.results, stats, cancelled, timed_out, _done=tuple(self.done))


def _run_serial(
    fn: Callable[[Any, list[Any]], Any],
    batches: list[list[Any]],
    context: Any,
    tally: _Tally[R],
    cancel: Callable[[], bool] | None,
    time_limit: float | None,
) -> BatchRun[R]:
    """Return the run of `batches` in a loop in this process."""
    cancelled = timed_out = False
    start = time.perf_counter()
    for k, batch in enumerate(batches):
        if cancel is not None and cancel():
            cancelled = True
            break
        if time_limit is not None and time.perf_counter() - start >= time_limit:
            timed_out = True
            break
        out, seconds = _timed_call(fn, context, batch)
        tally.add(k, len(batch), out, seconds)
    wall = time.perf_counter() - start
    return tally.finish("serial", None, 1, wall, 0.0, cancelled=cancelled, timed_out=timed_out)


def _run_ray(
    fn: Callable[[Any, list[Any]], Any],
    batches: list[list[Any]],
    context: Any,
    tally: _Tally[R],
    address: str | None,
    cancel: Callable[[], bool] | None,
    time_limit: float | None,
    connect_timeout: float,
) -> BatchRun[R]:
    """Return the run of `batches` as Ray tasks, all submitted up front."""
    started = time.perf_counter()
    owned = start_ray(address, connect_timeout)  # refuses a Ray too old to authenticate
    startup = time.perf_counter() - started
    import ray
    from ray.exceptions import RayTaskError

    try:
        access = ray_access()
        workers = max(1, int(ray.cluster_resources().get("CPU", 1)))
        start = time.perf_counter()
        deadline = None if time_limit is None else start + time_limit
        task = _remote_timed_call()
        context_ref = ray.put(context)
        refs = [task.remote(fn, context_ref, batch) for batch in batches]
        index = {ref: k for k, ref in enumerate(refs)}
        pending = list(refs)
        cancelled = timed_out = False
        try:
            while pending:
                if cancel is not None and cancel():
                    cancelled = True
                    break
                tick = _TICK_S
                if deadline is not None:
                    tick = min(tick, deadline - time.perf_counter())
                    if tick <= 0:
                        timed_out = True
                        break
                ready, pending = ray.wait(pending, num_returns=1, timeout=tick)
                for ref in ready:
                    k = index[ref]
                    try:
                        out, seconds = ray.get(ref)
                    except RayTaskError as err:
                        raise _original(err) from err
                    tally.add(k, len(batches[k]), out, seconds)
        finally:
            for ref in pending:
                ray.cancel(ref, force=False)
        wall = time.perf_counter() - start
    finally:
        if owned:
            stop_ray()
    return tally.finish(
        "ray",
        address,
        workers,
        wall,
        startup,
        cancelled=cancelled,
        timed_out=timed_out,
        access=access,
    )


def check_engine(engine: str, address: str | None = None) -> None:
    """Raise InputError for an unknown engine, an address without Ray, or an installed Ray too
    old to authenticate (`ray_session.check_ray_version`): a job checks this before its
    set-up, and no Ray process starts for a refused one."""
    if engine not in ENGINES:
        raise InputError(f"engine: must be one of {list(ENGINES)}, got {engine!r}")
    if engine == "serial":
        if address is not None:
            raise InputError(
                f"address: {address!r} is for the ray engine; leave it out with engine='serial'"
            )
        return
    check_ray_version()


@contextmanager
def engine_session(
    engine: str, address: str | None = None, *, connect_timeout: float = 10.0
) -> Iterator[str]:
    """Start (or attach to) Ray once for a job of several `run_batches` calls, and shut it
    down after, if this call started it; a no-op for the serial engine.

    Yields who may use that Ray (`BatchStats.access`; empty for serial). The runs inside
    reuse the session, so a search's rounds pay Ray's start-up once.
    """
    check_engine(engine, address)
    if engine == "serial":
        yield ""
        return
    owned = start_ray(address, connect_timeout)
    try:
        yield ray_access()
    finally:
        if owned:
            stop_ray()


def _original(err: RayTaskError) -> BaseException:
    """Return the exception raised inside a Ray task, as its own type where possible.

    A `WorkbenchError` comes back as itself (its message and attributes intact, the Ray
    error chained as its cause); any other exception as Ray's instance of both
    ``RayTaskError`` and the cause's class, whose message carries the remote traceback.
    """
    if isinstance(err.cause, WorkbenchError):
        return err.cause
    return err.as_instanceof_cause()


_REMOTE: list[Any] = []


def _remote_timed_call() -> Any:
    """Return `_timed_call` as a Ray remote function (made once per process)."""
    if not _REMOTE:
        import ray

        _REMOTE.append(ray.remote(_timed_call))
    return _REMOTE[0]
