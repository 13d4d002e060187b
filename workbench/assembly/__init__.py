"""Virtual assembly (seed 003): interference of parts by cells, and part path planning."""

from workbench.assembly.cells import CellGrid, subdivide, winding_number
from workbench.assembly.interference import InterferenceChecker, exact_interference
from workbench.assembly.plan import PLANNERS, PartPath, plan_part_path

__all__ = [
    "PLANNERS",
    "CellGrid",
    "InterferenceChecker",
    "PartPath",
    "exact_interference",
    "plan_part_path",
    "subdivide",
    "winding_number",
]
