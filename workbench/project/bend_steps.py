"""The project file's bend process models: the grasp, and each bend's grasp and tool station.

`bending.grasp` (a `GraspSpec`) holds the part for every bend unless `bending.steps` gives one
`BendStepSpec` per bend in sequence order; `step_problems` checks those steps against the
press's stations and the part's bends and flanges.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal

import numpy as np
from pydantic import Field

from workbench.pressbrake.grasp import Grasp
from workbench.project.common import Angle, Coordinate, Loc, StrictModel
from workbench.project.units import DEG, MM


class GraspSpec(StrictModel):
    """Where the gripper holds the part: a flange, an offset in its plane [mm, deg], a face."""

    flange: str = "1"
    offset: Annotated[list[Coordinate], Field(min_length=2, max_length=2)] | None = None
    # [x, y] mm in the flange's polygon frame; None = the polygon's centroid
    yaw: Angle = 0.0  # deg, gripper rotation about the flange normal
    face: Literal["top", "bottom"] = "top"  # the flange's face held: top = its +z face

    def to_si(self) -> Grasp:
        """Return the grasp in SI: offset [m] (None: the centroid), yaw [rad], face +1/-1."""
        off = None if self.offset is None else np.asarray(self.offset, float) * MM
        return Grasp(self.flange, off, self.yaw * DEG, 1 if self.face == "top" else -1)

    def set_si(self, grasp: Grasp, *, keep_yaw: bool = False) -> None:
        """Store `grasp` (SI) in this section (mm, deg); `keep_yaw` leaves the yaw as it is."""
        self.flange = grasp.flange
        self.offset = None if grasp.offset is None else [float(v / MM) for v in grasp.offset]
        if not keep_yaw:
            self.yaw = float(grasp.yaw / DEG)
        self.face = "top" if grasp.face > 0 else "bottom"


class BendStepSpec(StrictModel):
    """One bend of the process: its grasp and tool station (None: the press's first)."""

    bend: str
    grasp: GraspSpec
    station: str | None = None

    def to_si(self, first: str) -> BendStepSI:
        """Return the step in SI; a step without `station` takes `first` (the first station)."""
        return BendStepSI(self.bend, self.grasp.to_si(), self.station or first)


@dataclass(frozen=True, eq=False)
class BendStepSI:
    """One bend of the process in SI: the bend's name, its grasp and its tool station's name."""

    bend: str
    grasp: Grasp
    station: str


def step_problems(
    steps: list[BendStepSpec],
    stations: list[str],
    seq: list[str] | None = None,
    flanges: list[str] | None = None,
) -> list[tuple[Loc, str, object]]:
    """Return the problems of `steps` (locations in the `bending` section): unknown
    `stations`; with the sequence in use `seq` and the part's `flanges`, bends not in
    sequence order and unknown flanges."""
    out: list[tuple[Loc, str, object]] = []
    for i, st in enumerate(steps):
        if st.station is not None and st.station not in stations:
            out.append(
                (
                    ("steps", i, "station"),
                    f"no station {st.station!r}; stations are {stations}",
                    st.station,
                )
            )
    if seq is None or flanges is None:
        return out
    for i, st in enumerate(steps):
        if i >= len(seq):
            out.append(
                (
                    ("steps", i, "bend"),
                    f"one step more than the {len(seq)} bends of the sequence in use {seq}; "
                    "remove it",
                    st.bend,
                )
            )
        elif st.bend != seq[i]:
            out.append(
                (
                    ("steps", i, "bend"),
                    f"expected {seq[i]!r}, got {st.bend!r}: the steps list every bend once, "
                    f"in the order of the sequence in use {seq}",
                    st.bend,
                )
            )
        if st.grasp.flange not in flanges:
            out.append(
                (
                    ("steps", i, "grasp", "flange"),
                    f"no flange {st.grasp.flange!r}; flanges are {flanges}",
                    st.grasp.flange,
                )
            )
    if len(steps) < len(seq):
        out.append(
            (
                ("steps",),
                f"{len(steps)} step(s) for {len(seq)} bends; add one for each of "
                f"{seq[len(steps) :]}, in sequence order",
                len(steps),
            )
        )
    return out
