"""The polishing robot program (issue 12 part 4) against its plan: planned joints at the kept
targets, durations from the trajectory, the path within the chordal tolerance, the force offset
in the targets, and the RAPID and KRL posts read back."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.motion.programs.controller_program import Comment, MoveInstr
from workbench.motion.programs.krl import write_krl
from workbench.motion.programs.krl_read import read_krl
from workbench.motion.programs.rapid import write_rapid
from workbench.motion.programs.rapid_read import read_rapid
from workbench.polishing.program import CHORD_TOLERANCE, thin_path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from example_plans import planned  # noqa: E402
from program_round_trip import check_read_back  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def _chord_distances(P: np.ndarray, i: int, j: int) -> np.ndarray:
    """Distances of P[i+1:j] from segment P[i]P[j], by dense sampling of the segment (a twin of
    the closed-form projection)."""
    s = np.linspace(0.0, 1.0, 20001)
    seg = P[i] + s[:, None] * (P[j] - P[i])
    return np.array([np.min(np.linalg.norm(seg - p, axis=1)) for p in P[i + 1 : j]])


def _fewest_moves(P: np.ndarray, Z: np.ndarray, tol: float) -> int:
    """Return the fewest linear moves (brute-force dynamic programming over every chord) that
    keep every point within `tol` of its chord."""
    n = len(P)
    best = np.full(n, np.inf)
    best[0] = 0
    for j in range(1, n):
        for i in range(j):
            if best[i] + 1 < best[j] and (j - i < 2 or _chord_distances(P, i, j).max() <= tol):
                best[j] = best[i] + 1
    return int(best[-1])


@pytest.mark.parametrize(
    ("n", "tol"),
    [
        (21, 1e-3),  # chords span about 3 of the 20 steps: a representative case, ~0.5 s
        pytest.param(61, 0.05e-3, marks=pytest.mark.slow),  # the fine circle: ~17 s of twin
    ],
)
def test_thinning_keeps_a_circle_within_the_tolerance_with_the_fewest_moves(
    n: int, tol: float
) -> None:
    R = 0.1
    a = np.linspace(0.0, np.pi / 2, n)
    P = np.column_stack([R * np.cos(a), R * np.sin(a), np.zeros_like(a)])
    Z = np.tile([0.0, 0.0, 1.0], (len(a), 1))
    kept = thin_path(P, Z, tol=tol, angle_tol=1.0)
    for i, j in zip(kept[:-1], kept[1:], strict=True):
        if j - i > 1:
            assert _chord_distances(P, int(i), int(j)).max() <= tol + 1e-9
    assert len(kept) - 1 == _fewest_moves(P, Z, tol) < n - 1  # and some points were dropped
    # closed form: a chord of sagitta tol spans 2 acos(1 - tol/R); 90 deg needs at least this many
    assert len(kept) - 1 >= np.ceil((np.pi / 2) / (2 * np.arccos(1 - tol / R)))
    # a straight line is one move; a forced index splits it
    line = np.column_stack([np.linspace(0, 1, 11), np.zeros(11), np.zeros(11)])
    Zl = np.tile([0.0, 0.0, 1.0], (11, 1))
    assert list(thin_path(line, Zl)) == [0, 10]
    assert list(thin_path(line, Zl, (4,))) == [0, 4, 10]


def test_thinning_keeps_the_tool_axis_within_its_angle() -> None:
    P = np.column_stack([np.linspace(0, 0.1, 21), np.zeros(21), np.zeros(21)])
    t = np.radians(np.linspace(0.0, 10.0, 21)) ** 2 * 10  # a non-uniform turn of the axis
    Z = np.column_stack([np.sin(t), np.zeros(21), np.cos(t)])
    kept = thin_path(P, Z, angle_tol=np.radians(0.5))
    assert len(kept) > 2
    with pytest.raises(InputError):
        thin_path(P, Z, tol=0.0)


@pytest.fixture(scope="module")
def polished() -> tuple:
    # the polishing cell's plan and program, once per session (tests/example_plans.py: the
    # export and read-back matrices read the same ones); these tests only read them
    wb, (prog,) = planned("polishing_cell.json", "polishing")
    return wb, wb.polishing.last_motion, prog


def test_program_reproduces_the_planned_path_joints_and_times(polished: tuple) -> None:
    wb, plan, prog = polished
    traj = plan.trajectory
    q_plan, t_plan = traj.waypoints, traj.waypoint_times
    moves = prog.moves
    assert moves[0].kind == "joint" and all(m.kind == "linear" for m in moves[1:])
    assert len(moves) < len(q_plan) / 2  # thinned
    # each kept target holds the planned joints of one waypoint, in order
    idx = [int(np.argmin(np.abs(q_plan - m.target.q).max(axis=1))) for m in moves]
    for m, k in zip(moves, idx, strict=True):
        assert np.abs(q_plan[k] - m.target.q).max() == 0.0
    assert idx[0] == 0 and idx[-1] == len(q_plan) - 1 and np.all(np.diff(idx) > 0)
    for m, a, b in zip(moves[1:], idx[:-1], idx[1:], strict=True):
        assert abs(m.duration - (t_plan[b] - t_plan[a])) < 1e-12
    process_time = sum(m.duration for m in moves[1:])
    assert abs(process_time - plan.cycle_time) <= 0.01 * plan.cycle_time
    # every planned TCP point lies within the tolerance of its move's chord
    tool = prog.tool(moves[0].tool)
    P = (wb.robot.fk(q_plan) @ tool.T_flange_tcp)[:, :3, 3]
    for a, b in zip(idx[:-1], idx[1:], strict=True):
        if b - a > 1:
            assert _chord_distances(P, a, b).max() <= CHORD_TOLERANCE + 1e-9


def test_targets_carry_the_force_offset_and_the_force_is_in_a_comment(polished: tuple) -> None:
    wb, plan, prog = polished
    pp = wb.polishing.last_path
    si = wb.polishing.si
    D = si.force / si.control.stiffness
    assert D == pytest.approx(20.0 / 5000.0)  # seed 004: F = 20 N, k = 5000 N/m
    wobj = prog.work_object(prog.moves[0].wobj)
    T_world_base = wb.setup.T_world_base
    checked = 0
    for m in prog.moves[1:]:
        k = int(m.name.lstrip("lead_inoutp"))
        if not pp.path.is_process[k]:
            continue
        T_world = T_world_base @ wobj.T_base_wobj @ m.target.T_wobj_tcp
        want = pp.path.points[k] - D * pp.path.normals[k]  # D into the surface
        assert np.linalg.norm(T_world[:3, 3] - want) < 1e-6
        checked += 1
    assert checked > 100
    texts = [c.text for c in prog.instructions if isinstance(c, Comment)]
    assert any("F = 20 N" in t and "D = F/k = 4.000 mm" in t for t in texts)
    first = next(
        i for i, c in enumerate(prog.instructions) if isinstance(c, Comment) and "press" in c.text
    )
    assert isinstance(prog.instructions[first + 1], MoveInstr)


@pytest.mark.parametrize("write, read", [(write_rapid, read_rapid), (write_krl, read_krl)])
def test_rapid_and_krl_read_back(polished: tuple, write, read) -> None:  # noqa: ANN001
    wb, _, prog = polished
    out = write(prog)
    check_read_back(prog, read(out.files), wb.robot)
    text = "\n".join(out.files.values())
    assert "20 N" in text and "4.000 mm" in text
