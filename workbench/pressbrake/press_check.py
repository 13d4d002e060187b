"""The part against the press brake and the cell while one bend is made (SI units).

Broad phase: the part's OBB tree (seed 000) against every obstacle, batched over frames.
Narrow phase where the tree hits: a cell box is exact already (the tree's verdict stands, as
on the transfer); a cylinder or mesh of the cell is confirmed by `obstacles.confirm_exact`;
the press's tools (punch, die, fingers: the part lies on them, so their contact is the
process) are confirmed against the folded part's exact solid with python-fcl (its surface,
plus a containment test of one vertex), because a flange's box is raised by the bend's rise
over the whole flange and would meet a punch whose flank is a degree off the flange.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import fcl
import numpy as np
from numpy.typing import NDArray

from workbench.collision.shapes import bvh_model, fcl_transform
from workbench.pressbrake.obstacles import Obstacles, confirm_exact, winding_number
from workbench.sheetmetal.folding import FoldedState

F64 = NDArray[np.float64]

#: Obstacle names of the press's tools (their hits are confirmed on the exact solid).
TOOLS = ("punch", "die", "back-gauge finger")


def is_tool(name: str) -> bool:
    """Return whether obstacle `name` is one of the press's tools."""
    return name.startswith(TOOLS)


@dataclass(frozen=True)
class PartHit:
    """The first collision of a frame: the flanges and obstacles (names) that touch."""

    frame: int
    flanges: tuple[str, ...]
    obstacles: tuple[str, ...]

    def describe(self) -> str:
        """Return "flange '3' hits the punch" in words."""
        fl = ", ".join(repr(f) for f in self.flanges) or "the part"
        obs = ", ".join(dict.fromkeys(self.obstacles))
        return f"flange {fl} hits the {obs}" if self.flanges else f"the part hits the {obs}"


def _solid_hits(state: FoldedState, T_world_part: F64, obstacles: Obstacles, idx: int) -> bool:
    solid = state.__dict__.get("_solid_fcl")
    if solid is None:
        mesh = state.solid()
        solid = (bvh_model(mesh.vertices, mesh.faces), mesh.vertices[0].copy())
        object.__setattr__(state, "_solid_fcl", solid)
    model, vertex = solid
    box = obstacles.boxes[idx]
    shape = obstacles.exact[idx]
    a = fcl.CollisionObject(model, fcl_transform(T_world_part))
    if shape is None:
        geom = fcl.Box(*(2.0 * np.asarray(box.half_extents, float)))
        b = fcl.CollisionObject(
            geom, fcl.Transform(np.asarray(box.rotation), np.asarray(box.center))
        )
    else:
        b = fcl.CollisionObject(shape.geometry, fcl_transform(shape.T_world))
    if fcl.collide(a, b, fcl.CollisionRequest()) > 0:
        return True
    p = (T_world_part[:3, :3] @ vertex + T_world_part[:3, 3])[None]
    if shape is None:
        return bool(box.contains(p)[0])
    return shape.mesh is not None and bool(winding_number(shape.mesh, p)[0] > 0.5)


#: Frames `check_states` checks between two progress reports (each about 0.1 s here).
PROGRESS_FRAMES = 100


def frame_hits(
    state: FoldedState, T_world_part: F64, obstacles: Obstacles
) -> list[tuple[int, int, int]]:
    """Return (frame, flange, obstacle) index triples where the part folded as `state`, at
    the poses `T_world_part` (F, 4, 4) [m], touches `obstacles`: its OBB tree batched over
    the frames; the cell's non-box shapes and the press's tools confirmed exactly."""
    T = np.asarray(T_world_part, float)
    tree = state.obb_tree(0)
    Tg = T @ state.T_part_flange[0]
    rep = confirm_exact(tree, tree.collide_frames(obstacles.boxes, Tg), obstacles, Tg)
    return [
        (int(f), int(fl), int(o))
        for f, fl, o in rep.hits
        if not is_tool(obstacles.names[int(o)]) or _solid_hits(state, T[int(f)], obstacles, int(o))
    ]


def check_states(
    states: Sequence[FoldedState],
    T_world_part: F64,
    obstacles: Sequence[Obstacles],
    progress: Callable[[int], None] | None = None,
) -> list[PartHit | None]:
    """Return, per frame, the first collision of the part (None when free).

    Frame i: the part folded as `states[i]` at `T_world_part[i]` (4, 4) [m] among
    `obstacles[i]` (what the press and cell are at that instant). `progress(frames done)`
    every `PROGRESS_FRAMES` frames.
    """
    out: list[PartHit | None] = []
    for state, T, obs in zip(states, T_world_part, obstacles, strict=True):
        if progress is not None and len(out) % PROGRESS_FRAMES == 0:
            progress(len(out))
        keep = [(fl, o) for _, fl, o in frame_hits(state, T[None], obs)]
        if not keep:
            out.append(None)
            continue
        names = [fl.name for fl in state.part.flanges]
        out.append(
            PartHit(
                len(out),
                tuple(dict.fromkeys(names[f] for f, _ in keep)),
                tuple(obs.names[o] for _, o in keep),
            )
        )
    return out


def frames_report(hits: Sequence[PartHit | None]) -> NDArray[np.bool_]:
    """Return (F,) True where a frame collides."""
    return np.array([h is not None for h in hits], dtype=bool)
