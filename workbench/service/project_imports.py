"""Bringing the user's own cell into the open project: a robot of the library, an obstacle from a
CAD or mesh file, a sheet-metal part from a STEP or DXF file.

Each import edits a copy of the project's JSON, validates it as a whole (`project_from_dict`,
errors name the field) and switches the workbench to it: on any error the project stays as it
was. The domain does the reading (`workbench.cad`, `workbench.sheetmetal`); the project layer
turns its result into the part section (`workbench.project.part_import`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pydantic import ValidationError

from workbench.errors import InputError
from workbench.kinematics.robot_library import LIBRARY, library_robot
from workbench.project import project_from_dict
from workbench.project.common import Pose
from workbench.project.part_import import (
    PartImportSpec,
    cad_kind,
    import_part,
    part_import_settings,
)

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


@dataclass(frozen=True)
class RobotChoice:
    """A robot of the library as the GUI lists it: preset name, title, vendor, native format."""

    name: str
    title: str
    vendor: str
    program_format: str
    payload_kg: float
    reach_mm: float

    @property
    def label(self) -> str:
        """Return the dropdown text, e.g. 'ABB IRB 1200-7/0.7 (7 kg, 703 mm, rapid)'."""
        return f"{self.title} ({self.payload_kg:g} kg, {self.reach_mm:g} mm, {self.program_format})"


def robot_choices() -> list[RobotChoice]:
    """Return the robots of the library, in its order."""
    return [
        RobotChoice(r.name, r.title, r.vendor, r.program_format, r.payload_kg, r.reach_mm)
        for r in LIBRARY.values()
    ]


def _data(wb: Workbench) -> dict[str, Any]:
    """Return the project as the JSON it saves as (a copy to edit)."""
    return wb.project.model_dump(mode="json", exclude_none=True)


def _switch(wb: Workbench, data: dict[str, Any], source: str) -> None:
    wb.replace_project(project_from_dict(data, source=source))


def use_robot(wb: Workbench, preset: str) -> None:
    """Make the project's robot the library's `preset` at the same base, in its home posture.

    The name, base, TCP-speed and zone limits stay; per-joint rates and link meshes belonged to
    the old robot and go. Joint values stored elsewhere (joint moves, program start) stay as
    they are, read in the new controller's convention: the plan refuses one outside the new
    robot's limits, naming its field.
    """
    robot = library_robot(preset)  # InputError listing the names
    data = _data(wb)
    old = data["robot"]
    data["robot"] = {
        k: v for k, v in old.items() if k in ("name", "base", "max_tcp_speed", "max_zone")
    }
    data["robot"]["preset"] = robot.name
    data["robot"]["joints"] = [float(v) for v in robot.home_deg]
    _switch(wb, data, f"robot {robot.title}")


def add_cell_file(
    wb: Workbench, path: Path, *, name: str | None = None, xyz_mm: list[float] | None = None
) -> str:
    """Add the mesh or STEP file `path` (an allowed folder's) to the cell as an obstacle at
    `xyz_mm` [mm, world] (default the origin); return the object's name (the file's stem, made
    unique)."""
    data = _data(wb)
    objects = data.setdefault("cell", {}).setdefault("objects", [])
    taken = {o.get("name") for o in objects}
    base = name or Path(path).stem or "obstacle"
    unique, i = base, 2
    while unique in taken:
        unique, i = f"{base}_{i}", i + 1
    obj: dict[str, Any] = {"name": unique, "shape": "mesh", "path": str(path)}
    if xyz_mm is not None:
        obj["pose"] = {"xyz": list(xyz_mm), "rpy": [0.0, 0.0, 0.0]}
    objects.append(obj)
    _switch(wb, data, f"cell object {unique}")
    return unique


def obstacle_coordinate(axis: int, value_mm: float) -> float:
    """Return coordinate `axis` (0 x, 1 y, 2 z) [mm] of an obstacle's position, checked by the
    project's bounds for a pose (`cell.objects[].pose.xyz`); InputError naming the field."""
    xyz = [0.0, 0.0, 0.0]
    xyz[axis] = value_mm
    try:
        return float(Pose(xyz=xyz).xyz[axis])
    except ValidationError as exc:
        raise InputError(
            f"cell.objects[].pose.xyz[{axis}]: {value_mm:g} mm: {exc.errors()[0]['msg']}"
        ) from None


def import_settings(settings: dict[str, Any], name: str = "") -> PartImportSpec:
    """Return the CAD part settings (`bending.part_import`'s fields, mm) checked for a file
    called `name` (a DXF's bend layer only for a .dxf); ProjectError names a bad field."""
    given = dict(settings)
    if cad_kind(name) != "DXF":
        given.pop("bend_layer", None)
    return part_import_settings(given)


def import_bending_part(wb: Workbench, name: str, data: bytes, settings: dict[str, Any]) -> str:
    """Make the part recognised in CAD file `data` (a STEP of the bent part or a DXF flat
    pattern, by `name`'s ending) the bending section's part; return its summary.

    `settings` are `bending.part_import`'s fields [mm]: the sheet's `thickness` (a DXF does not
    say it; a STEP is checked against it), the bends' `inner_radius` where the file does not
    say it, the DXF's `bend_layer`. The part is stored inline (flanges and bends in mm/deg), so
    the project keeps it without the uploaded file; the bend order, the steps and the plan
    belonged to the old part and go, and the grasp moves to the new part's base flange.
    """
    bending = wb.project.bending
    if bending is None:
        raise InputError(
            "import part: the project has no 'bending' section (die, grasp, press); open a"
            " press-brake example (e.g. u_channel_cell.json) and import the part there"
        )
    spec = import_part(data, name, import_settings(settings, name), where=name)
    data_ = _data(wb)
    section = data_["bending"]
    for key in ("part_file", "part_import", "sequence", "steps"):
        section.pop(key, None)
    section["part"] = spec.model_dump(mode="json", exclude_none=True)
    section.setdefault("grasp", {})["flange"] = spec.flanges[0].name
    _switch(wb, data_, f"part {name}")
    return f"{spec.note}; thickness {spec.thickness:g} mm"
