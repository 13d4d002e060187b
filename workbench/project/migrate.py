"""Migrations of older project files, one schema version to the next, on the parsed JSON.

Version 1 -> 2: joint values are written in the robot controller's convention. A version-1
file stored them in the kinematic model's convention; for a preset robot with a controller
convention (the NACHI MZ07) they are converted, so that every posture stays the same:
`robot.joints`, `program.start`, the joint targets `program.moves[i].joints` (the program
runs on the project's robot) and `assembly.robots[i].joints`. Robots given by DH rows or a
URDF have the identity convention: their values, and DH limits, stay as they are.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np

from workbench.kinematics.joint_convention import JointConvention
from workbench.project.models import PRESET_CONVENTIONS
from workbench.project.units import DEG

DEFAULT_PRESET = "mz07"  # a project without a robot section gets the preset robot


def _convention(robot: object) -> JointConvention | None:
    preset = robot.get("preset") if isinstance(robot, dict) else None
    return PRESET_CONVENTIONS.get(preset) if isinstance(preset, str) else None


def _to_controller(values: object, conv: JointConvention) -> object:
    """Return model joints [deg] as the controller's [deg]; anything malformed unchanged (the
    validation that follows names it)."""
    if not isinstance(values, list) or len(values) != conv.dof:
        return values
    if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in values):
        return values
    q = conv.to_controller(np.asarray(values, float) * DEG) / DEG
    return [round(float(v), 9) for v in q]


def _convert(section: object, key: str, conv: JointConvention | None) -> None:
    if conv is not None and isinstance(section, dict) and key in section:
        section[key] = _to_controller(section[key], conv)


def v1_to_v2(data: dict[str, Any]) -> dict[str, Any]:
    """Return a version-1 project (parsed JSON) with its joint values in the controller's convention."""
    data = copy.deepcopy(data)
    robot = data.get("robot", {"preset": DEFAULT_PRESET})
    conv = _convention(robot)
    _convert(data.get("robot"), "joints", conv)
    program = data.get("program")
    if isinstance(program, dict):
        _convert(program, "start", conv)
        moves = program.get("moves")
        for move in moves if isinstance(moves, list) else []:
            _convert(move, "joints", conv)
    assembly = data.get("assembly")
    robots = assembly.get("robots") if isinstance(assembly, dict) else None
    for arm in robots if isinstance(robots, list) else []:
        if isinstance(arm, dict):  # an assembly robot is a preset, "mz07" unless it says
            _convert(arm, "joints", _convention({"preset": arm.get("preset", DEFAULT_PRESET)}))
    return data
