"""Bring your own cell: a part from STEP and from DXF, a STEP obstacle, a robot of the library.

Opens the press-brake cell whose part is a STEP file of the bent U-channel (recognised into
flanges and bends, unfolded by the K-factor model) and plans its cycle; reads the pan's DXF
flat pattern into the same cell; adds a STEP fixture to the MZ07 cell and shows what the
collision check sees; then lists the robot library and what each robot makes of the MZ07
cell's first target (its IK configurations and the program format it exports by default).

    python examples/07_own_cell.py
"""

from __future__ import annotations

from pathlib import Path

from workbench import Workbench, WorkbenchError

ROOT = Path(__file__).resolve().parents[1]
PROJECTS = ROOT / "projects"


def main() -> None:
    # 1. A STEP of the bent part, named by the project (bending.part_file).
    wb = Workbench.open(PROJECTS / "step_channel_cell.json")
    part = wb.bending.part_spec()
    print(f"part: {part.note}; thickness {part.thickness:g} mm")
    for bend in part.bends:
        print(
            f"  {bend.name}: {bend.parent} -> {bend.child}, {180 - bend.included_angle:g} deg"
            f" {bend.direction}"
        )
    print(f"flat blank: {wb.bending.part.blank_area() * 1e6:.1f} mm^2")
    print(wb.bending.plan().summary())

    # 2. A DXF flat pattern into the same cell: the DXF says no thickness, so it is given.
    dxf = (PROJECTS / "parts" / "pan_flat.dxf").read_bytes()
    try:
        wb.import_part("pan_flat.dxf", dxf, {})
    except WorkbenchError as exc:
        print(f"refused: {exc}")
    print(wb.import_part("pan_flat.dxf", dxf, {"thickness": 1.5, "inner_radius": 1.92}))
    print(f"  flanges {', '.join(f.name for f in wb.bending.part_spec().flanges)}")

    # 3. A STEP fixture in the MZ07 cell, placed (on purpose) around the
    # gripper's tip in the stored posture (30 mm above the TCP).
    cell = Workbench.open(PROJECTS / "mz07_cell.json")
    tcp_mm = [float(v) * 1000.0 for v in cell.tcp_pose()[:3, 3]]
    fixture = ROOT / "web_assets" / "parts" / "fixture_block.step"
    name = cell.add_cell_file(fixture, xyz_mm=[tcp_mm[0], tcp_mm[1], tcp_mm[2] + 30.0])
    status = cell.collision_status()
    hits = sorted({a if b == name else b for a, b in status.colliding if name in (a, b)})
    print(
        f"obstacle {name}: {len(cell.cell)} cell bodies; it touches {', '.join(hits) or 'nothing'}"
    )

    # 4. The robot library on the MZ07 cell's first Cartesian target.
    moves = cell.project.program.moves  # type: ignore[union-attr]
    target = next(m for m in moves if getattr(m, "pose", None) is not None)
    for choice in Workbench.robot_choices():
        wb = Workbench.open(PROJECTS / "mz07_cell.json")
        wb.use_robot(choice.name)
        T = wb.tcp_pose()
        T[:3, 3] = [v / 1000.0 for v in target.pose.xyz]  # type: ignore[union-attr]
        n = len(wb.ik_solutions(T))
        print(
            f"{choice.label}: {n} configuration(s) reach {target.name};"
            f" exports {wb.default_program_format()}"
        )


if __name__ == "__main__":
    main()
