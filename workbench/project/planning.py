"""The project file's `planning` section: the time limit of every workflow's planning.

``{"time_limit": 600}`` [s] (the default `DEFAULT_TIME_LIMIT_S`, also when the section is
absent): the motion program, the bending transfer or cycle, the assembly sequence and the
polishing path, simulation and motion each stop past it with a PlanningError naming
``planning.time_limit`` and the step they had reached (`workbench.plan_limit`). The default
is ten minutes: the slowest example plan (the seed part cell's cycle) takes about a minute
and a half on a 2-core machine, so a plan that runs ten is stuck, not slow. See
docs/programs.md ("Planning limits").
"""

from __future__ import annotations

from typing import Annotated

from workbench.project import bounds as B
from workbench.project.common import StrictModel

#: The default time limit of one workflow's planning [s]: see the module docstring.
DEFAULT_TIME_LIMIT_S = 600.0


class PlanningSpec(StrictModel):
    """How long one workflow's planning may run."""

    time_limit: Annotated[float, B.span(B.PLAN_TIME_S_OPEN, "s", lo_open=True)] = (
        DEFAULT_TIME_LIMIT_S  # [s] each workflow's planning; past it the plan ends with a PlanningError naming it
    )
