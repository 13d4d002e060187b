"""Polishing picked faces of a STEP solid (issue 29 part 6): the face list, `polishing.faces`,
the path on the picked face, the rest of the solid an obstacle for the robot and the tool."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import trimesh

from workbench.cad.step import StepTolerance, write_step
from workbench.cad.step_faces import faces_submesh, read_step_faces
from workbench.errors import InputError, WorkbenchError
from workbench.polishing.solid_workpiece import contact_zone, load_solid_workpiece

REPO = Path(__file__).resolve().parents[2]
SLAB = (200.0, 120.0, 20.0)  # [mm] x, y, z; the slab spans z 0..20, the top face at z = 20


def _slab_step() -> bytes:
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.gp import gp_Pnt

    box = BRepPrimAPI_MakeBox(gp_Pnt(-100, -60, 0), *SLAB).Shape()
    return write_step(box, "slab")


def _cylinder_step() -> bytes:
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder

    return write_step(BRepPrimAPI_MakeCylinder(30.0, 50.0).Shape(), "cylinder")


@pytest.fixture(scope="module")
def slab_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("solid") / "slab.step"
    path.write_bytes(_slab_step())
    return path


def _top(faces) -> int:  # type: ignore[no-untyped-def]
    return next(f.index for f in faces if f.normal is not None and f.normal[2] > 0.99)


def test_face_list_areas_types_and_stable_indices(slab_file: Path) -> None:
    tol = StepTolerance()
    first = read_step_faces(slab_file.read_bytes(), "slab.step", "workpiece", tol)
    again = read_step_faces(slab_file.read_bytes(), "slab.step", "workpiece", tol)
    assert first.faces == again.faces  # same file, same indices
    assert [f.kind for f in first.faces] == ["plane"] * 6
    x, y, z = SLAB
    # Closed form: two faces of each of the slab's three areas.
    assert sorted(round(f.area, 6) for f in first.faces) == sorted(2 * [x * y, x * z, y * z])
    # The mesh's own triangles, per face, give the same areas (planar faces: exactly).
    areas = first.mesh.area_faces
    ids = first.mesh.face_attributes["step_face"]
    for f in first.faces:
        assert areas[ids == f.index].sum() == pytest.approx(f.area, rel=1e-9)
        # a planar face's normal is its triangles' normal (outward)
        n = first.mesh.face_normals[ids == f.index]
        assert np.allclose(n, f.normal, atol=1e-9)
    top = first.faces[_top(first.faces)]
    assert top.centroid == pytest.approx((0.0, 0.0, 20.0), abs=1e-9)


def test_curved_faces_named_and_measured() -> None:
    read = read_step_faces(_cylinder_step(), "cyl.step", "workpiece", StepTolerance())
    kinds = sorted(f.kind for f in read.faces)
    assert kinds == ["cylinder", "plane", "plane"]
    side = next(f for f in read.faces if f.kind == "cylinder")
    assert side.normal is None
    assert side.area == pytest.approx(2 * math.pi * 30 * 50, rel=1e-9)  # GProp vs closed form
    # the tessellation (0.05 mm chordal) lies within it: inscribed, so slightly smaller
    sub = faces_submesh(read.mesh, [side.index])
    assert sub.area == pytest.approx(side.area, rel=1e-3)


def test_picked_face_is_the_surface_and_the_band_splits_the_rest(slab_file: Path) -> None:
    faces = read_step_faces(slab_file.read_bytes(), "s", "w", StepTolerance()).faces
    top = _top(faces)
    mesh, report, solid = load_solid_workpiece(slab_file, [top], np.eye(4))
    # the surface: the top face only, in metres, z = 20 mm everywhere
    assert np.allclose(mesh.vertices[:, 2], 0.020, atol=1e-12)
    assert mesh.area == pytest.approx(200 * 120 * 1e-6, rel=1e-9)
    assert not report.is_watertight and solid.mesh.is_watertight
    band = 0.005
    zone, away = contact_zone(solid, band)
    # Distance to the top face of a point of this slab's other faces: its depth 0.020 - z
    # (the top face covers the whole slab). The zone reaches the band, not beyond twice it;
    # nothing beyond the zone comes within the band.
    assert zone.vertices[zone.faces].reshape(-1, 3)[:, 2].min() >= 0.020 - 2 * band - 1e-12
    assert 0.020 - away.vertices[away.faces].reshape(-1, 3)[:, 2].max() >= band - 1e-12
    assert zone.area + away.area == pytest.approx(solid.mesh.area - mesh.area, rel=1e-9)
    with pytest.raises(InputError, match="indices 0 to 5") as err:
        load_solid_workpiece(slab_file, [6], np.eye(4))
    assert err.value.field == "faces"


def _project(tmp_path: Path, slab_file: Path, faces: list[int] | None) -> Path:
    data = json.loads((REPO / "projects/step_cell.json").read_text())
    for obj in data["cell"]["objects"]:
        if "path" in obj:
            obj["path"] = str(REPO / "projects" / obj["path"])
    data["polishing"]["workpiece"] = str(slab_file)
    if faces is not None:
        data["polishing"]["faces"] = faces
    path = tmp_path / "slab_cell.json"
    path.write_text(json.dumps(data))
    return path


def _open(tmp_path: Path, slab_file: Path, faces: list[int] | None = None):  # type: ignore[no-untyped-def]
    from workbench.service import Workbench

    return Workbench.open(
        _project(tmp_path, slab_file, faces), allowed_dirs=[REPO, slab_file.parent]
    )


@pytest.mark.parametrize(
    ("faces", "said"),
    [([], "is empty"), ([-1], "count from 0"), ([5, 5], "picked twice")],
)
def test_bad_faces_refused_naming_the_field(
    tmp_path: Path, slab_file: Path, faces: list[int], said: str
) -> None:
    with pytest.raises(WorkbenchError, match=said) as err:
        _open(tmp_path, slab_file, faces)
    assert "polishing.faces" in str(err.value)


def test_face_out_of_range_and_whole_solid_named(tmp_path: Path, slab_file: Path) -> None:
    wb = _open(tmp_path, slab_file)
    assert len(wb.polishing.faces()) == 6
    with pytest.raises(InputError, match="closed STEP solid") as err:
        wb.polishing.load_workpiece()
    assert err.value.field == "polishing.faces"
    with pytest.raises(InputError, match="indices 0 to 5") as err:
        wb.polishing.set_faces([9])
    assert err.value.field == "polishing.faces"
    assert wb.project.polishing.faces is None  # refused: the section stays as it was


def test_mesh_workpiece_has_no_faces_to_pick(tmp_path: Path, slab_file: Path) -> None:
    wb = _open(tmp_path, slab_file)
    wb.project.polishing.workpiece = str(REPO / "web_assets/workpieces/panel.stl")
    with pytest.raises(InputError, match="no faces to pick") as err:
        wb.polishing.faces()
    assert err.value.field == "polishing.workpiece"
    with pytest.raises(WorkbenchError, match="mesh file") as err2:
        wb.polishing.set_faces([0])
    assert err2.value.field == "polishing.faces"


def test_path_on_the_picked_face_and_pushed_path_collides(tmp_path: Path, slab_file: Path) -> None:
    wb = _open(tmp_path, slab_file)
    top = _top(wb.polishing.faces())
    wb.polishing.set_faces([top])
    assert wb.project.polishing.faces == [top]
    pp = wb.polishing.plan_path()
    process = pp.path.points[pp.path.is_process]
    # Independent twin: trimesh's closest point on the picked face's triangles (world frame).
    solid = wb.polishing._fitted.solid
    face = faces_submesh(solid.mesh, [top])
    _, dist, _ = trimesh.proximity.closest_point(face, process)
    assert dist.max() < 1e-6  # [m]
    # The robot and the tool reach the path's first process point: no collision there (the
    # tool is in contact with the polished face); pushed 30 mm into the slab it collides.
    checker = wb.polishing.plan_checker()
    T = wb.polishing.tcp_poses(pp)[int(np.argmax(pp.path.is_process))]
    q_on = wb.ik_solutions(T)[0].q
    assert not checker.check(q_on, distance=False).in_collision
    pushed = T.copy()
    pushed[:3, 3] += 0.030 * T[:3, 2]  # the tool z points into the surface
    q_in = min(wb.ik_solutions(pushed), key=lambda s: np.abs(s.q - q_on).max()).q
    hit = checker.check(q_in, distance=False)
    assert hit.in_collision
    assert any("workpiece" in b for pair in hit.colliding for b in pair)
    assert not wb.checker.check(q_in, distance=False).in_collision  # the cell alone: free


@pytest.mark.slow
def test_full_plan_and_export_with_faces(tmp_path: Path, slab_file: Path) -> None:
    wb = _open(tmp_path, slab_file)
    wb.polishing.set_faces([_top(wb.polishing.faces())])
    plan = wb.polishing.plan_motion()
    assert plan.ok, plan.summary()
    assert wb.polishing.robot_programs(plan)


@pytest.mark.slow  # opens the cell's workbench (~1 s)
def test_cli_lists_picks_and_saves(
    tmp_path: Path, slab_file: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from workbench.cli import main
    from workbench.project.io import load_project

    project = _project(tmp_path, slab_file, None)
    allow = ["--allow-dir", str(REPO), "--allow-dir", str(slab_file.parent)]
    out = tmp_path / "picked.json"
    assert main(["polishing-faces", str(project), "--pick", "5", "--out", str(out), *allow]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[5].startswith("* 5: plane, 24000.0 mm² at (0.0, 0.0, 20.0) mm")
    assert sum(line.startswith("*") for line in lines) == 1
    assert load_project(out).polishing.faces == [5]  # type: ignore[union-attr]
    assert main(["polishing-faces", str(project), "--pick", "9", "--out", str(out), *allow]) == 2
    assert "polishing.faces: face 9" in capsys.readouterr().err


@pytest.mark.slow  # opens the cell's workbench (~1 s)
def test_suggested_face_and_a_new_solid_file(tmp_path: Path, slab_file: Path) -> None:
    wb = _open(tmp_path, slab_file)
    wb.project.polishing.workpiece = str(REPO / "web_assets/workpieces/panel.stl")
    # The slab's top and bottom have the same area: the top (higher in the world) is suggested.
    picked = wb.polishing.suggested_faces(slab_file)
    assert picked == [_top(wb.polishing.faces(slab_file))]
    with pytest.raises(InputError, match="indices 0 to 5"):
        wb.polishing.set_faces([7], slab_file)
    assert wb.project.polishing.workpiece.endswith("panel.stl")  # refused: nothing changed
    wb.polishing.set_faces(picked, slab_file)
    assert wb.project.polishing.workpiece == str(slab_file)
    assert wb.project.polishing.faces == picked
    assert wb.polishing.report.n_faces == 2  # the top face's two triangles
