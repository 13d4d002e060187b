"""Where the gripper holds the part: a flange, a point on it and a yaw; the TCP frame there.

SI units. The TCP sits on the gripped flange's top face (z = +t/2 in the flange frame),
its z axis into the sheet, rotated by `yaw` about the flange normal; with `face` −1 on the
bottom face (z = −t/2), its z axis into the sheet (the flange's +z).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import make_transform, rot_x, rot_z
from workbench.sheetmetal.part import SheetMetalPart


@dataclass(frozen=True, eq=False)
class Grasp:
    """The gripped flange's name, the grasp point (2,) [m] in its polygon frame (None: its
    centroid), the gripper's yaw [rad] about the flange normal and the `face` it holds (+1:
    the flange's +z face, −1: its −z face)."""

    flange: str
    offset: NDArray[np.float64] | None = None
    yaw: float = 0.0
    face: int = 1


def grasp_point(part: SheetMetalPart, grasp: Grasp) -> NDArray[np.float64]:
    """Return the grasp point (2,) [m] in the gripped flange's polygon frame."""
    if grasp.offset is not None:
        return np.asarray(grasp.offset, float)
    poly = part.flanges[part.flange_index(grasp.flange)].polygon
    c = shapely.Polygon(poly).centroid
    return np.array([c.x, c.y])


def T_flange_grasp(part: SheetMetalPart, grasp: Grasp) -> NDArray[np.float64]:
    """Return the TCP pose (4, 4) [m] in the gripped flange's frame: on the gripped face (top:
    z = +t/2, bottom: z = −t/2), z into the sheet."""
    off = grasp_point(part, grasp)
    side = 1.0 if grasp.face > 0 else -1.0
    R = rot_z(grasp.yaw) @ (rot_x(np.pi) if side > 0 else np.eye(3))
    return make_transform(R, [off[0], off[1], side * part.thickness / 2])


def T_part_grasp(part: SheetMetalPart, grasp: Grasp, step: int) -> NDArray[np.float64]:
    """Return the TCP pose (4, 4) [m] in the part frame after `step` bends of the sequence."""
    state = part.fold(step)
    g = part.flange_index(grasp.flange)
    return state.T_part_flange[g] @ T_flange_grasp(part, grasp)  # type: ignore[no-any-return]


def check_flange(part: SheetMetalPart, flange: str, where: str = "grasp.flange") -> None:
    """Raise InputError naming `where` and the flanges when the part has no flange `flange`."""
    names = [f.name for f in part.flanges]
    if flange not in names:
        raise InputError(f"no flange {flange!r}; flanges are {names}", field=where)


def checked_grasp(
    part: SheetMetalPart, flange: str, offset: ArrayLike | None = None, yaw: float = 0.0
) -> Grasp:
    """Return the grasp of `flange` at `offset` (2,) [m] (None: centroid), `yaw` [rad].

    InputError names the field: an unknown flange, an offset that is not two finite numbers
    or lies outside the flange, a yaw that is not finite.
    """
    check_flange(part, flange)
    off = None
    if offset is not None:
        off = np.asarray(offset, float)
        if off.shape != (2,) or not np.all(np.isfinite(off)):
            raise InputError(f"grasp.offset: expected 2 finite numbers [m], got {offset!r}")
        poly = shapely.Polygon(part.flanges[part.flange_index(flange)].polygon)
        if not poly.buffer(1e-9).contains(shapely.Point(*off)):
            raise InputError(
                f"grasp.offset: ({off[0] * 1e3:.1f}, {off[1] * 1e3:.1f}) mm lies outside flange "
                f"{flange!r}; pick a point on it"
            )
    if not np.isfinite(yaw):
        raise InputError(f"grasp.yaw: must be finite, got {yaw!r}")
    return Grasp(flange, off, float(yaw))
