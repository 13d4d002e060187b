"""The press brake's die: where the part lies for each bend, and the robot's pose holding it there.

SI units. The die frame has x along the bend line, z up (towards the punch), the robot on
its -y side. For bend `step` of the sequence the part is folded by the `step` bends before
it; the middle of the bend zone lies on the die's x axis, centred, the sheet's outer side on
the die, and the gripped flange on the robot's side.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.aabb import world_aabb
from workbench.geometry.transforms import invert_transform, make_transform, rot_z
from workbench.pressbrake.grasp import Grasp, T_flange_grasp, T_part_grasp
from workbench.sheetmetal.part import SheetMetalPart


@dataclass(frozen=True, eq=False)
class Die:
    """The die's bend-line frame `T_world_die` (4, 4) [m] and its `length` [m].

    `length_field` names the length in error messages (e.g. the project field).
    """

    T_world_die: NDArray[np.float64]
    length: float
    length_field: str = "die.length"


@dataclass(frozen=True, eq=False)
class DiePlacement:
    """The robot holding the part with bend `bend` (sequence index `step`) on the die."""

    bend: str
    step: int
    T_world_part: NDArray[np.float64]  # (4, 4) [m]
    T_world_tcp: NDArray[np.float64]  # (4, 4) [m]
    q: NDArray[np.float64]  # (dof,) [rad]


def bend_on_die(step: float, n_bends: int) -> int:
    """Return the sequence index of the bend on the die while the part is folded to `step`.

    A fractional step (a bend partway) is the bend being made; the folded part (step =
    n_bends) stays on the die for the last bend.
    """
    return min(int(np.floor(step + 1e-9)), n_bends - 1)


def die_part_pose(part: SheetMetalPart, step: int, die: Die, grasp: Grasp) -> NDArray[np.float64]:
    """Return T_world_part (4, 4) [m] with bend number `step` of the sequence on the die.

    Raises InputError when `step` is out of range or the bend line is longer than the die.
    """
    if not 0 <= step < len(part.bends):
        raise InputError(f"step: must be in 0..{len(part.bends) - 1}, got {step}")
    b = part.bends[step]
    if part.bend_lengths[step] > die.length + 1e-9:
        raise InputError(
            f"bend {b.name!r}: its bend line is {part.bend_lengths[step] * 1e3:.1f} mm long; the "
            f"die is {die.length * 1e3:g} mm ({die.length_field}): it does not fit"
        )
    state = part.fold(step)
    geo = state.bend_cross_section(step)
    w = geo["w"]
    mid = (geo["pa"] + geo["pb"]) / 2 + geo["n"] * part.bend_allowances[step] / 2
    T_parent_line = make_transform(
        np.column_stack([geo["d"], np.cross(w, geo["d"]), w]), mid - w * part.thickness / 2
    )
    T_part_line = state.T_part_flange[b.parent] @ T_parent_line
    g = part.flange_index(grasp.flange)
    T_part_tcp = state.T_part_flange[g] @ T_flange_grasp(part, grasp)
    if (invert_transform(T_part_line) @ T_part_tcp)[1, 3] > 0:
        T_part_line = T_part_line @ make_transform(rot_z(np.pi), np.zeros(3))
    return die.T_world_die @ invert_transform(T_part_line)  # type: ignore[no-any-return]


def die_targets(
    part: SheetMetalPart, die: Die, grasp: Grasp
) -> tuple[list[NDArray[np.float64]], NDArray[np.float64], list[str]]:
    """Return each bend's T_world_part, the TCP poses (B, 4, 4) [m] holding it there, and names."""
    steps = range(len(part.bends))
    T_part = [die_part_pose(part, s, die, grasp) for s in steps]
    T_tcp = np.array([T_part[s] @ T_part_grasp(part, grasp, s) for s in steps])
    names = [f"bend {part.bends[s].name!r} (step {s + 1}) on the die" for s in steps]
    return T_part, T_tcp, names


def die_placements(
    part: SheetMetalPart,
    T_world_part: list[NDArray[np.float64]],
    T_world_tcp: NDArray[np.float64],
    q: NDArray[np.float64],
) -> tuple[DiePlacement, ...]:
    """Return the placements of every bend from `die_targets` and the joints (B, dof) reaching them."""
    return tuple(
        DiePlacement(part.bends[s].name, s, T_world_part[s], T_world_tcp[s], q[s])
        for s in range(len(part.bends))
    )


def die_boxes(part: SheetMetalPart, die: Die, grasp: Grasp) -> list[NDArray[np.float64]]:
    """Return world boxes (2, 3) [m] (lo, hi) of the flat part on the die for its first bend
    and of the die's bend line: what a view of the bending frames."""
    T_world_part = die_part_pose(part, 0, die, grasp)
    flat = world_aabb(part.fold(0.0).solid().vertices, T_world_part)
    ends = np.array([[-die.length / 2, 0, 0, 1], [die.length / 2, 0, 0, 1]]) @ die.T_world_die.T
    return [flat, world_aabb(ends[:, :3])]
