"""A sample robot program (every move kind, every action, several arm configurations and turns,
a tool and a work object that are not identities) and the read-back check every post passes.

The check is the twin of a post + reader pair: it re-solves every Cartesian target the reader
returns through the tool, the work object and the stored configuration data (as the
controller's IK would), and compares with the joints the planner chose.
"""

from __future__ import annotations

import numpy as np

from workbench.geometry.transforms import invert_transform, make_transform, rpy_to_matrix
from workbench.kinematics.arm_configuration import arm_configuration
from workbench.kinematics.model import RobotModel
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    MoveInstr,
    PulseOutput,
    ReadProgram,
    RobotProgram,
    SetOutput,
    Signal,
    SyncPoint,
    Target,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.motion.programs.first_move import FIRST_MOVE_SPEED, safe_start
from workbench.motion.programs.readback import solve_moves

DEG = np.pi / 180.0

# planned joints [deg, model convention]: different configurations, J4/J6 beyond +-180 deg
SAMPLE_JOINTS_DEG = {
    "home": [0.0, 0.0, 0.0, 0.0, -90.0, 0.0],
    "p_pick": [10.0, -20.0, 30.0, 40.0, -60.0, 200.0],
    "p_via": [-5.0, -10.0, 25.0, 20.0, -70.0, 150.0],
    "p_place": [-30.0, 10.0, 60.0, -100.0, -120.0, -250.0],
    "p_far": [100.0, -60.0, 120.0, 185.0, -30.0, 10.0],
    "p_flip": [20.0, -5.0, 40.0, -20.0, 15.0, -30.0],
    "p_back": [29.0, 46.0, 83.0, -51.0, -102.0, -95.0],
}


def sample_tool() -> ToolData:
    """Return a tool 150 mm out and 40 mm aside, tilted 30 deg about x; 2.5 kg."""
    T = make_transform(rpy_to_matrix(np.array([30.0, 0.0, 10.0]) * DEG), [0.04, 0.0, 0.15])
    return ToolData("gripper", T, mass=2.5, cog=np.array([0.01, 0.0, 0.08]))


def sample_wobj() -> WorkObject:
    """Return a work object 600 mm in front of the robot, 200 mm up, turned 25 deg about z."""
    T = make_transform(rpy_to_matrix(np.array([0.0, 0.0, 25.0]) * DEG), [0.6, -0.1, 0.2])
    return WorkObject("fixture", T)


def sample_program(
    model: RobotModel | None = None, name: str = "demo"
) -> tuple[RobotProgram, RobotModel]:
    """Return (program, model): every move kind, every action, two tools, two work objects."""
    model = model or preset_robot("mz07")
    tool = sample_tool()
    flange = ToolData("flange", np.eye(4), mass=0.1, cog=np.zeros(3))
    wobj = sample_wobj()
    base = WorkObject("base", np.eye(4))

    def cart(name: str, t: ToolData = tool, w: WorkObject = wobj) -> Target:
        q = np.array(SAMPLE_JOINTS_DEG[name]) * DEG
        T = invert_transform(w.T_base_wobj) @ model.fk(q) @ t.T_flange_tcp
        return Target(name, q, T, arm_configuration(model, q))

    def joint(name: str) -> Target:
        return Target(name, np.array(SAMPLE_JOINTS_DEG[name]) * DEG)

    out = Signal("do_grip", 3)
    closed = Signal("di_closed", 4)
    ins = (
        Comment("sample program: every move kind and action"),
        MoveInstr("joint", joint("home"), 0.6, 0.0, "gripper", "fixture", 1.25),
        MoveInstr("joint", cart("p_pick"), 0.5, 0.02, "gripper", "fixture", 0.9),
        MoveInstr("linear", cart("p_place"), 0.25, 0.0, "gripper", "fixture", 2.0),
        Gripper(True, out, True, closed, 2.0, 0.2),
        MoveInstr(
            "circular", cart("p_far"), 0.1, 0.0, "gripper", "fixture", 3.5, via=cart("p_via")
        ),
        SetOutput(Signal("do_blow", 5), True),
        WaitTime(0.5),
        PulseOutput(Signal("do_blow", 5), 0.3),
        WaitInput(Signal("di_part", 6), True, 5.0),
        SyncPoint("sync_1", ("demo", "other"), Signal("do_sync", 7), Signal("di_sync", 8)),
        MoveInstr("linear", cart("p_flip", flange, base), 0.05, 0.01, "flange", "base", 1.0),
        MoveInstr("joint", cart("p_back", flange, base), 0.8, 0.0, "flange", "base", 1.7),
        Gripper(False, out, False, None, None, 0.1),
        MoveInstr("joint", joint("home"), 1.0, 0.0, "gripper", "fixture", 1.5),
    )
    prog = RobotProgram(name, (tool, flange), (wobj, base), ins, model.convention, model.dof, "r1")
    return prog, model


