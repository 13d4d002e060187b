"""STEP import (issue 23): OCP-made STEP files read back, tessellated within the stated
tolerances and compared with Open CASCADE's exact properties (GProp, BRepBndLib), closed forms
and distances to the exact surfaces (BRepExtrema); bad files; STEP in a project.

The bounds, for a tessellation with chordal deviation d and angular deflection a of a shape of
area A and smallest radius of curvature r (docs/cad.md):
- every vertex lies on the surface (within the shape's own tolerance, 1e-7 mm here);
- every triangle lies within d of the surface (sampled: centroids and edge midpoints);
- |volume - V| <= d A: the region between the mesh and the surface lies within d of it;
- |area - A| <= A (1 - cos a + 2 d / r): projecting a triangle onto the surface scales its
  area by cos(angle of the normals) / (1 - h k1)(1 - h k2), h <= d, k <= 1/r;
- the mesh's bounding box lies inside the exact one and within d of it.
"""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh

from workbench import Workbench
from workbench.cad.example_parts import fixture_block, height_field_face
from workbench.cad.step import (
    StepProperties,
    StepTolerance,
    faces_of,
    read_step_mesh,
    read_step_shape,
    step_properties,
    tessellate,
    write_step,
)
from workbench.errors import InputError, MeshError, ProjectError
from workbench.service.mesh_files import load_mesh_file

ROOT = Path(__file__).resolve().parents[2]
DEG5 = math.radians(5.0)


# -- shapes [mm] -------------------------------------------------------------------------------
def _box() -> Any:
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox

    return BRepPrimAPI_MakeBox(100.0, 60.0, 30.0).Shape()


