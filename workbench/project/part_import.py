"""Parts from CAD: `bending.part_file` naming a STEP (.step/.stp) or DXF (.dxf) file.

A STEP file holds the bent part as a solid: its faces are recognised as flanges and bends
(`workbench.sheetmetal.from_solid`). A DXF holds the flat pattern: the blank's outline and
bend lines on the `bend_layer` (`workbench.cad.dxf`, `workbench.cad.flat_pattern`). Either
becomes the same `PartSpec` (mm/deg) as a part JSON: flanges "F1", "F2", .., bends "B1", ..
The optional section `bending.part_import` (mm) sets what the file does not say::

    "part_import": {"thickness": 2, "bend_layer": "BEND", "inner_radius": 2,
                    "k_factor": 0.4, "base": "F2"}

- `thickness` [mm]: needed for a DXF; for a STEP it must match the solid's own (0.001 mm);
- `bend_layer`: the DXF layer of the bend lines (default `DEFAULT_BEND_LAYER`, "BEND"; DXF
  only; a STEP accepts the default, which saves before 2026-12 wrote into every part_import);
- `inner_radius` [mm]: a DXF's bends without their own; for a STEP it must match every bend;
- `k_factor`: K for every bend (default: Table 1 from r/t);
- `base`: the flange whose frame is the part frame (STEP; default: the largest flange).
"""

from __future__ import annotations

from os import PathLike
from pathlib import PurePath
from typing import TYPE_CHECKING, Annotated, Any

import numpy as np
from pydantic import Field, ValidationError

from workbench.errors import ProjectError
from workbench.project import bounds as B
from workbench.project.common import StrictModel
from workbench.project.units import DEG, MM

CAD_SUFFIXES = {".step": "STEP", ".stp": "STEP", ".dxf": "DXF"}
"""Part file endings read as CAD (anything else is a part JSON)."""
if TYPE_CHECKING:
    from workbench.project.bending import PartSpec

MATCH_MM = 1e-3  # a setting that restates the STEP's own thickness or radius, within this
DEFAULT_BEND_LAYER = "BEND"


class PartImportSpec(StrictModel):
    """`bending.part_import`: what a CAD part file does not say [mm]; see the module docstring."""

    thickness: Annotated[float, B.span(B.THICKNESS_MM, "mm")] | None = None
    bend_layer: Annotated[str, Field(min_length=1, max_length=255)] | None = None  # DXF only
    inner_radius: Annotated[float, B.span(B.INNER_RADIUS_MM, "mm")] | None = None
    k_factor: Annotated[float, Field(ge=0, le=1)] | None = None
    base: Annotated[str, Field(min_length=1, max_length=64)] | None = None

    @property
    def layer(self) -> str:
        """Return the DXF layer of the bend lines: `bend_layer`, or `DEFAULT_BEND_LAYER`."""
        return self.bend_layer if self.bend_layer is not None else DEFAULT_BEND_LAYER


def cad_kind(path: str | None) -> str | None:
    """Return "STEP" or "DXF" for a CAD part file name, None for a part JSON (or no path)."""
    if path is None:
        return None
    return CAD_SUFFIXES.get(PurePath(path).suffix.lower())


def _setting(field: str, message: str, prefix: str = "bending.part_import") -> ProjectError:
    return ProjectError(message, field=f"{prefix}.{field}")


def _flange_mm(f: dict[str, Any], mm: Any) -> dict[str, Any]:
    """Return flange `f` (SI spec) in mm; `holes` only when it has any (older files unchanged)."""
    out: dict[str, Any] = {
        "name": str(f["name"]),
        "polygon": [[mm(x), mm(y)] for x, y in f["polygon"]],
    }
    if f.get("holes"):
        out["holes"] = [[[mm(x), mm(y)] for x, y in h] for h in f["holes"]]
    return out


def part_spec_from_si(spec: dict[str, Any], *, name: str, note: str, where: str) -> PartSpec:
    """Return the `PartSpec` (mm/deg) of SI part `spec` (`SheetMetalPart.from_spec`'s form).

    Lengths are rounded to 1e-6 mm and angles to 1e-9 deg (noise of the CAD kernel, far below
    the model's 1e-3 mm edge-length check). ProjectError names `where` if it is invalid.
    """
    from workbench.project.bending import PartSpec

    def mm(v: Any) -> float:
        return round(float(v) / MM, 6)

    bends = []
    for b in spec["bends"]:
        if "bend_angle" in b:
            included = np.pi - float(b["bend_angle"])
        else:
            included = float(b["included_angle"])
        r = b.get("inner_radius")
        bend = {
            "name": str(b["name"]),
            "parent": str(b["parent"]),
            "parent_edge": int(b["parent_edge"]),
            "child": str(b["child"]),
            "child_edge": int(b["child_edge"]),
            "included_angle": round(included / DEG, 9),
            "inner_radius": None if r is None else mm(r),
            "direction": {1: "up", -1: "down"}.get(b.get("direction", "up"), b.get("direction")),
        }
        if b.get("k_factor") is not None:
            bend["k_factor"] = float(b["k_factor"])
        bends.append(bend)
    data = {
        "name": name,
        "note": note,
        "thickness": mm(spec["thickness"]),
        "k_factor": spec.get("k_factor"),
        "flanges": [_flange_mm(f, mm) for f in spec["flanges"]],
        "bends": bends,
    }
    if spec.get("sequence") is not None:
        data["sequence"] = [str(s) for s in spec["sequence"]]
    return PartSpec.checked(data, where, where)


