"""A plan's time limit and cancel, checked through its progress callback.

Every workflow's planning (the motion program, the bending transfer or cycle, the assembly
sequence, the polishing path and its motion) runs under a `PlanLimit`: the project's
``planning.time_limit`` [s] (docs/programs.md, "Planning limits") and the caller's
``cancel()``. `PlanLimit.watch` wraps the plan's progress callback: every call first checks
the clock and ``cancel()``, and past the limit (or once cancelled) raises `PlanLimitError`, a
`PlanningError` naming the setting, what was being planned and the step it had reached.
The planners' loops already report progress; the ones that did not (the joint RRTs, a
cycle's frame checks) call it on every extension or batch, so a limit applies within one
step of work.

A limit never changes a verdict: it either lets the plan finish exactly as it would have
without one, or ends it with the error (nothing is returned half-planned). The sequence
search's own ``time_limit`` works differently on purpose: a search returns the plans it found
so far (`pressbrake.sequencing`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from workbench.errors import InputError, PlanLimitError

Progress = Callable[[float, str], None]

#: The setting a plan's time limit comes from (the project file's field).
TIME_LIMIT_FIELD = "planning.time_limit"


@dataclass
class PlanLimit:
    """The time limit `seconds` (None: none) and `cancel` of planning `what` (words).

    The clock starts when the limit is made; `setting` is the field the limit came from."""

    seconds: float | None
    what: str
    cancel: Callable[[], bool] | None = None
    setting: str = TIME_LIMIT_FIELD
    start: float = field(default_factory=time.perf_counter)

    def __post_init__(self) -> None:
        s = self.seconds
        if s is not None and not (isinstance(s, int | float) and math.isfinite(s) and s > 0):
            raise InputError(f"must be > 0 s or None, got {s!r}", field=self.setting)

    def elapsed(self) -> float:
        """Return the seconds since the limit was made."""
        return time.perf_counter() - self.start

    def check(self, doing: str = "") -> None:
        """Raise PlanLimitError when `cancel()` is True or the time limit has passed; `doing`
        (words) says which step of the plan had been reached."""
        at = f" while {doing}" if doing else ""
        if self.cancel is not None and self.cancel():
            raise PlanLimitError(
                f"{self.what}: cancelled after {self.elapsed():.1f} s{at}; nothing was planned",
                cancelled=True,
            )
        if self.seconds is not None and self.elapsed() > self.seconds:
            raise PlanLimitError(
                f"{self.what}: stopped at the time limit of {self.seconds:g} s{at}; nothing was"
                f" planned. Raise {self.setting} in the project (or leave it out for the"
                " default), or make the plan smaller (fewer moves, a freer cell)",
                field=self.setting,
            )

    def watch(self, progress: Progress | None = None) -> Progress:
        """Return a progress callback that checks the limit, then forwards to `progress`."""

        def report(fraction: float, message: str) -> None:
            self.check(message)
            if progress is not None:
                progress(fraction, message)

        return report
