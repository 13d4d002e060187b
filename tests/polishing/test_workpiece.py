"""Workpiece import: units, defects and bad files, checked against meshes built by hand."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.workpiece import load_workpiece

PANEL = Path(__file__).resolve().parents[2] / "web_assets" / "workpieces" / "panel.stl"


def _save(mesh: trimesh.Trimesh, path: Path, scale: float = 1.0) -> Path:
    trimesh.Trimesh(vertices=mesh.vertices * scale, faces=mesh.faces, process=False).export(
        str(path)
    )
    return path


def test_example_panel_is_read_in_mm_and_clean() -> None:
    mesh, report = load_workpiece(PANEL)
    assert report.units == "mm" and report.scale == 1e-3
    # The panel spans 300 x 200 mm; the grid generator is the twin.
    ref = make_panel()
    np.testing.assert_allclose(mesh.bounds, ref.bounds, atol=1e-6)
    assert report.n_faces == 2 * 59 * 39
    assert report.n_degenerate_faces == 0 and report.n_nonmanifold_edges == 0
    assert report.n_boundary_loops == 1 and report.n_holes == 0
    assert report.n_boundary_edges == 2 * (59 + 39)
    assert not report.is_watertight


def test_units_auto_metres_and_explicit(tmp_path: Path) -> None:
    panel = make_panel(10, 8)
    p_m = _save(panel, tmp_path / "m.stl")
    _, rep = load_workpiece(p_m)
    assert rep.units == "m" and rep.scale == 1.0
    _, rep = load_workpiece(p_m, units="m")
    assert rep.bbox_diagonal == pytest.approx(
        np.linalg.norm(np.ptp(panel.vertices, axis=0)), rel=1e-6
    )


def test_wrong_units_are_flagged(tmp_path: Path) -> None:
    panel = make_panel(10, 8)
    p_mm = _save(panel, tmp_path / "mm.stl", 1000.0)
    with pytest.raises(MeshError, match="units='mm'"):
        load_workpiece(p_mm, units="m")  # 360 m diagonal
    p_m = _save(panel, tmp_path / "m.stl")
    with pytest.raises(MeshError, match="units='m'"):
        load_workpiece(p_m, units="mm")  # 0.36 mm diagonal
    with pytest.raises(InputError, match="units"):
        load_workpiece(p_m, units="inch")  # type: ignore[arg-type]


def test_bad_files(tmp_path: Path) -> None:
    with pytest.raises(MeshError, match="does not exist"):
        load_workpiece(tmp_path / "missing.stl")
    empty = tmp_path / "empty.stl"
    empty.write_bytes(b"")
    with pytest.raises(MeshError, match="empty"):
        load_workpiece(empty)
    junk = tmp_path / "junk.stl"
    junk.write_text("this is not a mesh\n" * 20)
    with pytest.raises(MeshError, match="junk.stl"):
        load_workpiece(junk)


def test_defects_are_counted(tmp_path: Path) -> None:
    # A 4x4 grid with one square removed (a hole), a zero-area sliver and a fin on one edge.
    panel = make_panel(5, 5, half_x=0.05, half_y=0.05)
    faces = np.asarray(panel.faces)
    v = np.asarray(panel.vertices)
    # Remove both triangles of the inner square (1,1)-(2,2): squares are (i,j) with a = i*5+j.
    a = 1 * 5 + 1
    faces = faces[faces[:, 0] != a]
    line = np.array([[0.2, 0.0, 0.0], [0.21, 0.0, 0.0], [0.22, 0.0, 0.0]])
    extra_v = np.vstack([v, v[a] + [0.0, 0.0, 0.02], line])
    fin = [[0, 1, len(v)]]  # a third face on the boundary edge (0, 1) -> still 2 faces there
    fin2 = [[6, 7, len(v)], [7, 6, len(v)]]  # edge (6, 7) interior -> now 4 faces: non-manifold
    sliver = [[len(v) + 1, len(v) + 2, len(v) + 3]]  # three collinear vertices: zero area
    mesh = trimesh.Trimesh(
        vertices=extra_v, faces=np.vstack([faces, fin, fin2, sliver]), process=False
    )
    path = tmp_path / "defects.ply"
    mesh.export(str(path))
    _, rep = load_workpiece(path, units="m")
    assert rep.n_degenerate_faces == 1
    assert rep.n_nonmanifold_edges == 1
    assert rep.n_holes == 1  # the removed square; the outer rim is not a hole
    assert any("non-manifold" in w for w in rep.warnings)


def test_example_workpiece_is_regenerated_byte_for_byte(tmp_path: Path) -> None:
    from workbench.polishing.example_workpiece import main

    out = main(tmp_path / "panel.stl")
    assert out.read_bytes() == PANEL.read_bytes()


def test_units_errors_name_the_units_field(tmp_path: Path) -> None:
    p_mm = _save(make_panel(10, 8), tmp_path / "mm.stl", 1000.0)
    with pytest.raises(MeshError) as err:
        load_workpiece(p_mm, units="m")
    assert err.value.field == "units" and str(err.value) == f"units: {err.value.detail}"
    assert "1000x off" in err.value.detail
    with pytest.raises(MeshError) as missing:
        load_workpiece(tmp_path / "missing.stl")
    assert missing.value.field is None  # about the file, not a field of the call


def test_messages_name_the_file_as_told(tmp_path: Path) -> None:
    real = str(tmp_path / "missing.stl")
    with pytest.raises(MeshError) as err:
        load_workpiece(real, name="parts/panel.stl")
    assert "'parts/panel.stl' does not exist" in str(err.value) and real not in str(err.value)
    junk = tmp_path / "junk.stl"
    junk.write_text("this is not a mesh\n" * 20)
    with pytest.raises(MeshError) as bad:
        load_workpiece(junk, name="junk.stl")
    assert str(junk) not in str(bad.value) and "'junk.stl'" in str(bad.value)