def _from_step(data: bytes, name: str, settings: PartImportSpec, where: str) -> dict[str, Any]:
    from workbench.cad.step import read_step_sheet
    from workbench.errors import InputError
    from workbench.sheetmetal.from_solid import recognise_part

    if settings.bend_layer not in (None, DEFAULT_BEND_LAYER):
        raise _setting("bend_layer", f"only for a DXF part file; {name!r} is a STEP: remove it")
    brep = read_step_sheet(data, name, where)
    try:
        spec = recognise_part(brep, where=where, base=settings.base).spec
    except InputError as exc:
        raise ProjectError.of(exc.within("bending.part_import")) from exc
    t = spec["thickness"] / MM
    if settings.thickness is not None and abs(settings.thickness - t) > MATCH_MM:
        raise _setting(
            "thickness",
            f"{settings.thickness:g} mm, but the sheet in {name!r} is {t:.4g} mm thick;"
            " remove the setting (a STEP gives its own) or fix it",
        )
    if settings.inner_radius is not None:
        for b in spec["bends"]:
            r = b["inner_radius"] / MM
            if abs(settings.inner_radius - r) > MATCH_MM:
                raise _setting(
                    "inner_radius",
                    f"{settings.inner_radius:g} mm, but bend {b['name']} in {name!r} has"
                    f" {r:.4g} mm; remove the setting (a STEP gives its own radii) or fix it",
                )
    if settings.k_factor is not None:
        spec["k_factor"] = settings.k_factor
    return spec


def _from_dxf(data: bytes, name: str, settings: PartImportSpec, where: str) -> dict[str, Any]:
    if settings.thickness is None:
        raise _setting(
            "thickness",
            f"missing: a DXF flat pattern ({name!r}) has no thickness; give it in mm,"
            ' e.g. "part_import": {"thickness": 2} (workbench import-part: --thickness 2)',
        )
    from workbench.cad.dxf import read_flat_pattern
    from workbench.sheetmetal.flat_split import part_spec_from_flat_pattern

    if settings.base is not None:
        raise _setting("base", "only for a STEP part file; a DXF's base is its largest flange, F1")
    pattern = read_flat_pattern(data, name, where, bend_layer=settings.layer)
    return part_spec_from_flat_pattern(
        pattern,
        thickness=settings.thickness * MM,
        inner_radius=None if settings.inner_radius is None else settings.inner_radius * MM,
        k_factor=settings.k_factor,
        field=where,
    )


def import_part(
    data: bytes,
    name: str,
    settings: PartImportSpec | None = None,
    *,
    where: str = "bending.part_file",
) -> PartSpec:
    """Return the `PartSpec` (mm/deg) of the CAD part file `data` named `name` (.step/.stp/.dxf).

    Errors (WorkbenchError subclasses) name `where` and the face or entity for what is in the
    file, and ``bending.part_import.<field>`` for a setting that is missing or contradicts it.
    """
    kind = cad_kind(name)
    settings = settings or PartImportSpec()
    shown = f"{where} ({name})"
    if kind == "STEP":
        spec = _from_step(data, name, settings, shown)
        note = (
            f"recognised from the STEP solid {name!r}: {len(spec['flanges'])} flanges, "
            f"{len(spec['bends'])} bends"
        )
    elif kind == "DXF":
        spec = _from_dxf(data, name, settings, shown)
        note = f"from the DXF flat pattern {name!r} (bend lines on layer {settings.layer!r})"
    else:
        raise ProjectError(f"{name!r} is not a .step, .stp or .dxf file", field=where)
    return part_spec_from_si(spec, name=PurePath(name).stem, note=note, where=shown)


def part_import_settings(settings: dict[str, Any]) -> PartImportSpec:
    """Return `settings` (`bending.part_import`'s fields, mm) as the checked model; ProjectError
    names each bad field (``part_import.thickness: ...``) with its allowed range."""
    from workbench.project.io import problems_from

    try:
        return PartImportSpec.model_validate(settings)
    except ValidationError as exc:
        found = [(f"part_import.{path}", m) for path, m in problems_from(exc)]
        raise ProjectError("; ".join(f"{a}: {b}" for a, b in found), found) from None


def write_part_json(
    data: bytes, name: str, settings: dict[str, Any], out: PathLike[str] | str
) -> list[str]:
    """Write the part recognised in CAD file `data` (named `name`) as a part JSON [mm/deg] to
    `out` (atomic), and return a summary: one line per flange and bend, then the file written.

    `settings` are `bending.part_import`'s fields; ProjectError names a bad one.
    """
    import json

    from workbench.atomic_file import atomic_write_text

    part = import_part(data, name, part_import_settings(settings), where=name)
    text = json.dumps(part.model_dump(mode="json", exclude_none=True), indent=1)
    atomic_write_text(out, text + "\n")
    lines = [f"{name}: {part.note}; thickness {part.thickness:g} mm"]
    for f in part.flanges:
        size = np.ptp(np.asarray(f.polygon), axis=0)
        lines.append(f"  flange {f.name}: {len(f.polygon)} corners, {size[0]:g} x {size[1]:g} mm")
    for b in part.bends:
        lines.append(
            f"  bend {b.name}: {b.parent} edge {b.parent_edge} -> {b.child} edge {b.child_edge},"
            f" {180 - b.included_angle:g} deg {b.direction}, inner radius {b.inner_radius:g} mm"
        )
    lines.append(f"wrote {out} (rename the flanges and bends there and keep it)")
    return lines
