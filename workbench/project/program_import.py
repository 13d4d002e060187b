"""A robot program written elsewhere (read back by a reader) turned into the project's program
section (mm, deg): moves, actions, the signals and work objects they use, and the tool.

`imported_project(project, read, joints)` returns a new project dict and the notes a user must
see: every line the reader did not understand (by line), every value the project could not
take as it was (a circular move, a time-only joint move, signals without numbers, a work object
or tool that differs from the project's). Nothing is dropped without a note.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.motion.programs.controller_program import (
    Comment,
    PulseOutput,
    ReadMove,
    ReadProgram,
    SetOutput,
    SyncPoint,
    WaitInput,
    WaitTime,
)
from workbench.project.common import Pose
from workbench.project.program_io import BASE_WOBJ
from workbench.project.target_configuration import ConfigurationSpec
from workbench.project.units import matrix_to_pose, pose_to_matrix, to_deg, to_mm

if TYPE_CHECKING:
    from workbench.kinematics.joint_convention import JointConvention
    from workbench.kinematics.target_configuration import TargetConfiguration
    from workbench.project.models import Project

FloatArray = NDArray[np.float64]

_IDENTITY_WOBJS = ("wobj0", "base", "world", "$WORLD", "BASE_DATA[0]")


@dataclass(frozen=True)
class ImportResult:
    """The project with the imported program (`data`, a project dict) and the notes."""

    data: dict[str, Any]
    notes: tuple[str, ...]


def _pose(T: FloatArray) -> dict[str, list[float]]:
    p = matrix_to_pose(T)
    return {"xyz": [float(v) for v in p.xyz], "rpy": [float(v) for v in p.rpy]}


def _same(Ta: FloatArray, Tb: FloatArray) -> bool:
    if np.linalg.norm(Ta[:3, 3] - Tb[:3, 3]) > 1e-5:
        return False
    c = (np.trace(Ta[:3, :3].T @ Tb[:3, :3]) - 1.0) / 2.0
    return bool(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))) < 0.01)


class _Signals:
    """The project's io signals, extended by the ones the program uses."""

    def __init__(self, io: dict[str, Any], notes: list[str]) -> None:
        self.io = io
        self.notes = notes

    def name(self, kind: str, name: str, number: int) -> str:
        items = self.io.setdefault(kind, [])
        other = self.io.setdefault("inputs" if kind == "outputs" else "outputs", [])
        for s in items:
            if s["name"] == name or (not name and s["number"] == number):
                return str(s["name"])
        label = name or f"{'do' if kind == 'outputs' else 'di'}_{number}"
        if any(s["name"] == label for s in other):
            label = f"{label}_{kind[:-1]}"
        used = {s["number"] for s in items}
        if number <= 0 or number in used:
            number = max(used, default=0) + 1
            self.notes.append(
                f"io.{kind}: {label!r} has no number in the program; numbered {number} (set the"
                " controller's number in the project)"
            )
        items.append({"name": label, "number": int(number)})
        return label


def _move_items(
    mv: ReadMove,
    q_model: FloatArray,
    convention: JointConvention,
    T_world_wobj: FloatArray,
    notes: list[str],
    configuration: TargetConfiguration | None = None,
) -> list[dict[str, Any]]:
    where = f"line {mv.line} ({mv.name})"
    zone = float(to_mm(mv.zone))
    wobj = None if mv.wobj in _IDENTITY_WOBJS else mv.wobj
    if mv.kind == "joint":
        joints = [float(v) for v in to_deg(convention.to_controller(q_model))]
        if mv.speed is None:
            notes.append(
                f"{where}: a joint move given by its time only ({mv.duration} s); planned at 100 %"
                " of the joint speeds"
            )
        speed = 100.0 if mv.speed is None else float(mv.speed) * 100.0
        item: dict[str, Any] = {"name": mv.name, "type": "joint", "joints": joints}
        item.update(speed=min(speed, 100.0), zone=zone)
        if wobj:
            item["wobj"] = wobj
        return [item]
    assert mv.speed is not None
    out = []
    targets = [mv.target] if mv.via is None else [mv.via, mv.target]
    if mv.via is not None:
        notes.append(
            f"{where}: a circular move is imported as two linear moves (through its via point to"
            " its end); the planner has no circular interpolation yet"
        )
    for tgt in targets:
        if tgt.T_wobj_tcp is None:
            raise InputError(f"a {mv.kind} move needs a Cartesian target", field=where)
        item = {"name": tgt.name, "type": "linear", "pose": _pose(T_world_wobj @ tgt.T_wobj_tcp)}
        item.update(speed=float(to_mm(mv.speed)), zone=zone)
        if configuration is not None and tgt is mv.target:  # the via's is chosen by the plan
            item["configuration"] = ConfigurationSpec.of(configuration).model_dump(mode="json")
        if wobj:
            item["wobj"] = wobj
        out.append(item)
    return out


