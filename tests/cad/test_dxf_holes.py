"""Holes of a DXF flat pattern: drawn here with ezdxf (circle, slot, rectangle), read into the
flanges they fall in, written back, and kept by fold(unfold(part)).

The truth is ezdxf's own entities: a CIRCLE's centre and pi r^2, a bulged slot's centre and
length x width + pi r^2, a rectangle's centre and w x h. The model's holes are chords of the
curves within `dxf_contours.CHORD_TOL`, so their areas lie between the exact area less
perimeter x CHORD_TOL and the exact area.
"""

from __future__ import annotations

import io

import ezdxf
import numpy as np
import pytest
import shapely
from ezdxf.enums import TextEntityAlignment

from workbench.cad.dxf import read_flat_pattern
from workbench.cad.dxf_contours import CHORD_TOL
from workbench.cad.dxf_write import write_flat_pattern
from workbench.cad.flat_pattern import FlatPatternError
from workbench.sheetmetal.flat_blank import flat_pattern_of_part
from workbench.sheetmetal.flat_split import part_spec_from_flat_pattern
from workbench.sheetmetal.part import SheetMetalPart

MM = 1e-3
FIELD = "bending.part_file (holes.dxf)"
T_MM = 2.0


def drawing(extra=None) -> tuple[bytes, list[tuple[np.ndarray, float, float]]]:
    """Return a DXF (200 x 100 mm, one UP 90 deg bend at y = 60) and its holes' truth:
    (centre [m], exact area [m^2], perimeter [m]) from the entities' own parameters."""
    doc = ezdxf.new("R2010", units=4)
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (200, 0), (200, 100), (0, 100)], close=True)
    circle = msp.add_circle((40, 25), 5)
    # A slot 30 mm between its end centres, 10 mm wide: two straight sides, two half circles.
    slot = msp.add_lwpolyline(
        [(90, 20, 0, 0, 0), (120, 20, 0, 0, 1), (120, 30, 0, 0, 0), (90, 30, 0, 0, 1)],
        format="xyseb",
        close=True,
    )
    rect = msp.add_lwpolyline([(140, 75), (170, 75), (170, 90), (140, 90)], close=True)
    if extra is not None:
        extra(msp)
    msp.add_line((0, 60), (200, 60), dxfattribs={"layer": "BEND"})
    msp.add_text("UP 90%%d R2", height=2.5).set_placement(
        (100, 62), align=TextEntityAlignment.MIDDLE_CENTER
    )
    r = circle.dxf.radius
    pts = np.array(slot.get_points("xy"))
    half_w = abs(slot.get_points("xyb")[1][2]) * (pts[2, 1] - pts[1, 1]) / 2  # bulge 1: r = h/2
    length = np.linalg.norm(pts[1] - pts[0])
    rp = np.array(rect.get_points("xy"))
    w, h = np.ptp(rp, axis=0)
    truth = [
        (np.array(circle.dxf.center)[:2] * MM, np.pi * r**2 * MM**2, 2 * np.pi * r * MM),
        (
            pts.mean(axis=0) * MM,
            (length * 2 * half_w + np.pi * half_w**2) * MM**2,
            (2 * length + 2 * np.pi * half_w) * MM,
        ),
        (rp.mean(axis=0) * MM, w * h * MM**2, 2 * (w + h) * MM),
    ]
    stream = io.StringIO()
    doc.write(stream)
    return stream.getvalue().encode(doc.output_encoding), truth


def read(data: bytes) -> SheetMetalPart:
    pattern = read_flat_pattern(data, "holes.dxf", FIELD, bend_layer="BEND")
    spec = part_spec_from_flat_pattern(
        pattern, thickness=T_MM * MM, inner_radius=None, k_factor=None, field=FIELD
    )
    return SheetMetalPart.from_spec(spec)


def holes_in_part_frame(part: SheetMetalPart) -> list[tuple[str, shapely.Polygon]]:
    """Return (flange name, hole) for every hole placed flat in the part frame."""
    T = part.fold(0).T_part_flange
    return [
        (fl.name, shapely.Polygon(h @ T[f, :2, :2].T + T[f, :2, 3]))
        for f, fl in enumerate(part.flanges)
        for h in fl.holes
    ]


def match(holes: list[tuple[str, shapely.Polygon]], truth) -> list[str]:
    """Assert each true hole has one model hole of its centre and area; return their flanges."""
    assert len(holes) == len(truth)
    names = []
    for centre, area, perimeter in truth:
        d = [np.linalg.norm(np.asarray(p.centroid.coords[0]) - centre) for _, p in holes]
        k = int(np.argmin(d))
        assert d[k] < 1e-9  # symmetric chording keeps the centre
        assert area - perimeter * CHORD_TOL <= holes[k][1].area <= area * (1 + 1e-12)
        names.append(holes[k][0])
    return names


def test_dxf_holes_become_flange_holes_written_back_and_refolded() -> None:
    data, truth = drawing()
    part = read(data)
    names = match(holes_in_part_frame(part), truth)
    base, wall = part.flanges[0].name, part.flanges[1].name
    assert names == [base, base, wall]  # below the bend line: base; the rectangle is above it
    # The folded solid loses the holes' volume (closed form within the chords).
    mesh = part.fold(len(part.bends)).solid()
    assert mesh.is_watertight
    assert mesh.volume == pytest.approx(part.thickness * part.blank_area(), rel=1e-9)
    # Written back: the DXF holds the outline and the three holes as closed polylines ...
    written = write_flat_pattern(flat_pattern_of_part(part), bend_layer="BEND")
    doc = ezdxf.read(io.StringIO(written.decode("utf-8")))
    closed = [e for e in doc.modelspace().query("LWPOLYLINE") if e.closed]
    assert len(closed) == 4
    # ... and reads back as the same part, holes at the same places with the same areas.
    again = read(written)
    before, after = holes_in_part_frame(part), holes_in_part_frame(again)
    exact = [(np.asarray(p.centroid.coords[0]), p.area, 0.0) for _, p in before]
    for (_, p), (_, q) in zip(before, after, strict=True):
        assert p.symmetric_difference(q).area < 1e-12
    assert match(after, exact) == [f.name for f in part.flanges for _ in f.holes]
    # fold(unfold(part)): each flange keeps its holes in its own frame.
    spec = part_spec_from_flat_pattern(
        flat_pattern_of_part(part),
        thickness=part.thickness,
        inner_radius=None,
        k_factor=None,
        field=FIELD,
    )
    refolded = SheetMetalPart.from_spec(spec)
    for f, g in zip(part.flanges, refolded.flanges, strict=True):
        assert len(f.holes) == len(g.holes)
        for h, k in zip(f.holes, g.holes, strict=True):
            assert shapely.Polygon(h).symmetric_difference(shapely.Polygon(k)).area < 1e-12


def test_hole_in_a_bend_zone_is_refused_naming_the_bend() -> None:
    # 1 mm off the bend line, 0.8 mm across: inside the zone (about 2.3 mm each side), not on the line.
    data, _ = drawing(lambda msp: msp.add_circle((100, 61.2), 0.4))
    with pytest.raises(FlatPatternError, match="bend zone of bend line 1") as exc:
        read(data)
    assert "inner contour" in str(exc.value) and "centre 100, 61.2 mm" in str(exc.value)
