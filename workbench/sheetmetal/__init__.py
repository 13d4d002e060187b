"""Robotic press-brake bending (seed 000): K factor, part model, folded solid, OBB tree, die and transfer."""

from __future__ import annotations

from workbench.sheetmetal.check_cost import CheckCost, check_cost
from workbench.sheetmetal.die import Die, DiePlacement, bend_on_die, die_part_pose
from workbench.sheetmetal.folding import FoldedState
from workbench.sheetmetal.grasp import Grasp, T_flange_grasp, checked_grasp, grasp_point
from workbench.sheetmetal.kfactor import bend_allowance, flange_extension, flange_rise, k_factor
from workbench.sheetmetal.obbtree import CollisionReport, FramesReport, OBBTree
from workbench.sheetmetal.obstacles import Obstacles, cell_obstacles
from workbench.sheetmetal.part import Bend, Flange, SheetMetalPart
from workbench.sheetmetal.plan import BendingPlan, FirstCollision, first_collision, playback
from workbench.sheetmetal.sequence import check_sequence, sequence_problem
from workbench.sheetmetal.transfer import Transfer, carried_poses, transfer_poses

__all__ = [
    "Bend",
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
    "Transfer",
    "bend_allowance",
    "bend_on_die",
    "carried_poses",
    "cell_obstacles",
    "check_cost",
    "check_sequence",
    "checked_grasp",
    "die_part_pose",
    "first_collision",
    "flange_extension",
    "flange_rise",
    "grasp_point",
    "k_factor",
    "playback",
    "sequence_problem",
    "transfer_poses",
]
