"""A SAFE FIRST MOVE: every exported program reaches its first target at a bounded speed from
wherever the robot stands.

A plan times its first move from a start posture (the plan's start, the robot's joints); the
controller starts from wherever the robot is. A timed first move (RAPID's ``\\T``, URScript's
``t=``) would cover any distance in the planned time, at up to full axis speed. So every post
writes the first move through `safe_start`: a plain joint move (a linear first move becomes a
joint move to the same target: a straight line from an unknown posture is no plan), untimed,
at most `FIRST_MOVE_SPEED` of the joints' maximum speed (RAPID, which has no joint
percentage: `FIRST_MOVE_TCP_SPEED` and `FIRST_MOVE_ORI_SPEED`), ending in an exact stop, so the
planned cycle starts at the first target. KUKA calls this the BCO run (block coincidence):
the first motion of a program, run to its point at the programmed velocity, PTP by custom.

The first move's planned duration stays in the `RobotProgram` (what the plan says); it is not
written, and it is not part of the cycle the read-back tests replan (they start at the first
target).
"""

from __future__ import annotations

from dataclasses import replace

from workbench.motion.programs.controller_program import MoveInstr, RobotProgram

FIRST_MOVE_SPEED = 0.1
"""The first move's largest speed, a fraction of the joints' maximum speed (10 %)."""

FIRST_MOVE_TCP_SPEED = 0.25
"""RAPID's first move: TCP speed [m/s], ISO 10218-1's reduced speed (250 mm/s)."""

FIRST_MOVE_ORI_SPEED = 45.0
"""RAPID's first move: reorientation speed [deg/s] (10 % of ABB's predefined 500 deg/s is
too slow to matter; 45 deg/s is about 10 % of a wrist axis' maximum speed)."""


def first_move_index(program: RobotProgram) -> int | None:
    """Return the index in `program.instructions` of the first move (None: no move)."""
    return next((k for k, i in enumerate(program.instructions) if isinstance(i, MoveInstr)), None)


def safe_first_move(mv: MoveInstr) -> MoveInstr:
    """Return `mv` as a safe first move: a joint move to the same target (a circular first
    move goes to its end point), untimed (duration 0), at min(its speed, FIRST_MOVE_SPEED) of
    the joints' maximum (a linear move's speed is a TCP speed: FIRST_MOVE_SPEED), exact stop."""
    speed = min(mv.speed, FIRST_MOVE_SPEED) if mv.kind == "joint" else FIRST_MOVE_SPEED
    return replace(mv, kind="joint", speed=speed, zone=0.0, duration=0.0, via=None)


def safe_start(program: RobotProgram) -> RobotProgram:
    """Return `program` with its first move made safe (`safe_first_move`); what every post
    writes."""
    k = first_move_index(program)
    if k is None:
        return program
    ins = list(program.instructions)
    ins[k] = safe_first_move(ins[k])  # type: ignore[arg-type]
    return replace(program, instructions=tuple(ins))
