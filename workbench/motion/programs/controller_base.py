"""Work objects moved between the model's robot base and the controller's base frame.

Programs state work objects in the controller's base (world) frame: ABB's base frame, KUKA's
$ROBROOT, UR's base and NACHI's robot frame lie where the model's base lies, but FANUC's world
frame lies on the J1 axis at the height of J2 (ROS-Industrial's `base_link-base` joint).
`T_base_controller` (4, 4) [m] is that frame in the model's base; the service moves a program's
work objects into it before a post writes them, and a read program's back before its targets
are re-solved with the model.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from workbench.geometry.transforms import invert_transform
from workbench.motion.programs.controller_program import ReadProgram, RobotProgram, WorkObject

FloatArray = NDArray[np.float64]


def _moved(wobjs: tuple[WorkObject, ...], T: FloatArray) -> tuple[WorkObject, ...]:
    return tuple(replace(w, T_base_wobj=T @ w.T_base_wobj) for w in wobjs)


def _is_identity(T: FloatArray) -> bool:
    return bool(np.array_equal(np.asarray(T, float), np.eye(4)))


def in_controller_base(program: RobotProgram, T_base_controller: FloatArray) -> RobotProgram:
    """Return `program` with its work objects in the controller's base frame (4, 4) [m]."""
    if _is_identity(T_base_controller):
        return program
    T = invert_transform(np.asarray(T_base_controller, float))
    return replace(program, work_objects=_moved(program.work_objects, T))


def in_model_base(read: ReadProgram, T_base_controller: FloatArray) -> ReadProgram:
    """Return a read program with its work objects moved from the controller's base frame into
    the model's (the inverse of `in_controller_base`)."""
    if _is_identity(T_base_controller):
        return read
    T = np.asarray(T_base_controller, float)
    return replace(read, work_objects=_moved(read.work_objects, T))
