"""Motion: jerk-limited trajectories through joint waypoints, moves through IK, validation, export."""

from __future__ import annotations

from workbench.motion.moves import JointPath, plan_program, time_program
from workbench.motion.program import JOINT, LINEAR, Move, Program
from workbench.motion.sampled import SampledMotion
from workbench.motion.trajectory import Trajectory, smooth_joint_path
from workbench.motion.validation import (
    ValidationReport,
    Violation,
    validate_samples,
    validate_trajectory,
)

__all__ = [
    "JOINT",
    "LINEAR",
    "JointPath",
    "Move",
    "Program",
    "SampledMotion",
    "Trajectory",
    "ValidationReport",
    "Violation",
    "plan_program",
    "smooth_joint_path",
    "time_program",
    "validate_samples",
    "validate_trajectory",
]
