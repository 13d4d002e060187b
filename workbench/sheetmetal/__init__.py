"""The sheet-metal part (seed 000): K factor, flanges and bends, folding, the folded solid, its
hierarchical OBB tree, flat patterns, and recognition from a bent solid.

The press-brake process that bends it (press, die, grasps, sequence search, the cycle) is
`workbench.pressbrake`, one layer up: nothing here imports it.
"""

from __future__ import annotations

from workbench.sheetmetal.check_cost import CheckCost
from workbench.sheetmetal.folding import FoldedState
from workbench.sheetmetal.kfactor import bend_allowance, flange_extension, flange_rise, k_factor
from workbench.sheetmetal.obbtree import CollisionReport, FramesReport, OBBTree
from workbench.sheetmetal.part import Bend, Flange, SheetMetalPart
from workbench.sheetmetal.sequence import check_sequence, sequence_problem

# `check_cost` (the function) stays in its module of the same name: a package attribute of
# that name would hide the module from `import workbench.sheetmetal.check_cost as m`.

__all__ = [
    "Bend",
    "CheckCost",
    "CollisionReport",
    "Flange",
    "FoldedState",
    "FramesReport",
    "OBBTree",
    "SheetMetalPart",
    "bend_allowance",
    "check_sequence",
    "flange_extension",
    "flange_rise",
    "k_factor",
    "sequence_problem",
]
