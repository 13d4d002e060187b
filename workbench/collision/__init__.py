"""Collision checking: exact python-fcl checks of robots against cells (the baseline)."""

from __future__ import annotations

from workbench.collision.fcl_checker import CollisionReport, CollisionScene
from workbench.collision.robot_checker import PathReport, RobotCollisionChecker
from workbench.collision.shapes import Solid, bvh_model, check_mesh, fcl_transform

__all__ = [
    "CollisionReport",
    "CollisionScene",
    "PathReport",
    "RobotCollisionChecker",
    "Solid",
    "bvh_model",
    "check_mesh",
    "fcl_transform",
]
