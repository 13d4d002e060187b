"""`ProgramEditor`: teaching and editing the project's program, with undo and redo.

Every edit builds the new program, validates the whole project with it (the pydantic models
and `program_io.check_references`, through `project_from_dict`) and only then replaces the
program; a refused edit raises a `WorkbenchError` naming the field (``program.moves[3].speed``)
and the old program stays. Targets are taught in the project's units: the TCP pose through
`project.units.matrix_to_pose`, the joints as the project stores them (the controller's).

The editor of a workbench (`editor(wb)`) lives as long as its project: opening or importing
another project starts a new one with an empty history. It also knows whether the latest
motion plan was planned before the latest edit (`plan_is_stale`); exports then plan again.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from workbench.errors import InputError, ProjectError
from workbench.kinematics.target_configuration import target_configuration
from workbench.motion.program import planned_configurations
from workbench.project import bounds as B
from workbench.project.io import project_from_dict
from workbench.project.program_io import ACTION_ITEMS, program_items, wobj_names
from workbench.project.target_configuration import ConfigurationSpec
from workbench.project.units import matrix_to_pose

if TYPE_CHECKING:
    from workbench.service.motion_plan import MotionPlan
    from workbench.service.workbench import Workbench

TARGET_KINDS = {
    "linear": "a linear move to the current TCP pose",
    "joint": "a joint move to the current TCP pose",
    "joints": "a joint move to the current joints",
}
"""What `add_target` adds, by kind."""
MOVE_FIELDS = ("name", "type", "speed", "zone", "wobj")
"""The fields of a move `update_item` is meant for (the targets are taught, not typed)."""
ACTION_TYPES = tuple(ACTION_ITEMS)
"""The actions `insert_action` inserts: gripper, set_output, pulse_output, wait_input, wait, comment."""
MAX_HISTORY = 200
"""Edits kept for undo."""
_NEVER = object()  # no edit yet: no plan is stale


@dataclass(frozen=True)
class PlannedTimes:
    """The latest plan's times: per program item the planned duration [s] of a move (None for
    an action, or for every item when the plan is `stale`), and the plan's cycle time [s]."""

    durations: tuple[float | None, ...]
    cycle_time: float
    stale: bool


def store_configurations(wb: Workbench, plan: MotionPlan) -> None:
    """Store in each pose target of the program that has none the arm configuration it was
    planned in (`planned_configurations`), so that the next plan solves it the same; a linear
    target reached in another configuration than it stores raises PlanningError naming it."""
    project = wb._project  # not `wb.project`: the jog joints stay out of the file here
    if project.program is None:
        return
    items = program_items(project, wb.robot.convention)
    joints = [mv.target.q for mv in wb.robot_programs("motion", plan)[0].moves]
    for i, conf in planned_configurations(items, joints, wb.robot):
        move = project.program.moves[i]
        if move.configuration is None:
            move.configuration = ConfigurationSpec.of(conf)


def editor(wb: Workbench) -> ProgramEditor:
    """Return the program editor of `wb`'s open project (one per project, made on first use)."""
    return wb._workflow("program_editor", ProgramEditor)  # type: ignore[no-any-return]


