"""Every workflow's planning under the project's time limit and the caller's cancel.

`limited(what)` decorates a service's plan method (one that takes ``progress``): the call
also takes ``cancel`` (a callable; True ends the plan) and runs with its progress watched by
a `workbench.plan_limit.PlanLimit` of ``planning.time_limit`` (default
`project.planning.DEFAULT_TIME_LIMIT_S`), so past the limit or once cancelled the plan ends
with a PlanLimitError naming the setting, the plan and the step it had reached.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, TypeVar

from workbench.plan_limit import PlanLimit
from workbench.project.planning import DEFAULT_TIME_LIMIT_S

R = TypeVar("R")


def plan_limit(wb: Any, what: str, cancel: Callable[[], bool] | None = None) -> PlanLimit:
    """Return the limit of planning `what` (words) in the open project of `wb`, from now."""
    project = wb.project
    spec = project.planning
    seconds = DEFAULT_TIME_LIMIT_S if spec is None else spec.time_limit
    return PlanLimit(seconds, f"{what} of project {project.name!r}", cancel)


def limited(what: str) -> Callable[[Callable[..., R]], Callable[..., R]]:
    """Return a decorator: the method's ``progress`` watched by `plan_limit` (what, ``cancel``);
    the method's owner is a `Workbench` or has one as ``wb``."""

    def decorate(method: Callable[..., R]) -> Callable[..., R]:
        @functools.wraps(method)
        def run(
            self: Any,
            *args: Any,
            progress: Callable[[float, str], None] | None = None,
            cancel: Callable[[], bool] | None = None,
            **kw: Any,
        ) -> R:
            limit = plan_limit(getattr(self, "wb", self), what, cancel)
            limit.check("starting")
            return method(self, *args, progress=limit.watch(progress), **kw)

        return run

    return decorate
