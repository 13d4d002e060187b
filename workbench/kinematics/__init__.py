"""Robot kinematics: DH and URDF arms, batched FK, analytic (OPW) and numeric IK, link geometry."""

from __future__ import annotations

from workbench.kinematics.configurations import labelled_solutions
from workbench.kinematics.dh_robot import IK_TOL, DHRobot
from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.joint_convention import JointConvention
from workbench.kinematics.link_shapes import flange_mesh, link_meshes
from workbench.kinematics.model import RobotModel
from workbench.kinematics.path_ik import PathIK, follow_path
from workbench.kinematics.presets import MZ07_SEED_DH, MZ07_SEED_TOOL
from workbench.kinematics.robot_library import (
    ROBOT_NAMES,
    LibraryRobot,
    library_robot,
    preset_robot,
)
from workbench.kinematics.singularity import Singularities
from workbench.kinematics.urdf_robot import URDFRobot

__all__ = [
    "IK_TOL",
    "MZ07_SEED_DH",
    "MZ07_SEED_TOOL",
    "ROBOT_NAMES",
    "DHRobot",
    "JointConvention",
    "LibraryRobot",
    "PathIK",
    "RobotModel",
    "Singularities",
    "URDFRobot",
    "branch_name",
    "flange_mesh",
    "follow_path",
    "labelled_solutions",
    "library_robot",
    "link_meshes",
    "preset_robot",
]
