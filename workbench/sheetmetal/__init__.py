"""Robotic press-brake bending (seed 000): K factor, part model, folded solid, OBB tree."""

from __future__ import annotations

from workbench.sheetmetal.folding import FoldedState
from workbench.sheetmetal.kfactor import bend_allowance, flange_extension, flange_rise, k_factor
from workbench.sheetmetal.obbtree import CollisionReport, FramesReport, OBBTree
from workbench.sheetmetal.part import Bend, Flange, SheetMetalPart

__all__ = [
    "Bend",
    "CollisionReport",
    "Flange",
    "FoldedState",
    "FramesReport",
    "OBBTree",
    "SheetMetalPart",
    "bend_allowance",
    "flange_extension",
    "flange_rise",
    "k_factor",
]
