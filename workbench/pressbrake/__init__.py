"""The press-brake process (seed 000) that bends a `workbench.sheetmetal` part: the press (punch,
V-die, stations, back-gauge, ram), air bending, the die placements, grasps and the grasp grid,
one bend's set-up and its cheap evaluation, the press and cell checks, the bend-sequence and
grasp search, the cycle's path and transits, the planned cycle and its program, and the
transfer planner of a plan without a press.
"""

from __future__ import annotations

from workbench.pressbrake.airbend import AIR_BEND_RATIO, air_bend_radius, apex_depth, short_flanges
from workbench.pressbrake.bend_eval import BendEval, Reach, SweepContext, evaluate_batch
from workbench.pressbrake.bend_setup import BendPose, GaugeStop, bend_pose, gauge_stop
from workbench.pressbrake.cycle import BendingCycle, check_cycle
from workbench.pressbrake.cycle_path import CycleCell, CycleStep
from workbench.pressbrake.cycle_plan import CycleRobot
from workbench.pressbrake.die import (
    Die,
    DiePlacement,
    bend_on_die,
    die_part_pose,
    die_placements,
    die_targets,
)
from workbench.pressbrake.grasp import (
    Grasp,
    T_flange_grasp,
    T_part_grasp,
    check_flange,
    checked_grasp,
    grasp_point,
)
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.plan import (
    BendingPlan,
    FirstCollision,
    first_collision,
    playback,
    robot_frames,
)
from workbench.pressbrake.press import (
    BackGauge,
    DieTool,
    PressBrake,
    Punch,
    Ram,
    Station,
    punch_profile,
    ram_time,
)
from workbench.pressbrake.result import BendingResult
from workbench.pressbrake.sequencing import (
    SearchResult,
    SearchSettings,
    SearchStats,
    SequencePlan,
    find_sequences,
)
from workbench.pressbrake.transfer import (
    Transfer,
    base_flange_poses,
    carried_poses,
    check_part,
    transfer_poses,
    world_tcp,
)
from workbench.pressbrake.transfer_plan import plan_transfer

__all__ = [
    "air_bend_radius",
    "AIR_BEND_RATIO",
    "apex_depth",
    "BackGauge",
    "base_flange_poses",
    "bend_on_die",
    "bend_pose",
    "BendEval",
    "BendingCycle",
    "BendingPlan",
    "BendingResult",
    "BendPose",
    "carried_poses",
    "cell_obstacles",
    "check_cycle",
    "CycleRobot",
    "check_flange",
    "check_part",
    "checked_grasp",
    "CycleCell",
    "CycleStep",
    "Die",
    "die_part_pose",
    "die_placements",
    "die_targets",
    "DiePlacement",
    "DieTool",
    "evaluate_batch",
    "find_sequences",
    "first_collision",
    "FirstCollision",
    "gauge_stop",
    "GaugeStop",
    "Grasp",
    "grasp_point",
    "Obstacles",
    "plan_transfer",
    "playback",
    "PressBrake",
    "Punch",
    "punch_profile",
    "Ram",
    "ram_time",
    "Reach",
    "robot_frames",
    "SearchResult",
    "SearchSettings",
    "SearchStats",
    "SequencePlan",
    "short_flanges",
    "Station",
    "SweepContext",
    "T_flange_grasp",
    "T_part_grasp",
    "Transfer",
    "transfer_poses",
    "world_tcp",
]