class ProgramEditor:
    """Edits of one workbench's program; every edit can be undone and redone."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
        self._lock = threading.RLock()
        self._undo: list[dict[str, Any] | None] = []
        self._redo: list[dict[str, Any] | None] = []
        self._stale_plan: object = _NEVER

    # -- state --------------------------------------------------------------------------------
    @property
    def items(self) -> list[Any]:
        """Return the program's items in order (moves and actions, the project's models)."""
        program = self.wb.project.program
        return [] if program is None else list(program.moves)

    def item(self, i: int) -> Any:
        """Return item `i` (0-based); InputError naming the index when there is none."""
        return self.items[self._index(i)]

    @property
    def can_undo(self) -> bool:
        """Return True when there is an edit to undo."""
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        """Return True when there is an undone edit to redo."""
        return bool(self._redo)

    def allowed(self, i: int, field: str) -> str:
        """Return the range move `i`'s `field` ("speed" or "zone") may take, with its unit: the
        project's bounds, as an edit checks them ("(0, 100] %" for a joint move's speed)."""
        item = self.item(i)
        if field == "zone":
            (lo, hi), unit, left = B.ZONE_MM, "mm", "["
        elif field == "speed" and getattr(item, "type", None) == "joint":
            (lo, hi), unit, left = B.JOINT_MOVE_PERCENT_OPEN, "% of the joints' maximum speed", "("
        elif field == "speed" and getattr(item, "type", None) == "linear":
            (lo, hi), unit, left = B.LINEAR_SPEED_MM_S, "mm/s", "["
        else:
            raise InputError(f"program.moves[{i}]: {field!r} is not a number of this item")
        return f"{left}{lo:g}, {hi:g}] {unit}"

    def work_objects(self) -> list[str]:
        """Return the names a move's `wobj` may take ("base" first)."""
        return wobj_names(self.wb.project)

    def plan_is_stale(self, plan: MotionPlan | None = None) -> bool:
        """Return True when `plan` (default: the latest) was planned before the latest edit."""
        plan = plan if plan is not None else self.wb.last_plan
        return plan is not None and plan is self._stale_plan

    def planned_times(self) -> PlannedTimes | None:
        """Return the latest plan's move durations and cycle time (None before a plan)."""
        plan = self.wb.last_plan
        if plan is None:
            return None
        items = self.items
        if self.plan_is_stale(plan):
            return PlannedTimes((None,) * len(items), plan.cycle_time, True)
        moves = iter(self.wb.robot_programs("motion", plan)[0].moves)
        durations = [
            None if getattr(it, "type", None) in ACTION_ITEMS else next(moves).duration
            for it in items
        ]
        return PlannedTimes(tuple(durations), plan.cycle_time, False)

    # -- edits --------------------------------------------------------------------------------
    def add_target(self, kind: str, at: int | None = None, *, name: str | None = None) -> int:
        """Insert the robot's current TCP pose or joints as a move before item `at` (default: at
        the end) and return its index. `kind`: "linear" or "joint" (a move to the TCP pose),
        "joints" (a joint move to the joints). The name defaults to the first free targetN."""
        if kind not in TARGET_KINDS:
            raise InputError(f"target kind: {kind!r} is not one of {', '.join(TARGET_KINDS)}")
        project = self.wb.project  # stores the current joints (controller's, deg) in the file
        move: dict[str, Any] = {"name": name or self._free_name(), "speed": 100.0}
        if kind == "joints":
            move |= {"type": "joint", "joints": list(project.robot.joints or ())}
        else:
            pose = matrix_to_pose(self.wb.tcp_pose())
            pose = pose.model_copy(
                update={"xyz": [_tidy(v) for v in pose.xyz], "rpy": [_tidy(v) for v in pose.rpy]}
            )
            conf = ConfigurationSpec.of(target_configuration(self.wb.robot, self.wb.joints))
            move |= {"type": kind, "pose": pose.model_dump(mode="json")}
            move["configuration"] = conf.model_dump(mode="json")
        moves = self._dumps()
        k = len(moves) if at is None else self._slot(at, len(moves))
        moves.insert(k, move)
        self._apply(moves)
        return k

    def update_item(self, i: int, **fields: Any) -> None:
        """Change fields of item `i`: a move's name, type, speed, zone or wobj ("base": the
        robot base), an action's own fields (signal, value, seconds, text, ...)."""
        moves = self._dumps()
        k = self._index(i, len(moves))
        if "wobj" in fields and fields["wobj"] in ("base", ""):
            fields["wobj"] = None  # the default: the file leaves it out
        moves[k] = {key: v for key, v in (moves[k] | fields).items() if v is not None}
        self._apply(moves)

    def insert_action(self, i: int, item: dict[str, Any]) -> int:
        """Insert an action (a program item such as {"type": "gripper", "action": "close"})
        before item `i` (`len(items)`: at the end); return its index."""
        if not isinstance(item, dict) or item.get("type") not in ACTION_ITEMS:
            got = item.get("type") if isinstance(item, dict) else type(item).__name__
            raise InputError(f"action type: {got!r} is not one of {', '.join(ACTION_ITEMS)}")
        moves = self._dumps()
        k = self._slot(i, len(moves))
        moves.insert(k, dict(item))
        self._apply(moves)
        return k

    def move_item(self, i: int, delta: int) -> int:
        """Move item `i` by `delta` places (-1: up, +1: down) and return its new index."""
        moves = self._dumps()
        k = self._index(i, len(moves))
        j = k + int(delta)
        if not 0 <= j < len(moves):
            where = "up: it is the first item" if j < 0 else "down: it is the last item"
            raise InputError(f"program.moves[{k}]: cannot move it {where}")
        moves.insert(j, moves.pop(k))
        self._apply(moves)
        return j

    def delete_item(self, i: int) -> None:
        """Delete item `i`."""
        moves = self._dumps()
        del moves[self._index(i, len(moves))]
        self._apply(moves)

    def undo(self) -> None:
        """Undo the latest edit (InputError when there is none)."""
        with self._lock:
            if not self._undo:
                raise InputError("undo: nothing to undo in this session")
            self._restore(self._undo, self._redo)

    def redo(self) -> None:
        """Redo the latest undone edit (InputError when there is none)."""
        with self._lock:
            if not self._redo:
                raise InputError("redo: nothing to redo")
            self._restore(self._redo, self._undo)

    # -- internals ------------------------------------------------------------------------------
    def _program_dump(self) -> dict[str, Any] | None:
        program = self.wb.project.program
        return None if program is None else program.model_dump(mode="json", exclude_none=True)

    def _dumps(self) -> list[dict[str, Any]]:
        program = self._program_dump()
        return [] if program is None else list(program["moves"])

    def _index(self, i: int, n: int | None = None) -> int:
        n = len(self.items) if n is None else n
        if isinstance(i, bool) or not isinstance(i, int) or not 0 <= i < n:
            raise InputError(
                f"program.moves[{i}]: no such item; the program has {n} item(s)"
                + (f" (0 to {n - 1})" if n else "")
            )
        return i

    def _slot(self, at: int, n: int) -> int:
        if isinstance(at, bool) or not isinstance(at, int) or not 0 <= at <= n:
            raise InputError(f"insert at {at!r}: must be 0 to {n} (the program has {n} item(s))")
        return at

    def _free_name(self) -> str:
        used = {getattr(it, "name", None) for it in self.items}
        return next(f"target{k}" for k in range(1, len(used) + 2) if f"target{k}" not in used)

    def _apply(self, moves: list[dict[str, Any]]) -> None:
        with self._lock:
            old = self._program_dump()
            new = dict(old or {"name": "main"}) | {"moves": moves}
            self._set(new)
            self._undo.append(old)
            del self._undo[:-MAX_HISTORY]
            self._redo.clear()

    def _restore(self, source: list[dict[str, Any] | None], target: list[Any]) -> None:
        current = self._program_dump()
        self._set(source[-1])
        source.pop()
        target.append(current)

    def _set(self, program: dict[str, Any] | None) -> None:
        """Validate the project with `program` and make it the project's (or raise, unchanged)."""
        project = self.wb.project
        data = project.model_dump(mode="json", exclude_none=True)
        data.pop("program", None)
        if program is not None:
            data["program"] = program
        try:
            checked = project_from_dict(data, source="program")
        except ProjectError as exc:  # each problem names its field and what is allowed
            problems = [
                msg if path == "(top level)" else f"{path}: {msg}" for path, msg in exc.problems
            ]
            raise InputError("; ".join(problems) or str(exc)) from None
        stale = self.wb.last_plan
        project.program = checked.program
        self._stale_plan = stale


def _tidy(v: float) -> float:
    """Return `v` without float noise (430.00000000000006 -> 430.0; the file keeps 1e-6)."""
    r = round(v, 6)
    return 0.0 if r == 0 else r
