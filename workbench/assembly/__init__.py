"""Virtual assembly (seed 003): interference of parts by cells, part path planning, timed tasks.

The public names, by concept: a part's interference (`cells`, `interference`, `contacts`),
a part's path (`plan`, `planners`), the workcell of parts and arms (`part`, `arm`,
`workcell`), a part move with its carrying robot (`part_moves`, `carry`), the sequence's
timed tasks and their timeline (`tasks`, `timeline`), its checks (`arm_check`,
`robot_pairs`) and its exports (`programs`). SI units throughout (m, rad, s).
"""

from __future__ import annotations

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.arm_check import check_arm
from workbench.assembly.carry import carry_ik
from workbench.assembly.cells import CellGrid, subdivide, winding_number
from workbench.assembly.contacts import Bodies, Contact
from workbench.assembly.interference import InterferenceChecker, exact_interference
from workbench.assembly.part import AssemblyPart, primitive_mesh
from workbench.assembly.part_moves import PLANNER_CHOICES, PartPlan, plan_move
from workbench.assembly.plan import PLANNERS, PartPath, plan_part_path
from workbench.assembly.planners.joint_rrt import CarriedPath, CarrySpace, plan_carried_path
from workbench.assembly.programs import KEY_POINT_FORMATS, assembly_programs, key_points_text
from workbench.assembly.robot_pairs import cell_bodies, cross_contacts
from workbench.assembly.tasks import TaskPlan, plan_tasks
from workbench.assembly.timeline import AssemblyPlan
from workbench.assembly.workcell import Workcell

# `timed_plan` (the function) stays in its module of the same name: a package attribute
# of that name would hide the module from `import workbench.assembly.timed_plan as m`.

__all__ = [
    "KEY_POINT_FORMATS",
    "PLANNERS",
    "PLANNER_CHOICES",
    "AssemblyArm",
    "AssemblyPart",
    "AssemblyPlan",
    "Bodies",
    "CarriedPath",
    "CarrySpace",
    "CellGrid",
    "Contact",
    "InterferenceChecker",
    "PartPath",
    "PartPlan",
    "TaskPlan",
    "Workcell",
    "carry_ik",
    "cell_bodies",
    "check_arm",
    "cross_contacts",
    "exact_interference",
    "key_points_text",
    "plan_carried_path",
    "plan_move",
    "plan_part_path",
    "plan_tasks",
    "primitive_mesh",
    "assembly_programs",
    "subdivide",
    "winding_number",
]
