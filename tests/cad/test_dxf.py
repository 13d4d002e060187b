"""DXF flat patterns (workbench.cad.dxf): drawings written here with ezdxf, read into parts.

Each recognised part's flat blank (its flanges placed flat plus its bend zones) reproduces
the drawing's outline (area, and every vertex within 0.1 mm); flange lengths equal the hand
computation (flat width = sum of flanges + sum of bend allowances, K from seed Table 1 by
hand); the example parts written as DXF read back as the same part, folding included; and
every bad file is refused naming the field and the fix.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import ezdxf
import numpy as np
import pytest
import shapely
from ezdxf.enums import TextEntityAlignment
from twins import load_module

from workbench.cad.dxf import read_flat_pattern
from workbench.cad.dxf_write import write_flat_pattern
from workbench.cad.flat_pattern import (
    FlatPattern,
    FlatPatternError,
)
from workbench.errors import InputError
from workbench.sheetmetal.flat_blank import flat_pattern_of_part
from workbench.sheetmetal.flat_split import part_spec_from_flat_pattern
from workbench.sheetmetal.part import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]
MM = 1e-3
FIELD = "bending.part_file (flat.dxf)"
PAN_DXF = ROOT / "projects" / "parts" / "pan_flat.dxf"


TWIN = load_module("tests/sheetmetal/test_flat_split.py", "flat_pattern_twin")


def _new(units: int = 4, version: str = "R2010") -> tuple[Any, Any]:
    doc = ezdxf.new(version, units=units)
    return doc, doc.modelspace()


def _bytes(doc: Any) -> bytes:
    stream = io.StringIO()
    doc.write(stream)
    return stream.getvalue().encode(doc.output_encoding)


def _note(msp: Any, text: str, at: tuple[float, float], mtext: bool = False) -> None:
    if mtext:
        msp.add_mtext(text, dxfattribs={"insert": at, "char_height": 2.5})
    else:
        msp.add_text(text, height=2.5).set_placement(at, align=TextEntityAlignment.MIDDLE_CENTER)


def _read(data: bytes, t_mm: float, r_mm: float | None = None, **kw: Any):
    pattern = read_flat_pattern(data, "flat.dxf", FIELD, **kw)
    r = None if r_mm is None else r_mm * MM
    spec = part_spec_from_flat_pattern(
        pattern, thickness=t_mm * MM, inner_radius=r, k_factor=None, field=FIELD
    )
    return pattern, SheetMetalPart.from_spec(spec)


def assert_blank_reproduces(outline: np.ndarray, part: SheetMetalPart) -> float:
    """Return the largest vertex distance [m] between `outline` [m] and the part's flat blank
    (areas equal, every vertex of each within 0.1 mm of a vertex of the other)."""
    blank = flat_pattern_of_part(part).outline
    a, b = shapely.Polygon(outline), shapely.Polygon(blank)
    assert b.area == pytest.approx(a.area, abs=0.1 * MM * a.length)
    assert a.symmetric_difference(b).area < 0.1 * MM * a.length
    worst = 0.0
    for p, q in ((outline, blank), (blank, outline)):
        d = np.linalg.norm(p[:, None, :] - q[None, :, :], axis=2).min(axis=1)
        worst = max(worst, float(d.max()))
    assert worst < 0.1 * MM
    return worst


def _u_channel(units: int = 4, scale: float = 1.0) -> tuple[bytes, float, list[float]]:
    """A U-channel flat 200 mm long: flanges 25, 100, 110 mm, t = r = 2 mm, notes "UP 90° R2"."""
    ba = np.pi / 2 * (2.0 + 0.30 * 2.0)  # r/t = 1: Table 1 K = 0.30
    a, b, c = 25.0, 100.0, 110.0
    width = a + b + c + 2 * ba
    doc, msp = _new(units)
    s = 1.0 / scale
    msp.add_lwpolyline([(0, 0), (200 * s, 0), (200 * s, width * s), (0, width * s)], close=True)
    for y in (a + ba / 2, a + ba + b + ba / 2):
        msp.add_line((0, y * s), (200 * s, y * s), dxfattribs={"layer": "BEND"})
        _note(msp, f"UP 90%%d R{2 * s:.12g}", (100 * s, y * s + 3 * s))
    return _bytes(doc), width, [a, b, c]


def test_a_u_channel_flat_reads_into_its_flanges() -> None:
    data, width, lengths = _u_channel()
    pattern, part = _read(data, 2.0)
    assert pattern.notes == ()
    assert [b.name for b in part.bends] == ["B1", "B2"]
    assert all(b.direction == 1 and b.inner_radius == pytest.approx(2 * MM) for b in part.bends)
    assert np.degrees([b.angle for b in part.bends]) == pytest.approx([90, 90])
    got = sorted(float(np.ptp(f.polygon[:, 1])) / MM for f in part.flanges)
    assert got == pytest.approx(sorted(lengths), abs=1e-9)  # solved back from the flat width
    worst = assert_blank_reproduces(pattern.outline, part)
    assert worst < 1e-9
    folded = part.fold(2)
    assert np.isfinite(folded.T_part_flange).all()


def test_inches_via_insunits_give_the_same_part() -> None:
    data_mm, _, _ = _u_channel()
    data_in, _, _ = _u_channel(units=1, scale=25.4)
    _, mm = _read(data_mm, 2.0)
    pattern, inch = _read(data_in, 2.0)
    assert pattern.notes == ()
    for f, g in zip(mm.flanges, inch.flanges, strict=True):
        assert np.abs(f.polygon - g.polygon).max() < 1e-9
    assert inch.bends[0].inner_radius == pytest.approx(2 * MM, abs=1e-12)


def test_unset_units_are_taken_as_mm_and_said() -> None:
    data, _, _ = _u_channel(units=0)
    pattern, part = _read(data, 2.0)
    assert pattern.notes == ("drawing units taken as mm ($INSUNITS not set)",)
    assert part.bend_lengths == pytest.approx([0.2, 0.2])


def test_an_l_with_the_layer_convention_bends_down() -> None:
    # t = 1.5, r = 3: r/t = 2, Table 1 K = 0.40; 45 deg: BA = (pi/4)(3 + 0.40 * 1.5)
    ba = np.pi / 4 * (3.0 + 0.40 * 1.5)
    doc, msp = _new()
    width = 50 + 30 + ba
    msp.add_lwpolyline([(0, 0), (80, 0), (80, width), (0, width)], close=True)
    y = 50 + ba / 2
    msp.add_line((80, y), (0, y), dxfattribs={"layer": "Bend_Down"})
    _note(msp, "45° R3", (40, y + 4), mtext=True)  # the direction comes from the layer
    pattern, part = _read(_bytes(doc), 1.5)
    (bend,) = part.bends
    assert bend.direction == -1 and np.degrees(bend.angle) == pytest.approx(45)
    assert part.bend_allowances[0] / MM == pytest.approx(ba)
    assert sorted(np.ptp(f.polygon[:, 1]) / MM for f in part.flanges) == pytest.approx([30, 50])
    assert_blank_reproduces(pattern.outline, part)
    # folded down: the far flange drops below the base (z < 0)
    T = part.fold(1).T_part_flange[1]
    z = (np.c_[part.flanges[1].polygon, np.zeros(4), np.ones(4)] @ T.T)[:, 2]
    assert z.max() < 1e-9 and z.min() < -20 * MM


def _pan(notes_only: bool) -> tuple[bytes, float]:
    """A four-sided pan flat: base 160 x 120, walls 30, open (relief) corners, t = r = 1.5."""
    ba = np.pi / 2 * (1.5 + 0.30 * 1.5)
    w, h, d = 160.0, 120.0, 30.0 + ba
    pts = [(0, -d), (w, -d), (w, 0), (w + d, 0), (w + d, h), (w, h), (w, h + d), (0, h + d),
           (0, h), (-d, h), (-d, 0), (0, 0)]  # fmt: skip
    doc, msp = _new()
    msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "CUT"})
    c = ba / 2
    lines = [((0, -c), (w, -c)), ((w + c, 0), (w + c, h)), ((w, h + c), (0, h + c)),
             ((-c, h), (-c, 0))]  # fmt: skip
    for k, (a, b) in enumerate(lines):
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        if notes_only or k < 2:
            msp.add_line(a, b, dxfattribs={"layer": "BEND"})
            _note(msp, "up 90%%d r1.5", mid, mtext=k == 1)
        else:
            msp.add_line(a, b, dxfattribs={"layer": "BEND_UP"})
            _note(msp, "BEND 90.0°", mid)
    return _bytes(doc), ba


@pytest.mark.parametrize("notes_only", [True, False], ids=["notes", "notes+layers"])
def test_a_pan_with_corner_reliefs_reads_into_base_and_four_walls(notes_only: bool) -> None:
    data, ba = _pan(notes_only)
    pattern, part = _read(data, 1.5, 1.5)  # the layer-convention notes give no radius
    assert [f.name for f in part.flanges] == ["F1", "F2", "F3", "F4", "F5"]
    areas = sorted(shapely.Polygon(f.polygon).area / MM**2 for f in part.flanges)
    assert areas == pytest.approx(sorted([160 * 120, 160 * 30, 160 * 30, 120 * 30, 120 * 30]))
    assert all(b.parent == 0 and b.direction == 1 for b in part.bends)
    assert part.bend_allowances / MM == pytest.approx([ba] * 4)
    assert_blank_reproduces(pattern.outline, part)
    walls = part.fold(4)
    for f in range(1, 5):  # every wall stands up, 30 mm plus the bend's rise
        T = walls.T_part_flange[f]
        P = np.c_[part.flanges[f].polygon, np.zeros(4), np.ones(4)] @ T.T
        assert P[:, 2].max() > 30 * MM


def _rounded_l(as_polyline: bool) -> bytes:
    """An L flat 100 x 90 with R5 outer corners, the outline as LINE + ARC entities drawn in
    shuffled order and directions (or as one LWPOLYLINE with bulges)."""
    doc, msp = _new()
    r, w, h = 5.0, 100.0, 90.0
    if as_polyline:
        b = np.tan(np.pi / 8)  # a 90 deg arc's bulge
        pts = [(r, 0, 0, 0, 0), (w - r, 0, 0, 0, b), (w, r, 0, 0, 0), (w, h - r, 0, 0, b),
               (w - r, h, 0, 0, 0), (r, h, 0, 0, b), (0, h - r, 0, 0, 0), (0, r, 0, 0, b)]  # fmt: skip
        msp.add_lwpolyline(pts, format="xyseb", close=True)
    else:
        msp.add_line((w - r, 0), (r, 0))  # reversed
        msp.add_arc((r, h - r), r, 90, 180)
        msp.add_line((w, r), (w, h - r))
        msp.add_arc((w - r, r), r, 270, 360)
        msp.add_line((0, h - r), (0, r))
        msp.add_arc((w - r, h - r), r, 0, 90)
        msp.add_line((r, h), (w - r, h))
        msp.add_arc((r, r), r, 180, 270)
    msp.add_line((0, 60), (w, 60), dxfattribs={"layer": "BEND"})
    _note(msp, "DOWN 90 R2", (50, 62))
    return _bytes(doc)


def test_an_outline_of_line_and_arc_chains_equals_its_bulged_polyline_twin() -> None:
    pattern, part = _read(_rounded_l(False), 2.0)
    twin_pattern, twin = _read(_rounded_l(True), 2.0)
    exact = 100 * 90 - 4 * (1 - np.pi / 4) * 25  # mm², four R5 corners
    for p in (pattern, twin_pattern):  # flattened within 0.01 mm: the area is a hair smaller
        assert shapely.Polygon(p.outline).area / MM**2 == pytest.approx(exact, abs=0.01 * 380)
    a, b = shapely.Polygon(pattern.outline), shapely.Polygon(twin_pattern.outline)
    assert a.hausdorff_distance(b) < 0.02 * MM  # both within the chordal tolerance of the arcs
    assert_blank_reproduces(pattern.outline, part)
    assert part.bends[0].direction == -1
    assert len(part.flanges[1].polygon) > 4  # the arcs' vertices are in the flanges


def test_a_binary_dxf_reads_as_its_ascii_twin() -> None:
    data, _, _ = _u_channel()
    doc = ezdxf.read(io.StringIO(data.decode()))
    binary = io.BytesIO()
    doc.write(binary, fmt="bin")
    assert binary.getvalue().startswith(b"AutoCAD Binary DXF")
    a, _ = _read(data, 2.0)
    b, _ = _read(binary.getvalue(), 2.0)
    assert np.abs(a.outline - b.outline).max() == 0.0


def test_a_flat_pattern_inside_an_inserted_block_is_read_where_it_is_placed() -> None:
    doc, msp = _new()
    block = doc.blocks.new("FLAT")
    block.add_lwpolyline([(0, 0), (200, 0), (200, 100), (0, 100)], close=True)
    block.add_line((0, 60), (200, 60), dxfattribs={"layer": "0"})  # takes the insert's layer
    block.add_text("UP 90 R2", height=2.5).set_placement((100, 62))
    msp.add_blockref("FLAT", (1000, 500), dxfattribs={"layer": "BEND"})
    msp.add_line((1000, 700), (1300, 700), dxfattribs={"layer": "DIMS"})  # an open annotation
    msp.add_circle((1500, 500), 5, dxfattribs={"layer": "BEND"})  # not a LINE: ignored
    with pytest.raises(FlatPatternError, match="no closed outline"):
        _read(_bytes(doc), 2.0)  # the block's outline took layer BEND too: not an outline
    block.query("LWPOLYLINE")[0].dxf.layer = "CUT"
    pattern, part = _read(_bytes(doc), 2.0)
    assert pattern.outline.min(axis=0) / MM == pytest.approx([1000, 500])
    assert pattern.bend_lines[0].start / MM == pytest.approx([1000, 560])
    assert pattern.notes == (
        "1 open curve chain(s) off the bend layers ignored",
        "1 curve(s) on the bend layers that are not LINEs ignored",
    )
    assert_blank_reproduces(pattern.outline, part)


def test_a_hole_becomes_a_hole_of_its_flange() -> None:
    doc, msp = _new()
    msp.add_lwpolyline([(0, 0), (200, 0), (200, 100), (0, 100)], close=True)
    msp.add_circle((50, 20), 5)
    msp.add_line((0, 60), (200, 60), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90° R2", (100, 62))
    pattern, part = _read(_bytes(doc), 2.0)
    assert len(pattern.holes) == 1 and not any("inner contour" in n for n in pattern.notes)
    holed = [f for f in part.flanges if f.holes]
    assert len(holed) == 1 and len(holed[0].holes) == 1
    # The blank loses the chorded circle's area: between the circles of radius r - CHORD_TOL
    # (every chord lies outside it) and r (every vertex on it).
    from workbench.cad.dxf_contours import CHORD_TOL

    lost = 0.2 * 0.1 - part.blank_area()
    assert np.pi * (0.005 - CHORD_TOL) ** 2 < lost < np.pi * 0.005**2


@pytest.mark.parametrize("name", list(TWIN.EXAMPLES))
@pytest.mark.parametrize(
    "style",
    [dict(), dict(layers=True), dict(units="in"), dict(version="R12"), dict(version="R2018")],
    ids=["notes", "layers", "inches", "R12", "R2018"],
)
def test_an_example_part_written_as_dxf_reads_back_as_the_same_part(name: str, style: dict) -> None:
    part = TWIN.load_part(name, TWIN.EXAMPLES[name])
    data = write_flat_pattern(flat_pattern_of_part(part), **style)
    pattern, again = _read(data, part.thickness / MM)
    TWIN.assert_same_part(part, again)
    assert_blank_reproduces(pattern.outline, again)


def make_pan_flat_dxf() -> bytes:
    """Return projects/parts/pan_flat.dxf: the pan's flat pattern, notes without radius (its
    cell's press gives 1.92 mm, set in dxf_pan_cell.json's part_import)."""
    part = TWIN.load_part("pan", TWIN.EXAMPLES["pan"])
    pattern = flat_pattern_of_part(part)
    bare = [
        type(ln)(ln.start, ln.end, ln.angle, ln.direction, None, ln.label)
        for ln in pattern.bend_lines
    ]
    return write_flat_pattern(FlatPattern(pattern.outline, tuple(bare)))


def test_the_example_pan_dxf_is_the_pans_flat_pattern() -> None:
    pattern, part = _read(PAN_DXF.read_bytes(), 1.5, 1.92)
    fresh, _ = _read(make_pan_flat_dxf(), 1.5, 1.92)
    assert np.abs(pattern.outline - fresh.outline).max() < 1e-12
    TWIN.assert_same_part(TWIN.load_part("pan", TWIN.EXAMPLES["pan"]), part)


def test_the_dxf_pan_cell_holds_the_pan_cells_part() -> None:
    from workbench import Workbench

    dxf = Workbench.open(ROOT / "projects" / "dxf_pan_cell.json").bending
    pan = Workbench.open(ROOT / "projects" / "pan_cell.json").bending
    TWIN.assert_same_part(pan.part, dxf.part)
    assert dxf.sequence == ["B1", "B2", "B4", "B3"]  # bL, bR, bK, bF


@pytest.mark.slow
def test_the_dxf_pan_cell_plans_the_pan_cells_cycle() -> None:
    from workbench import Workbench

    dxf = Workbench.open(ROOT / "projects" / "dxf_pan_cell.json").bending.plan()
    pan = Workbench.open(ROOT / "projects" / "pan_cell.json").bending.plan()
    assert dxf.ok and dxf.first_problem is None, dxf.summary()
    assert dxf.regrips == pan.regrips == 2
    assert dxf.cycle_time == pytest.approx(pan.cycle_time, rel=1e-9)


# ------------------------------------------------------------------ refusals


def _refused(data: bytes, *fix: str, r_mm: float | None = 2.0, **kw: Any) -> str:
    with pytest.raises(FlatPatternError) as err:
        _read(data, 2.0, r_mm, **kw)
    msg = str(err.value)
    assert isinstance(err.value, InputError) and err.value.field == FIELD
    assert msg.startswith(FIELD + ":"), msg
    for part in fix:
        assert part in msg, msg
    return msg


def _box(msp: Any) -> None:
    msp.add_lwpolyline([(0, 0), (200, 0), (200, 100), (0, 100)], close=True)


def test_refusals_name_the_field_and_the_fix() -> None:
    _refused(b"solid cube\nendsolid\n", "is not a DXF file", "export the flat pattern as DXF")
    _refused(b"AutoCAD Binary DXF\r\n\x1a\x00garbage", "not a readable DXF", "export the flat")

    doc, msp = _new()
    msp.add_line((0, 0), (200, 0))
    msp.add_line((200, 0), (200, 100))
    msp.add_line((200, 100), (0, 100))
    msp.add_line((0, 100), (0, 2))  # a 2 mm gap
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _refused(_bytes(doc), "no closed outline", "gap of 2 mm", "join its ends")

    doc, msp = _new()
    msp.add_lwpolyline([(0, 0), (200, 100), (200, 0), (0, 100)], close=True)  # a bow tie
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _refused(_bytes(doc), "crosses itself", "redraw it as a simple closed contour")

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BENDLINES"})
    _refused(_bytes(doc), "no bend lines", "'BENDLINES'", "'0'", "put the bend lines on layer")
    _note(msp, "UP 90 R2", (100, 52))
    _read(_bytes(doc), 2.0, bend_layer="bendlines")  # the fix: name the layer (any case)

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    msp.add_line((200, 20), (0, 20), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90", (100, 52))
    _note(msp, "PART 4711", (100, 22))  # not a bend note
    _refused(
        _bytes(doc),
        "bend line 2 (LINE on layer 'BEND' from (200, 20) to (0, 20) mm) has no bend angle",
        "put a TEXT note such as 'UP 90° R1.5'",
    )

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _note(msp, "90°", (100, 52))
    _refused(_bytes(doc), "bend line 1", "has no direction", "write UP or DOWN", "BEND_UP")

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND_UP"})
    _note(msp, "DOWN 90", (100, 52))
    _refused(_bytes(doc), "contradicts its layer 'BEND_UP'", "make them agree")

    doc, msp = _new()
    _box(msp)
    msp.add_line((10, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90", (100, 52))
    _refused(
        _bytes(doc),
        "from (10, 50) to (200, 50) mm",
        "does not cross the outline from edge to edge",
        "draw each bend line from edge to edge",
    )

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    msp.add_line((100, 0), (100, 100), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90", (150, 52))
    _note(msp, "UP 90", (102, 20))
    _refused(
        _bytes(doc),
        "bend line 1",
        "bend line 2",
        "cross or touch at (100, 50) mm",
        "add a corner relief",
    )

    doc, msp = _new()
    _box(msp)
    msp.add_lwpolyline([(300, 0), (400, 0), (400, 100)], close=True)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90", (100, 52))
    _refused(_bytes(doc), "holds 2 separate outlines", "one flat pattern per file")

    doc, msp = _new()
    _box(msp)
    msp.add_line((0, 50), (200, 50), dxfattribs={"layer": "BEND"})
    _note(msp, "UP 90", (100, 52))
    _refused(_bytes(doc), "has no inner radius", "give inner_radius", r_mm=None)


if __name__ == "__main__":  # regenerate the example: python tests/cad/test_dxf.py
    PAN_DXF.write_bytes(make_pan_flat_dxf())
    print(f"wrote {PAN_DXF}")