def imported_project(
    project: Project,
    read: ReadProgram,
    joints: list[FloatArray],
    convention: JointConvention,
    *,
    source: str,
    configurations: list[TargetConfiguration] | None = None,
) -> ImportResult:
    """Return the project with `read` as its program (replacing the old one).

    `joints` (dof,) [rad, model] per move: the targets as the controller reaches them
    (`motion.programs.readback.solve_moves`), written as controller degrees for joint moves.
    The program's `start` stays (a program file states none). Linear targets keep their pose
    (world, via their work object) and, from `configurations`
    (the `TargetConfiguration` of each move's `joints`: what the program's confdata, Status/Turn
    or CONFIG selected), their arm configuration. The program's main tool
    (the one most moves use) becomes the project's tool when it differs, with a note.
    """
    notes = [
        f"{source}: line {n}: {text!r} is not understood; it was left out"
        for n, text in read.unknown
    ]
    notes += [f"{source}: {n}" for n in read.notes]
    data = project.model_dump(mode="json", exclude_none=True)
    T_world_base = pose_to_matrix(project.robot.base)
    moves = read.moves
    if not moves:
        lines = "; ".join(f"line {n}: {t!r}" for n, t in read.unknown[:5])
        raise InputError(
            f"{source}: the program has no moves the reader understood"
            + (f" (not understood: {lines})" if lines else "")
        )
    # the tool most moves use
    main_tool = Counter(m.tool for m in moves).most_common(1)[0][0]
    tool = next(t for t in read.tools if t.name == main_tool)
    if not _same(tool.T_flange_tcp, pose_to_matrix(project.tool.tcp)):
        data["tool"]["tcp"] = _pose(tool.T_flange_tcp)
        notes.append(
            f"tool: the program's tool {main_tool!r} replaces the project's TCP (its targets are"
            " TCP poses of that tool)"
        )
    if tool.mass is not None:
        data["tool"]["mass"] = float(tool.mass)
    if tool.cog is not None:
        data["tool"]["cog"] = [float(v) for v in to_mm(tool.cog)]
    others = sorted({m.tool for m in moves} - {main_tool})
    if others:
        notes.append(
            f"tool: moves with {others} are planned with {main_tool!r} (the project has one tool);"
            " their joint targets are exact, their linear paths are those of the main tool's TCP"
        )
    # work objects
    wobjs = {w["name"]: w for w in data.setdefault("work_objects", [])}
    T_wobj: dict[str, FloatArray] = {}
    for w in read.work_objects:
        T_world_wobj = T_world_base @ w.T_base_wobj
        T_wobj[w.name] = T_world_wobj
        if w.name in _IDENTITY_WOBJS or w.name == BASE_WOBJ:
            continue
        if w.name in wobjs and not _same(pose_to_matrix(project_pose(wobjs[w.name])), T_world_wobj):
            notes.append(f"work_objects: {w.name!r} takes the program's frame (it differed)")
        if w.name not in wobjs or w.name in {m.wobj for m in moves}:
            wobjs[w.name] = {"name": w.name, "pose": _pose(T_world_wobj)}
    data["work_objects"] = list(wobjs.values())
    # moves and actions, in order
    signals = _Signals(data.setdefault("io", {}), notes)
    items: list[dict[str, Any]] = []
    q_iter = iter(joints)
    c_iter = iter(configurations if configurations is not None else [None] * len(joints))
    for ins in read.instructions:
        if isinstance(ins, ReadMove):
            conf = next(c_iter)
            items += _move_items(ins, next(q_iter), convention, T_wobj[ins.wobj], notes, conf)
        elif isinstance(ins, SetOutput):
            name = signals.name("outputs", ins.signal.name, ins.signal.number)
            items.append({"type": "set_output", "signal": name, "value": ins.value})
        elif isinstance(ins, PulseOutput):
            name = signals.name("outputs", ins.signal.name, ins.signal.number)
            items.append({"type": "pulse_output", "signal": name, "duration": ins.duration})
        elif isinstance(ins, WaitInput):
            name = signals.name("inputs", ins.signal.name, ins.signal.number)
            item = {"type": "wait_input", "signal": name, "value": ins.value}
            if ins.timeout is not None:
                item["timeout"] = ins.timeout
            items.append(item)
        elif isinstance(ins, WaitTime):
            items.append({"type": "wait", "seconds": ins.seconds})
        elif isinstance(ins, Comment):
            items.append({"type": "comment", "text": ins.text[:200]})
        elif isinstance(ins, SyncPoint):
            notes.append(
                f"sync point {ins.name!r} (with {', '.join(ins.robots)}): a one-robot project has"
                " no partner; kept as a comment"
            )
            items.append({"type": "comment", "text": f"sync {ins.name}"})
    program = {"name": _program_name(read.name), "moves": items}
    if (data.get("program") or {}).get("start") is not None:  # the cell's start stays
        program["start"] = data["program"]["start"]
    data["program"] = program
    return ImportResult(data, tuple(notes))


def project_pose(w: dict[str, Any]) -> Pose:
    """Return a work object dict's pose as the project's `Pose`."""
    return Pose.model_validate(w.get("pose", {}))


def _program_name(name: str) -> str:
    clean = "".join(c if c.isalnum() or c == "_" else "_" for c in name)[:24] or "main"
    return clean if clean[0].isalpha() or clean[0] == "_" else "p_" + clean[:22]
