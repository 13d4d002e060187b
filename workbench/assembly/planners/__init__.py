"""Part path planners: seed 003's single-ant greedy and RRT-Connect in SE(3)."""

from workbench.assembly.planners.ant import plan_ant
from workbench.assembly.planners.rrt_connect import plan_rrt_connect, shortcut

__all__ = ["plan_ant", "plan_rrt_connect", "shortcut"]