def _cylinder() -> Any:
    """A cylinder r 10, h 20 standing at (5, -7, 3), moved there by a location (not built there)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder
    from OCP.gp import gp_Trsf, gp_Vec

    trsf = gp_Trsf()
    trsf.SetTranslation(gp_Vec(5.0, -7.0, 3.0))
    return BRepBuilderAPI_Transform(BRepPrimAPI_MakeCylinder(10.0, 20.0).Shape(), trsf).Shape()


def _filleted() -> Any:
    from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    box = _box()
    fillet = BRepFilletAPI_MakeFillet(box)
    explorer = TopExp_Explorer(box, TopAbs_EDGE)
    while explorer.More():
        fillet.Add(5.0, TopoDS.Edge(explorer.Current()))
        explorer.Next()
    return fillet.Shape()


def _sphere() -> Any:
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeSphere

    return BRepPrimAPI_MakeSphere(25.0).Shape()


def _free_form() -> Any:
    """A B-spline face over 120 x 80 mm: a dome with a cross wave, one open surface."""
    x, y = np.meshgrid(np.linspace(-60, 60, 13), np.linspace(-40, 40, 9), indexing="ij")
    z = 15.0 * (1 - (x / 80) ** 2 - (y / 60) ** 2) + 2.0 * np.sin(x / 15) * np.cos(y / 20)
    return height_field_face(z, -60.0, 10.0, -40.0, 10.0)


# name -> (shape, closed solid?, smallest radius of curvature [mm] or inf for flat faces)
SHAPES = {
    "box": (_box, True, math.inf),
    "cylinder": (_cylinder, True, 10.0),
    "filleted": (_filleted, True, 5.0),
    "sphere": (_sphere, True, 25.0),
    "free_form": (_free_form, False, 40.0),
}


def _round_trip(make: Any, tmp_path: Path, name: str) -> Any:
    """Return the shape written to a STEP file under tmp_path and read back."""
    path = tmp_path / f"{name}.step"
    path.write_bytes(write_step(make(), path.name))
    return read_step_shape(path.read_bytes(), path.name, "test")


def _surface_distance(shape: Any, points: np.ndarray) -> np.ndarray:
    """Return the distance [mm] of each point to the faces of `shape` (BRepExtrema; the faces,
    not the solid, so a point inside is not at distance 0)."""
    from OCP.BRep import BRep_Builder
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex
    from OCP.BRepExtrema import BRepExtrema_DistShapeShape
    from OCP.gp import gp_Pnt
    from OCP.TopoDS import TopoDS_Compound

    compound, builder = TopoDS_Compound(), BRep_Builder()
    builder.MakeCompound(compound)
    for face in faces_of(shape):
        builder.Add(compound, face)
    out = np.empty(len(points))
    for i, p in enumerate(points):
        vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(*map(float, p))).Vertex()
        dist = BRepExtrema_DistShapeShape(vertex, compound)
        out[i] = dist.Value()
    return out


# -- exact properties against closed forms -------------------------------------------------------
def test_exact_properties_match_closed_forms() -> None:
    box, cyl, sph = (
        step_properties(_box()),
        step_properties(_cylinder()),
        step_properties(_sphere()),
    )
    assert box.area == pytest.approx(2 * (100 * 60 + 100 * 30 + 60 * 30), rel=1e-12)
    assert box.volume == pytest.approx(100 * 60 * 30, rel=1e-12)
    assert np.allclose(box.bbox, [[0, 0, 0], [100, 60, 30]], atol=1e-9)
    assert cyl.area == pytest.approx(2 * math.pi * 10 * 20 + 2 * math.pi * 100, rel=1e-9)
    assert cyl.volume == pytest.approx(math.pi * 100 * 20, rel=1e-9)
    assert np.allclose(cyl.bbox, [[-5, -17, 3], [15, 3, 23]], atol=1e-6)
    assert sph.area == pytest.approx(4 * math.pi * 625, rel=1e-9)
    assert sph.volume == pytest.approx(4 / 3 * math.pi * 25**3, rel=1e-9)


# -- tessellation against the exact shape ---------------------------------------------------------
@pytest.mark.parametrize("name", sorted(SHAPES))
def test_tessellation_matches_the_exact_properties(name: str, tmp_path: Path) -> None:
    make, closed, r_min = SHAPES[name]
    shape = _round_trip(make, tmp_path, name)
    d = 0.05
    mesh = tessellate(shape, d, DEG5)
    exact: StepProperties = step_properties(shape)
    if closed:
        assert mesh.is_watertight and mesh.is_winding_consistent
        assert mesh.volume > 0, "outward normals: positive volume"
        assert abs(mesh.volume - exact.volume) <= d * exact.area
    else:
        assert mesh.is_winding_consistent
    area_bound = exact.area * (1 - math.cos(DEG5) + 2 * d / r_min)
    assert abs(mesh.area - exact.area) <= area_bound
    lo, hi = mesh.bounds
    assert np.all(lo >= exact.bbox[0] - 1e-6) and np.all(hi <= exact.bbox[1] + 1e-6)
    assert np.all(lo <= exact.bbox[0] + d) and np.all(hi >= exact.bbox[1] - d)


@pytest.mark.parametrize("name", ["cylinder", "filleted", "sphere", "free_form"])
def test_every_vertex_is_on_the_surface_and_every_triangle_within_the_chord(
    name: str, tmp_path: Path
) -> None:
    make, _, _ = SHAPES[name]
    shape = _round_trip(make, tmp_path, name)
    d = 0.02
    # A loose angular deflection (30 deg), so that the chordal deviation decides the mesh.
    mesh = tessellate(shape, d, math.radians(30.0))
    rng = np.random.default_rng(0)
    v = mesh.vertices[rng.choice(len(mesh.vertices), min(300, len(mesh.vertices)), replace=False)]
    assert _surface_distance(shape, v).max() <= 1e-6
    tri = mesh.triangles[rng.choice(len(mesh.faces), min(400, len(mesh.faces)), replace=False)]
    samples = np.concatenate([tri.mean(axis=1), (tri[:, 0] + tri[:, 1]) / 2])
    dev = _surface_distance(shape, samples)
    assert dev.max() <= d, f"{name}: {dev.max():.4f} mm off the surface, tolerance {d} mm"
    assert dev.max() >= 0.2 * d, "the chordal tolerance decides the mesh (not over-refined)"


def test_closed_forms_agree_with_the_surface_distance(tmp_path: Path) -> None:
    """The BRepExtrema distance used above against the sphere's and cylinder's closed forms."""
    sphere = _round_trip(_sphere, tmp_path, "sphere")
    mesh = tessellate(sphere, 0.02, math.radians(30.0))
    c = mesh.triangles.mean(axis=1)[:200]
    exact = 25.0 - np.linalg.norm(c, axis=1)
    assert np.allclose(_surface_distance(sphere, c), exact, atol=1e-7)
    assert exact.max() <= 0.02 and exact.min() >= 0.0


def test_a_finer_tolerance_gives_more_triangles_and_smaller_errors(tmp_path: Path) -> None:
    sphere = _round_trip(_sphere, tmp_path, "sphere")
    errors, counts = [], []
    for d in (0.4, 0.1, 0.025):
        from OCP.BRepTools import BRepTools

        BRepTools.Clean_s(sphere)  # a coarser mesh is not kept: start from the B-rep each time
        mesh = tessellate(sphere, d, math.radians(30.0))
        counts.append(len(mesh.faces))
        errors.append(abs(mesh.volume - 4 / 3 * math.pi * 25**3))
    assert counts == sorted(counts) and errors == sorted(errors, reverse=True)


def test_the_file_unit_is_read_into_mm(tmp_path: Path) -> None:
    """A STEP file in metres (its unit is in the file) reads as the same part in mm."""
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox

    data = write_step(BRepPrimAPI_MakeBox(0.1, 0.06, 0.03).Shape(), "m.step")
    assert b"SI_UNIT(.MILLI.,.METRE.)" in data
    in_metres = data.replace(b"SI_UNIT(.MILLI.,.METRE.)", b"SI_UNIT($,.METRE.)")
    shape = read_step_shape(in_metres, "m.step", "test")
    assert np.allclose(step_properties(shape).bbox, [[0, 0, 0], [100, 60, 30]], atol=1e-6)


# -- bad files: a MeshError (or the path rule's InputError) naming the field and the fix -------------
def _curves_only() -> bytes:
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.gp import gp_Pnt

    return write_step(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0)).Edge(), "c.step")


BAD_FILES = {
    "not_step": (lambda: b"solid x\nendsolid x\n", "is not a STEP file", "export the part as STEP"),
    "empty": (lambda: b"", "is not a STEP file", "export the part as STEP"),
    "truncated": (
        lambda: write_step(_box(), "t.step")[:2000],
        "cannot read STEP file",
        "complete STEP export",
    ),
    "curves_only": (_curves_only, "holds no surfaces or solids", "export the part's solid body"),
}


@pytest.mark.parametrize("case", sorted(BAD_FILES))
def test_bad_step_files_name_the_field_and_the_fix(case: str, tmp_path: Path) -> None:
    make, what, fix = BAD_FILES[case]
    (tmp_path / "part.step").write_bytes(make())
    field = "cell.objects[3].path"
    with pytest.raises(MeshError) as info:
        load_mesh_file("part.step", tmp_path, 0.001, field)
    message = str(info.value)
    assert message.startswith(field + ":") and what in message and fix in message, message


def test_a_step_file_over_the_mesh_limit_is_refused_before_it_is_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    data = write_step(_box(), "big.step")
    (tmp_path / "big.step").write_bytes(data)
    monkeypatch.setenv("WORKBENCH_MAX_MESH_BYTES", str(len(data) - 1))
    with pytest.raises(InputError, match=r"tool\.mesh.*WORKBENCH_MAX_MESH_BYTES"):
        load_mesh_file("big.step", tmp_path, 0.001, "tool.mesh")


def test_open_cascade_that_does_not_load_is_refused_with_the_fix(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # What a machine without libGL sees: importing OCP's modules fails (an OSError from the
    # loader; a None entry in sys.modules raises ImportError the same way).
    import sys

    from workbench.cad.step import read_step_shape

    monkeypatch.setitem(sys.modules, "OCP.STEPControl", None)
    with pytest.raises(MeshError, match=r"cell.objects\[0\].path: .*apt-get install libgl1"):
        read_step_shape(b"ISO-10303-21;\nHEADER;", "x.step", "cell.objects[0].path")


def test_too_many_triangles_are_refused_with_the_fix(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import workbench.cad.brep_mesh as brep_mesh

    (tmp_path / "s.step").write_bytes(write_step(_sphere(), "s.step"))
    monkeypatch.setattr(brep_mesh, "MAX_TRIANGLES", 1000)
    with pytest.raises(MeshError, match=r"assembly\.parts\[0\]\.path: .*raise the linear"):
        load_mesh_file("s.step", tmp_path, 0.001, "assembly.parts[0].path")


def test_a_step_file_loads_in_metres_with_the_tolerance(tmp_path: Path) -> None:
    (tmp_path / "f.STP").write_bytes(write_step(_filleted(), "f.STP"))
    coarse = load_mesh_file("f.STP", tmp_path, 0.001, "x", tolerance=StepTolerance(1e-4, 0.5))
    fine = load_mesh_file("f.STP", tmp_path, 0.001, "x", tolerance=StepTolerance(1e-5, 0.1))
    assert np.allclose(fine.bounds, [[0.0, 0.0, 0.0], [0.1, 0.06, 0.03]], atol=1e-9)
    assert len(fine.faces) > 2 * len(coarse.faces)
    assert fine.metadata["deflection_mm"] <= 0.01 and coarse.metadata["deflection_mm"] <= 0.1
    mesh = read_step_mesh(write_step(_box(), "b.step"), "b.step", "x", StepTolerance())
    assert np.allclose(mesh.bounds, [[0, 0, 0], [100, 60, 30]])  # read_step_mesh: mm


# -- STEP in a project --------------------------------------------------------------------------------
def _cell_project(path: str, xyz: list[float], **extra: Any) -> dict[str, Any]:
    obj = {"name": "block", "shape": "mesh", "path": path, "pose": {"xyz": xyz}}
    return {
        "schema_version": 2,
        "robot": {"preset": "mz07", "joints": [0, 0, 0, 0, 0, 0]},
        "cell": {"objects": [obj]},
        **extra,
    }


def test_a_step_cell_object_collides_as_the_same_shape_given_as_stl(tmp_path: Path) -> None:
    """The box as STEP against the box as an STL made by trimesh (an exact twin: a box's
    tessellation is exact), then the fixture block as STEP against its own tessellation as
    STL: the same verdicts and distances at seeded joint values around a contact."""
    (tmp_path / "box.step").write_bytes(write_step(_box(), "box.step"))
    box = trimesh.creation.box(extents=[100, 60, 30])
    box.apply_translation([50, 30, 15])
    box.export(tmp_path / "box.stl")
    (tmp_path / "block.step").write_bytes(write_step(fixture_block(), "block.step"))
    load_mesh_file("block.step", tmp_path, 1.0, "x").export(tmp_path / "block.stl")  # in mm
    probe = Workbench.from_dict(_cell_project("box.stl", [0, 0, -5000]), base_dir=tmp_path)
    tcp = probe.tcp_pose()[:3, 3] * 1000.0  # mm: the block is put at the tool's tip
    rng = np.random.default_rng(0)
    qs = probe.joints + rng.normal(0.0, 0.15, (12, probe.robot.dof))
    for step_file, stl_file, offset in (
        ("box.step", "box.stl", [-50, -30, -15]),
        ("block.step", "block.stl", [0, 0, 0]),
    ):
        xyz = list(tcp + offset)
        a = Workbench.from_dict(_cell_project(step_file, xyz), base_dir=tmp_path)
        b = Workbench.from_dict(_cell_project(stl_file, xyz), base_dir=tmp_path)
        assert a.collision_status().in_collision and "block" in str(a.collision_status().colliding)
        for q in qs:
            ra, rb = a.collision_status(q), b.collision_status(q)
            assert ra.colliding == rb.colliding
            assert ra.min_distance == pytest.approx(rb.min_distance, abs=1e-6)


def test_a_step_scale_other_than_mm_is_refused_at_load() -> None:
    data = _cell_project("part.step", [0, 0, 0])
    data["cell"]["objects"][0]["scale"] = 1.0
    with pytest.raises(ProjectError, match=r"cell\.objects\[0\]\.scale.*STEP carries its own"):
        Workbench.from_dict(data)
    data = _cell_project("part.stl", [0, 0, 0])
    data["tool"] = {"mesh": "tool.STP", "mesh_scale": 1.0}
    with pytest.raises(ProjectError, match=r"tool\.mesh_scale"):
        Workbench.from_dict(data)


def test_the_cad_section_sets_the_tolerance(tmp_path: Path) -> None:
    (tmp_path / "s.step").write_bytes(write_step(_sphere(), "s.step"))
    counts = []
    for linear in (0.5, 0.05):
        data = _cell_project(
            "s.step", [0, 0, -3000], cad={"linear_tolerance": linear, "angular_tolerance": 30}
        )
        wb = Workbench.from_dict(data, base_dir=tmp_path)
        mesh = wb.cell[0].mesh()  # in the body's frame [m]: the sphere's centre at 0
        counts.append(len(mesh.faces))
        chord = 25e-3 - np.linalg.norm(mesh.triangles.mean(axis=1), axis=1)  # closed form
        assert 0.3 * linear * 1e-3 <= chord.max() <= linear * 1e-3
    assert counts[1] > 5 * counts[0]  # N ~ 1 / d on a sphere
    for bad in ({"linear_tolerance": 0}, {"angular_tolerance": 90}, {"linear": 1}):
        with pytest.raises(ProjectError, match="cad"):
            Workbench.from_dict(_cell_project("s.step", [0, 0, -3000], cad=bad), base_dir=tmp_path)


# -- polishing on a STEP workpiece ---------------------------------------------------------------------
def test_the_step_cell_polishes_the_step_panel_as_the_stl_one() -> None:
    """projects/step_cell.json: the panel as a B-spline face (STEP) is fitted and planned like
    the same panel as an STL (projects/polishing_cell.json), and the path lies on the exact
    surface: its process points within 0.05 mm of the STEP face placed at the workpiece pose,
    its normals within 0.5 deg of the face's; the robot motion takes as long as the STL's."""
    t0 = time.perf_counter()
    wb = Workbench.open(ROOT / "projects" / "step_cell.json")
    opened = time.perf_counter() - t0
    stl = Workbench.open(ROOT / "projects" / "polishing_cell.json")
    report = wb.polishing.load_workpiece()
    assert report.units == "mm" and report.n_holes == 0 and report.n_nonmanifold_edges == 0
    path, ref = wb.polishing.plan_path(), stl.polishing.plan_path()
    assert path.coverage.fraction > 0.98
    assert path.length == pytest.approx(ref.length, rel=0.01)
    assert path.path.n_passes == ref.path.n_passes
    face = read_step_shape((ROOT / "web_assets/workpieces/panel.step").read_bytes(), "p", "t")
    T = wb.polishing.T_world_workpiece
    local = (path.path.points[path.path.is_process] - T[:3, 3]) @ T[:3, :3] * 1000.0  # mm
    every = max(1, len(local) // 150)
    dev = _surface_distance(face, local[::every])
    assert dev.max() <= 0.05, f"{dev.max():.4f} mm"
    # The fit's normals against the B-spline's own (the fit uses the exact vertex normals).
    normals = path.path.normals[path.path.is_process][::every] @ T[:3, :3]
    exact = _exact_normals(face, local[::every])
    angle = np.degrees(np.arccos(np.clip(np.abs(np.einsum("ij,ij->i", normals, exact)), 0, 1)))
    assert angle.max() <= 0.5 and angle.mean() <= 0.05, (angle.max(), angle.mean())
    assert opened < 5.0
    plan, ref_plan = wb.polishing.plan_motion(), stl.polishing.plan_motion()
    assert plan.ok and plan.cycle_time == pytest.approx(ref_plan.cycle_time, rel=0.02)


def _exact_normals(face: Any, points: np.ndarray) -> np.ndarray:
    """Return the unit normals of the face's surface at the points nearest to `points` [mm]."""
    from OCP.BRep import BRep_Tool
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.GeomLProp import GeomLProp_SLProps
    from OCP.gp import gp_Pnt

    surface = BRep_Tool.Surface_s(faces_of(face)[0])
    out = []
    for p in points:
        u, v = GeomAPI_ProjectPointOnSurf(gp_Pnt(*map(float, p)), surface).LowerDistanceParameters()
        n = GeomLProp_SLProps(surface, u, v, 1, 1e-9).Normal()
        out.append([n.X(), n.Y(), n.Z()])
    return np.asarray(out)


