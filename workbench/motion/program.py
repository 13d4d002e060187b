"""THE MOTION PROGRAM the planner takes: `Program`, a named list of joint and linear `Move`s (SI),
and the one conversion into it from the user's program (`motion_program`).

The user's program (the project's `program` section in mm and deg; `to_si()` gives its items
in SI) is a list of items, each a move (`ProgramMove`: a joint move to joints or to a TCP pose,
or a linear move to a pose, with its work object) or an action of the controller program
(`SetOutput`, `Gripper`, `WaitTime`, ...). The planner sees only the moves; a move followed by
an action (other than a comment) ends in an exact stop (`stop_zones`): the action happens at
the target, as a controller runs it (a robot in a blend has not arrived). A pose joint move goes
to the IK solution in its stored configuration (`solve_configuration`: branch and turns), or,
where it stores none, the one nearest the previous joint target (`nearest_ik`). The program
starts from its own start joints or, without them, from its first move's target
(`program_start`): never from wherever the robot was jogged, so a program plans the same.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, TypeAlias

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, PlanningError, UnreachableError
from workbench.geometry.pose_check import check_transform
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.kinematics.target_configuration import (
    TargetConfiguration,
    solve_configuration,
    target_configuration,
)

if TYPE_CHECKING:  # the actions are the controller program's; motion.programs imports this module
    from workbench.motion.programs.controller_program import Action

FloatArray = NDArray[np.float64]

JOINT = "joint"
LINEAR = "linear"


@dataclass(frozen=True)
class Move:
    """One move: a joint move (PTP/MoveJ) to joints [rad] or a linear move (LIN/MoveL) to a pose.

    `target` holds 6 joint angles [rad] for a joint move, or the 16 entries (row-major) of
    T_base_tcp [m] for a linear move. `speed` is a fraction (0, 1] of the joints' maximum
    speed for a joint move and the TCP speed [m/s] for a linear move. `zone` is the blend
    radius [m] around the target; 0 means an exact stop (fine).
    """

    kind: str
    target: tuple[float, ...]
    speed: float
    zone: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        if self.kind not in (JOINT, LINEAR):
            raise InputError(f"Move.kind must be 'joint' or 'linear', got {self.kind!r}")
        n = 6 if self.kind == JOINT else 16
        if len(self.target) != n or not np.all(np.isfinite(self.target)):
            raise InputError(
                f"Move {self.name!r}: target of a {self.kind} move must be {n} finite numbers"
            )
        if (
            not np.isfinite(self.speed)
            or self.speed <= 0
            or (self.kind == JOINT and self.speed > 1)
        ):
            allowed = "(0, 1] (fraction of max joint speed)" if self.kind == JOINT else "> 0 m/s"
            raise InputError(f"Move {self.name!r}: speed {self.speed!r} must be in {allowed}")
        if not np.isfinite(self.zone) or self.zone < 0:
            raise InputError(f"Move {self.name!r}: zone {self.zone!r} must be >= 0 m (0 = fine)")

    @classmethod
    def joint(cls, q: ArrayLike, *, speed: float = 1.0, zone: float = 0.0, name: str = "") -> Move:
        """Return a joint move to joints `q` (6,) [rad]."""
        return cls(
            JOINT, tuple(float(x) for x in np.asarray(q, float).reshape(-1)), speed, zone, name
        )

    @classmethod
    def linear(
        cls, T_base_tcp: ArrayLike, *, speed: float = 0.25, zone: float = 0.0, name: str = ""
    ) -> Move:
        """Return a linear move to the pose `T_base_tcp` (4, 4) [m]."""
        T = check_transform(T_base_tcp, f"Move {name!r}: T_base_tcp")
        return cls(LINEAR, tuple(float(x) for x in T.reshape(-1)), speed, zone, name)

    @property
    def q(self) -> NDArray[np.float64]:
        """Return the joint target (6,) [rad] of a joint move."""
        return np.array(self.target) if self.kind == JOINT else np.full(6, np.nan)

    @property
    def T(self) -> NDArray[np.float64]:
        """Return the pose target T_base_tcp (4, 4) [m] of a linear move."""
        return (
            np.array(self.target).reshape(4, 4) if self.kind == LINEAR else np.full((4, 4), np.nan)
        )


@dataclass(frozen=True)
class Program:
    """A named list of moves; `name` must be a valid identifier on every controller."""

    name: str
    moves: tuple[Move, ...]

    def __post_init__(self) -> None:
        if not self.name.isidentifier() or len(self.name) > 24:
            raise InputError(
                f"Program.name {self.name!r} must be an identifier of at most 24 characters"
            )
        if not self.moves:
            raise InputError("Program.moves is empty; add at least one move")


class ProgramMove(Protocol):
    """A move of a program (the project's `MoveSI` is one): `type` "joint" or "linear"; target
    `joints` (dof,) [rad, model] or `T_world_tcp` (4, 4) [m]; `speed` a fraction (joint) or
    [m/s] (linear); `zone` [m]; `wobj` the work object's name."""

    name: str
    type: str
    joints: FloatArray | None
    T_world_tcp: FloatArray | None
    speed: float
    zone: float
    wobj: str
    configuration: TargetConfiguration | None


Item: TypeAlias = "ProgramMove | Action"


def is_action(item: object) -> bool:
    """Return True for an action item (it has no target pose), False for a move."""
    return not hasattr(item, "T_world_tcp")


def program_moves(items: Sequence[Item]) -> list[tuple[int, ProgramMove]]:
    """Return the moves of `items` with their indices among the items."""
    return [(i, it) for i, it in enumerate(items) if not is_action(it)]  # type: ignore[misc]


def stop_zones(items: Sequence[Item]) -> list[float]:
    """Return each move's zone [m]: its own, or 0 where an action other than a comment follows
    it before the next move."""
    from workbench.motion.programs.controller_program import Comment  # noqa: PLC0415

    zones = []
    for i, mv in program_moves(items):
        stop = False
        for nxt in items[i + 1 :]:
            if not is_action(nxt):
                break
            stop = stop or not isinstance(nxt, Comment)
        zones.append(0.0 if stop else float(mv.zone))
    return zones


def nearest_ik(
    model: RobotModel, T_base_flange: FloatArray, q_near: FloatArray, where: str
) -> FloatArray:
    """Return the IK solution (dof,) [rad] of a flange pose nearest `q_near` (the planner's one
    rule for a pose's joints); UnreachableError names `where`."""
    try:
        sols = np.asarray(model.ik(T_base_flange, q_near=q_near), float)
    except UnreachableError as exc:
        raise exc.within(where) from exc
    if len(sols) == 0:
        raise UnreachableError(f"{where}: no IK solution within the joint limits")
    return np.asarray(sols[0], float)


def _where(index: int, mv: ProgramMove, prefix: str) -> str:
    return f"{prefix}[{index}]" + (f" ({mv.name})" if mv.name else "")


def pose_joints(
    model: RobotModel, mv: ProgramMove, T_base_flange: FloatArray, q_near: FloatArray, where: str
) -> FloatArray:
    """Return the joints (dof,) [rad] of a pose target: the IK solution in its stored
    configuration (a tie at a singular wrist broken towards `q_near`), or without one the
    solution nearest `q_near` (`nearest_ik`); UnreachableError names `where`."""
    conf = getattr(mv, "configuration", None)
    if conf is None:
        return nearest_ik(model, T_base_flange, q_near, f"{where}.pose")
    return solve_configuration(
        model, T_base_flange, conf, q_near=q_near, where=f"{where}.configuration"
    )


def program_start(
    items: Sequence[Item],
    model: RobotModel,
    T_world_base: FloatArray,
    T_flange_tcp: FloatArray,
    q_reference: FloatArray,
    *,
    field: str = "program.moves",
) -> FloatArray:
    """Return where a program without start joints starts (dof,) [rad]: its first move's target,
    the joints of a joint target or the IK solution of a pose in its stored configuration;
    a pose without one takes the solution nearest `q_reference` [rad] (a fixed posture, e.g.
    the joints the project file stores: never the robot's current, jogged joints). The first
    move then plans as a zero-length move."""
    moves_in = program_moves(items)
    if not moves_in:
        raise InputError(f"{field}: the program has no moves; add at least one")
    if len(moves_in) == 1:
        raise InputError(
            "a program of one move without start joints starts at its target and does not move;"
            " give 'program.start' [deg] (where the robot starts) or add a move",
            field="program.start",
        )
    i, mv = moves_in[0]
    if mv.joints is not None:
        return np.asarray(mv.joints, float)
    assert mv.T_world_tcp is not None
    T_base_flange = (
        invert_transform(np.asarray(T_world_base, float))
        @ mv.T_world_tcp
        @ invert_transform(np.asarray(T_flange_tcp, float))
    )
    q_ref = np.asarray(q_reference, float)
    return pose_joints(model, mv, T_base_flange, q_ref, _where(i, mv, field))


def motion_program(
    name: str,
    items: Sequence[Item],
    model: RobotModel,
    T_world_base: FloatArray,
    T_flange_tcp: FloatArray,
    q_start: FloatArray,
    *,
    field: str = "program.moves",
) -> Program:
    """Return the motion `Program` the planner runs for `items`: linear moves to the pose in the
    base frame, joint moves to their joints or to the pose's IK solution in its stored
    configuration, else nearest the previous joint target (`pose_joints`), zones from
    `stop_zones`.

    InputError names the item (`field`[i]) whose joints are of the wrong length or outside the
    limits [deg]; UnreachableError the pose without an IK solution.
    """
    moves_in = program_moves(items)
    if not moves_in:
        raise InputError(f"{field}: the program has no moves; add at least one")
    T_base_world = invert_transform(np.asarray(T_world_base, float))
    T_tcp_flange = invert_transform(np.asarray(T_flange_tcp, float))
    lo, hi = model.limits[:, 0], model.limits[:, 1]
    moves, q_prev = [], np.asarray(q_start, float)
    for (i, mv), zone in zip(moves_in, stop_zones(items), strict=True):
        where = _where(i, mv, field)
        if mv.joints is not None:
            q = np.asarray(mv.joints, float)
            if q.shape != (model.dof,):
                raise InputError(f"{where}.joints: expected {model.dof} values [deg], got {len(q)}")
            bad = np.flatnonzero((q < lo) | (q > hi))
            if bad.size:
                # Said in the controller's values: what the project file and the GUI show.
                j, conv = int(bad[0]), model.convention
                qc, lim = conv.to_controller(q), conv.limits_to_controller(model.limits)
                raise InputError(
                    f"{where}.joints[{j}]: {np.degrees(qc[j]):g} deg is outside the joint"
                    f" limits [{np.degrees(lim[j, 0]):.1f}, {np.degrees(lim[j, 1]):.1f}] deg;"
                    " move it inside"
                )
            moves.append(Move.joint(q, speed=mv.speed, zone=zone, name=mv.name))
            q_prev = q
            continue
        assert mv.T_world_tcp is not None
        T_base_tcp = T_base_world @ mv.T_world_tcp
        if mv.type == "linear":
            moves.append(Move.linear(T_base_tcp, speed=mv.speed, zone=zone, name=mv.name))
            continue
        q_prev = pose_joints(model, mv, T_base_tcp @ T_tcp_flange, q_prev, where)
        moves.append(Move.joint(q_prev, speed=mv.speed, zone=zone, name=mv.name))
    return Program(name, tuple(moves))


def planned_configurations(
    items: Sequence[Item],
    target_joints: Sequence[FloatArray],
    model: RobotModel,
    *,
    field: str = "program.moves",
) -> list[tuple[int, TargetConfiguration]]:
    """Return (item index, configuration) of every pose target as planned: `target_joints` are
    the planned joints (dof,) [rad] at each move's target, in order (`RobotProgram.moves`).

    A linear move runs on from where the arm is, so it cannot choose its target's configuration;
    where it arrives in another configuration than the one its target stores, a controller
    would stop (ABB's ConfL), so PlanningError names the target's field and the fix."""
    out = []
    for (i, mv), q in zip(program_moves(items), target_joints, strict=True):
        if mv.T_world_tcp is None:
            continue
        got = target_configuration(model, q)
        stored = getattr(mv, "configuration", None)
        if (
            stored is not None
            and mv.type == LINEAR
            and (stored.arm != got.arm or stored.turns[: model.dof] != got.turns)
        ):
            raise PlanningError(
                f"the line arrives at its target in {got.label()}, but the target stores"
                f" {stored.label()}: reach it with a joint move, or clear its configuration",
                field=f"{field}[{i}].configuration",
            )
        out.append((i, got))
    return out
