"""The service API: `Workbench` turns a project into domain objects and runs them."""

from __future__ import annotations

from workbench.motion import SampledMotion
from workbench.motion.programs import EXPORT_FORMATS, ExportedProgram, RobotProgram
from workbench.service.assembly import AssemblyService
from workbench.service.bending import BendingService
from workbench.service.calibration import CalibrationService
from workbench.service.calibration_result import CalibrationResult
from workbench.service.cell import CellBody
from workbench.service.collision_engine import CollisionService
from workbench.service.motion_plan import MotionPlan
from workbench.service.polishing import PolishingService
from workbench.service.programs import WORKFLOWS
from workbench.service.robot_setup import RobotSetup
from workbench.service.section import SectionService
from workbench.service.workbench import IKSolution, Workbench

__all__ = [
    "EXPORT_FORMATS",
    "WORKFLOWS",
    "AssemblyService",
    "BendingService",
    "CalibrationResult",
    "CalibrationService",
    "CellBody",
    "CollisionService",
    "ExportedProgram",
    "IKSolution",
    "MotionPlan",
    "PolishingService",
    "RobotProgram",
    "RobotSetup",
    "SampledMotion",
    "SectionService",
    "Workbench",
]