def test_a_step_workpiece_read_in_metres_is_refused_naming_the_units(tmp_path: Path) -> None:
    (tmp_path / "p.step").write_bytes(write_step(_free_form(), "p.step"))
    data = {**_cell_project("p.step", [0, 0, -3000]), "cell": {"objects": []}}
    data["polishing"] = {"workpiece": "p.step", "units": "m"}
    wb = Workbench.from_dict(data, base_dir=tmp_path)
    with pytest.raises(MeshError, match=r"polishing\.units: .*STEP file.*units='mm'"):
        wb.polishing.load_workpiece()
    report = wb.polishing.load_workpiece(units="auto")
    assert report.units == "mm" and report.bbox_diagonal == pytest.approx(0.146, abs=0.01)


def test_an_assembly_part_reads_from_step(tmp_path: Path) -> None:
    """A part of projects/assembly_cell.json given as a STEP cylinder: loaded closed, in m."""
    import json

    from workbench.project.paths import ProjectFolders

    (tmp_path / "pin.step").write_bytes(write_step(_cylinder(), "pin.step"))
    data = json.loads((ROOT / "projects" / "assembly_cell.json").read_text())
    data["assembly"]["parts"][2]["path"] = str(tmp_path / "pin.step")
    data["cad"] = {"linear_tolerance": 0.01}
    wb = Workbench.from_dict(data, base_dir=ProjectFolders(ROOT / "projects", [tmp_path]))
    part = wb.assembly.parts[data["assembly"]["parts"][2]["name"]]
    exact = step_properties(_cylinder())
    assert part.mesh.is_watertight and part.mesh.volume > 0
    assert abs(part.mesh.volume - exact.volume * 1e-9) <= 0.01e-3 * exact.area * 1e-6
    assert np.allclose(part.mesh.bounds, exact.bbox * 1e-3, atol=0.01e-3)


def test_the_mesh_carries_the_exact_outward_surface_normals(tmp_path: Path) -> None:
    sphere = tessellate(_round_trip(_sphere, tmp_path, "sphere"), 0.05, DEG5)
    n = np.asarray(sphere.vertex_attributes["surface_normals"], dtype=float)
    radial = sphere.vertices / np.linalg.norm(sphere.vertices, axis=1, keepdims=True)
    assert np.einsum("ij,ij->i", n, radial).min() > 1 - 1e-9  # closed form: outward radial
    for name in ("box", "filleted", "cylinder"):
        mesh = tessellate(_round_trip(SHAPES[name][0], tmp_path, name), 0.05, DEG5)
        exact = np.asarray(mesh.vertex_attributes["surface_normals"], dtype=float)
        assert np.allclose(np.linalg.norm(exact, axis=1), 1.0)
        area = np.asarray(mesh.vertex_normals, dtype=float)
        assert np.einsum("ij,ij->i", exact, area).min() > 0, name
