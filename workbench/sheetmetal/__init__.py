"""Robotic press-brake bending (seed 000): K factor, part model, folded solid, OBB tree, die and transfer."""

from __future__ import annotations

from workbench.sheetmetal.airbend import AIR_BEND_RATIO, air_bend_radius, apex_depth, short_flanges
from workbench.sheetmetal.bend_eval import BendEval, Reach, SweepContext, evaluate_batch
from workbench.sheetmetal.bend_setup import BendPose, GaugeStop, bend_pose, gauge_stop
from workbench.sheetmetal.check_cost import CheckCost
from workbench.sheetmetal.cycle import BendingCycle, check_cycle
from workbench.sheetmetal.cycle_path import CycleCell, CycleStep
from workbench.sheetmetal.die import (
    Die,
    DiePlacement,
    bend_on_die,
    die_part_pose,
    die_placements,
    die_targets,
)
from workbench.sheetmetal.folding import FoldedState
from workbench.sheetmetal.grasp import (
    Grasp,
    T_flange_grasp,
    T_part_grasp,
    check_flange,
    checked_grasp,
    grasp_point,
)
from workbench.sheetmetal.kfactor import bend_allowance, flange_extension, flange_rise, k_factor
from workbench.sheetmetal.obbtree import CollisionReport, FramesReport, OBBTree
from workbench.sheetmetal.obstacles import Obstacles, cell_obstacles
from workbench.sheetmetal.part import Bend, Flange, SheetMetalPart
from workbench.sheetmetal.plan import (
    BendingPlan,
    FirstCollision,
    first_collision,
    playback,
    robot_frames,
)
from workbench.sheetmetal.press import (
    BackGauge,
    DieTool,
    PressBrake,
    Punch,
    Ram,
    Station,
    punch_profile,
    ram_time,
)
from workbench.sheetmetal.sequence import check_sequence, sequence_problem
from workbench.sheetmetal.sequencing import (
    SearchResult,
    SearchSettings,
    SearchStats,
    SequencePlan,
    find_sequences,
)
from workbench.sheetmetal.transfer import (
    Transfer,
    base_flange_poses,
    carried_poses,
    check_part,
    transfer_poses,
    world_tcp,
)

# `check_cost` (the function) stays in its module of the same name: a package attribute of
# that name would hide the module from `import workbench.sheetmetal.check_cost as m`.

__all__ = [
    "AIR_BEND_RATIO",
    "BackGauge",
    "Bend",
    "BendEval",
    "BendPose",
    "BendingCycle",
    "CycleCell",
    "CycleStep",
    "DieTool",
    "GaugeStop",
    "PressBrake",
    "Punch",
    "Ram",
    "Reach",
    "SearchResult",
    "SearchSettings",
    "SearchStats",
    "SequencePlan",
    "Station",
    "SweepContext",
    "air_bend_radius",
    "apex_depth",
    "bend_pose",
    "check_cycle",
    "evaluate_batch",
    "find_sequences",
    "gauge_stop",
    "punch_profile",
    "ram_time",
    "short_flanges",
    "BendingPlan",
    "CheckCost",
    "CollisionReport",
    "Die",
    "DiePlacement",
    "FirstCollision",
    "Flange",
    "FoldedState",
    "FramesReport",
    "Grasp",
    "OBBTree",
    "Obstacles",
    "SheetMetalPart",
    "T_flange_grasp",
    "T_part_grasp",
    "Transfer",
    "base_flange_poses",
    "bend_allowance",
    "bend_on_die",
    "carried_poses",
    "cell_obstacles",
    "check_flange",
    "check_part",
    "check_sequence",
    "checked_grasp",
    "die_part_pose",
    "die_placements",
    "die_targets",
    "first_collision",
    "flange_extension",
    "flange_rise",
    "grasp_point",
    "k_factor",
    "playback",
    "robot_frames",
    "sequence_problem",
    "transfer_poses",
    "world_tcp",
]
