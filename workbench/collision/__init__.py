"""Collision checking: exact python-fcl checks of robots against cells (the baseline)."""

from __future__ import annotations

from workbench.collision.fcl_checker import CollisionScene, ContactReport
from workbench.collision.plan_check import (
    CollisionPolicy,
    check_motion,
    check_trajectory,
    default_cache_dir,
    shared_engine,
)
from workbench.collision.robot_checker import PathReport, RobotCollisionChecker
from workbench.collision.shapes import Solid, bvh_model, check_mesh, fcl_transform

__all__ = [
    "CollisionPolicy",
    "ContactReport",
    "CollisionScene",
    "PathReport",
    "RobotCollisionChecker",
    "Solid",
    "bvh_model",
    "check_mesh",
    "check_motion",
    "check_trajectory",
    "default_cache_dir",
    "fcl_transform",
    "shared_engine",
]
