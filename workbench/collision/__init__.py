"""Collision checking of robots against their cells and themselves (SI units).

The exact baseline (python-fcl: `RobotCollisionChecker`, `CollisionScene`, `ContactReport`),
the fast conservative engine by mode (`CollisionEngine`: spheres + SDF, capsules, exact;
`ConfigCheck`, `EnginePathReport`) and the plan collision policy every plan runs under
(`CollisionPolicy`, `check_trajectory`, `check_motion`, `shared_engine`).
"""

from __future__ import annotations

from workbench.collision.engine import CollisionEngine, ConfigCheck, EnginePathReport
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
    "CollisionEngine",
    "CollisionPolicy",
    "CollisionScene",
    "ConfigCheck",
    "ContactReport",
    "EnginePathReport",
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