def _angle(Ra: np.ndarray, Rb: np.ndarray) -> float:
    c = (np.trace(Ra.T @ Rb) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


def _same_signal(a: Signal, b: Signal, by: str) -> bool:
    return a.number == b.number if by == "number" else a.name == b.name


def _same_action(a, b, by: str) -> bool:  # noqa: ANN001
    if type(a) is not type(b):
        return False
    if isinstance(a, SetOutput):
        return _same_signal(a.signal, b.signal, by) and a.value == b.value
    if isinstance(a, PulseOutput):
        return _same_signal(a.signal, b.signal, by) and abs(a.duration - b.duration) < 1e-6
    if isinstance(a, WaitInput):
        t_ok = (a.timeout is None) == (b.timeout is None) and (
            a.timeout is None or abs(a.timeout - b.timeout) < 1e-6
        )
        return _same_signal(a.signal, b.signal, by) and a.value == b.value and t_ok
    if isinstance(a, WaitTime):
        return abs(a.seconds - b.seconds) < 1e-6
    if isinstance(a, SyncPoint):
        return a.name == b.name
    raise AssertionError(f"unexpected action {a!r}")


def check_read_back(
    program: RobotProgram,
    read: ReadProgram,
    model: RobotModel,
    *,
    signals_by: str = "name",
    joint_tol: float = 1e-6,
    check_durations: bool = True,
    check_speeds: bool = True,
    zone_tol: float = 1e-4,
    joint_zones: bool = True,
    zones: list[float] | None = None,
) -> None:
    """Assert that `read` (a reader's result on a post's output of `program`) is `program`:

    - the same number and kinds of moves, with the same tool and work object poses;
    - every target re-solved through tool, work object and configuration data equals the
      planned joints (`joint_tol` rad), and FK of the planned joints with the tool equals the
      read target in its work object (0.01 mm, 0.01 deg);
    - the low-level actions equal the plan's, in order (signals compared by `signals_by`);
    - each move's duration (where the program states one) or speed equals the plan's;
    - each zone equals the plan's within `zone_tol` [m] (FANUC's CR has 1 mm steps: 1e-3);
      with `joint_zones` False (FANUC: a blended joint move is CNT100, a speed percentage
      with no radius) a joint move reads as blended-of-no-size (0) exactly where it is blended;
      `zones` [m] replaces the plan's zones where the post must write others (URScript's blends
      cut so that they never overlap, `urscript.blend_radii`).
    """
    assert not read.unknown, f"the reader did not understand: {read.unknown}"
    # every post writes the first move safe (untimed, bounded speed, exact stop): compare with that
    program = safe_start(program)
    planned, got = program.moves, read.moves
    assert [m.kind for m in got] == [m.kind for m in planned]
    joints = solve_moves(read, model)
    for k, (mv, rm, q) in enumerate(zip(planned, got, joints, strict=True)):
        where = f"move {k} ({mv.name})"
        tool = program.tool(mv.tool)
        wobj = program.work_object(mv.wobj)
        rtool = next(t for t in read.tools if t.name == rm.tool)
        rwobj = next(w for w in read.work_objects if w.name == rm.wobj)
        assert np.allclose(rtool.T_flange_tcp[:3, 3], tool.T_flange_tcp[:3, 3], atol=1e-5), where
        assert _angle(rtool.T_flange_tcp[:3, :3], tool.T_flange_tcp[:3, :3]) < 0.01, where
        assert np.allclose(rwobj.T_base_wobj[:3, 3], wobj.T_base_wobj[:3, 3], atol=1e-5), where
        assert _angle(rwobj.T_base_wobj[:3, :3], wobj.T_base_wobj[:3, :3]) < 0.01, where
        assert np.max(np.abs(q - mv.target.q)) < joint_tol, (where, np.degrees(q - mv.target.q))
        if mv.target.cartesian:
            T_planned = (
                invert_transform(wobj.T_base_wobj) @ model.fk(mv.target.q) @ tool.T_flange_tcp
            )
            T_read = rm.target.T_wobj_tcp
            assert T_read is not None, where
            assert np.linalg.norm(T_read[:3, 3] - T_planned[:3, 3]) < 1e-5, where
            assert _angle(T_read[:3, :3], T_planned[:3, :3]) < 0.01, where
        zone = mv.zone if zones is None else zones[k]
        if joint_zones or mv.kind != "joint":
            assert abs(rm.zone - zone) < zone_tol, (where, rm.zone, zone)
        else:
            assert rm.zone == 0.0, (where, rm.zone)
        if any(m.force for m in got):  # a format with force control: every move's force
            assert abs(rm.force - mv.force) < 1e-9, (where, rm.force, mv.force)
        if k == 0:  # reached from anywhere: no stated time; a stated speed is the bounded one
            assert rm.duration is None, (where, rm.duration)
            assert rm.speed is None or rm.speed <= FIRST_MOVE_SPEED + 1e-9, (where, rm.speed)
        elif check_durations and rm.duration is not None:
            assert abs(rm.duration - mv.duration) <= 0.01 * mv.duration + 1e-3, where
        elif check_speeds:
            assert rm.speed is not None, where
            assert abs(rm.speed - mv.speed) <= 0.01 * mv.speed, (where, rm.speed, mv.speed)
    want, have = program.actions(), read.actions()
    assert len(want) == len(have), (want, have)
    for a, b in zip(want, have, strict=True):
        assert _same_action(a, b, signals_by), (a, b)
