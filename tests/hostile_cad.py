"""CAD files made to break readers (issue 29), and seeded mutations of the examples' CAD files.

Each maker returns the file's bytes; `HOSTILE` maps a case name to (file name, maker). The
STEP spheres are written as text (no OCP in the test process), as Open CASCADE writes
``BRepPrimAPI_MakeSphere``: one spherical face bounded by a vertex loop at its pole.
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STEP_EXAMPLES = (
    ROOT / "projects/parts/u_channel.step",
    ROOT / "projects/parts/tab_bracket.step",
    ROOT / "web_assets/parts/fixture_block.step",
    ROOT / "web_assets/workpieces/panel.step",
)
DXF_EXAMPLES = (ROOT / "projects/parts/pan_flat.dxf",)

_HEAD = """ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('hostile'),'2;1');
FILE_NAME('x','2026-01-01T00:00:00',('a'),('b'),'c','d','e');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));
ENDSEC;
DATA;
"""


def sphere_step(radius_mm: float) -> bytes:
    """Return a STEP AP214 file of a solid sphere of `radius_mm` about the origin."""
    r = f"{radius_mm:.6E}"
    body = f"""#1 = APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#2);
#2 = APPLICATION_CONTEXT('core data for automotive mechanical design processes');
#3 = SHAPE_DEFINITION_REPRESENTATION(#4,#10);
#4 = PRODUCT_DEFINITION_SHAPE('','',#5);
#5 = PRODUCT_DEFINITION('design','',#6,#9);
#6 = PRODUCT_DEFINITION_FORMATION('','',#7);
#7 = PRODUCT('s','s','',(#8));
#8 = PRODUCT_CONTEXT('',#2,'mechanical');
#9 = PRODUCT_DEFINITION_CONTEXT('part definition',#2,'design');
#10 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#11,#15),#40);
#11 = AXIS2_PLACEMENT_3D('',#12,#13,#14);
#12 = CARTESIAN_POINT('',(0.,0.,0.));
#13 = DIRECTION('',(0.,0.,1.));
#14 = DIRECTION('',(1.,0.,0.));
#15 = MANIFOLD_SOLID_BREP('',#16);
#16 = CLOSED_SHELL('',(#17));
#17 = ADVANCED_FACE('',(#18),#22,.T.);
#18 = FACE_BOUND('',#19,.T.);
#19 = VERTEX_LOOP('',#20);
#20 = VERTEX_POINT('',#21);
#21 = CARTESIAN_POINT('',(0.,0.,-{r}));
#22 = SPHERICAL_SURFACE('',#11,{r});
#40 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#44))
GLOBAL_UNIT_ASSIGNED_CONTEXT((#41,#42,#43)) REPRESENTATION_CONTEXT('Context #1','3D Context') );
#41 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );
#42 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );
#43 = ( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() );
#44 = UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#41,'distance_accuracy_value','');
"""
    return (_HEAD + body + "ENDSEC;\nEND-ISO-10303-21;\n").encode()


def deep_step(depth: int = 100_000) -> bytes:
    """Return the u-channel STEP with one entity whose list nests `depth` deep."""
    src = STEP_EXAMPLES[0].read_bytes()
    extra = b"#99999 = CARTESIAN_POINT(''," + b"(" * depth + b"0." + b")" * depth + b");\n"
    return src.replace(b"DATA;\n", b"DATA;\n" + extra, 1)


def broken_step() -> bytes:
    """Return the u-channel STEP with five VERTEX_POINT entities taken out: the edges that
    name them have unresolved references (OCP reports 10 load failures)."""
    text = STEP_EXAMPLES[0].read_text()
    dropped = 0
    out = []
    for chunk in text.split(";\n"):
        if dropped < 5 and re.match(r"\s*#\d+ = VERTEX_POINT", chunk):
            dropped += 1
            continue
        out.append(chunk)
    return ";\n".join(out).encode()


def many_entities_step(count: int) -> bytes:
    """Return a STEP file with `count` tiny entities."""
    rows = b"".join(b"#%d=DIRECTION('',(0.,0.,1.));\n" % (i + 1) for i in range(count))
    return _HEAD.encode() + rows + b"ENDSEC;\nEND-ISO-10303-21;\n"


# -- DXF (R12 text, written by hand: fast, and ezdxf's own writer refuses some of these) ---------------
def _dxf(entities: str, blocks: str = "") -> bytes:
    parts = ["0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n"]
    if blocks:
        parts.append("0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n")
    parts.append("0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n")
    return "".join(parts).encode()


def _line(a: tuple[float, float], b: tuple[float, float], layer: str = "0") -> str:
    return f"0\nLINE\n8\n{layer}\n10\n{a[0]}\n20\n{a[1]}\n30\n0\n11\n{b[0]}\n21\n{b[1]}\n31\n0\n"


def _outline(w: float = 100.0, h: float = 50.0) -> str:
    pts = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
    return "".join(_line(pts[i], pts[(i + 1) % 4]) for i in range(4))


def circle_dxf(radius: float = 1e9) -> bytes:
    """Return a flat pattern whose outline is a circle of `radius` mm."""
    return _dxf(
        f"0\nCIRCLE\n8\n0\n10\n0\n20\n0\n30\n0\n40\n{radius}\n" + _line((0, -1), (0, 1), "BEND")
    )


def spline_dxf(degree: int = 30) -> bytes:
    """Return an outline closed by one SPLINE of `degree` (degree + 1 control points), R2000."""
    import io

    import ezdxf

    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    n = degree + 1
    ctrl = [(100.0 * i / degree, 20.0 + (i % 2) * 10.0) for i in range(n)]
    msp.add_open_spline(ctrl, degree=degree)
    msp.add_lwpolyline([(100.0, 20.0), (100.0, 0.0), (0.0, 0.0), (0.0, 20.0)])
    msp.add_line((50.0, 0.0), (50.0, 20.0), dxfattribs={"layer": "BEND"})
    out = io.StringIO()
    doc.write(out)
    return out.getvalue().encode()


def block_bomb_dxf(levels: int = 8, fan: int = 10) -> bytes:
    """Return a drawing whose nested blocks expand to fan**levels lines."""
    blocks = "0\nBLOCK\n8\n0\n2\nB0\n70\n0\n10\n0\n20\n0\n30\n0\n3\nB0\n"
    blocks += "".join(_line((i, 0), (i, 1)) for i in range(fan)) + "0\nENDBLK\n8\n0\n"
    for level in range(1, levels):
        blocks += f"0\nBLOCK\n8\n0\n2\nB{level}\n70\n0\n10\n0\n20\n0\n30\n0\n3\nB{level}\n"
        blocks += "".join(
            f"0\nINSERT\n8\n0\n2\nB{level - 1}\n10\n{i}\n20\n0\n30\n0\n" for i in range(fan)
        )
        blocks += "0\nENDBLK\n8\n0\n"
    insert = f"0\nINSERT\n8\n0\n2\nB{levels - 1}\n10\n0\n20\n0\n30\n0\n"
    return _dxf(insert + _outline() + _line((50, 0), (50, 50), "BEND"), blocks)


def many_lines_dxf(count: int = 1_000_000) -> bytes:
    """Return a drawing of `count` short lines."""
    return _dxf("".join(_line((i * 1e-3, 0.0), (i * 1e-3, 1.0)) for i in range(count)))


def many_bends_dxf(count: int = 3000) -> bytes:
    """Return a 3000 mm blank with `count` parallel bend lines, each with its note."""
    w = 3000.0
    step = w / (count + 1)
    bends = "".join(
        _line((step * (i + 1), 0.0), (step * (i + 1), 50.0), "BEND")
        + f"0\nTEXT\n8\n0\n10\n{step * (i + 1)}\n20\n25\n30\n0\n40\n1\n1\nUP 90\n"
        for i in range(count)
    )
    return _dxf(_outline(w, 50.0) + bends)


HOSTILE: dict[str, tuple[str, Callable[[], bytes]]] = {
    "step_deep_nesting": ("deep.step", deep_step),
    "step_broken_references": ("broken.step", broken_step),
    "step_sphere_100m": ("sphere_100m.step", lambda: sphere_step(50_000.0)),
    "step_sphere_1e300": ("sphere_1e300.step", lambda: sphere_step(1e300)),
    "step_many_entities": ("many.step", lambda: many_entities_step(2_000_001)),
    "dxf_spline_degree_30": ("spline.dxf", spline_dxf),
    "dxf_circle_1e9": ("circle.dxf", circle_dxf),
    "dxf_block_bomb": ("bomb.dxf", block_bomb_dxf),
    "dxf_million_lines": ("lines.dxf", many_lines_dxf),
    "dxf_3000_bends": ("bends.dxf", many_bends_dxf),
}
"""The issue's hostile cases: name -> (file name, maker)."""


# -- mutations of the examples' files ------------------------------------------------------------------
_NUMBER = re.compile(rb"-?\d+\.\d*(?:E[+-]?\d+)?")
_REF = re.compile(rb"#\d+")
EXTREMES = (b"1.E+300", b"-1.E+300", b"1.E+09", b"0.", b"1.E-300", b"1.E+999", b"-0.")


def mutate(data: bytes, rng: random.Random, *, step: bool) -> tuple[bytes, str]:
    """Return `data` with one seeded mutation and its description."""
    lines = data.split(b"\n")
    what = rng.choice(("drop", "dup", "number", "ref", "truncate", "junk", "swap", "nest"))
    i = rng.randrange(len(lines))
    if what == "drop":
        del lines[i]
    elif what == "dup":
        lines.insert(i, lines[i])
    elif what == "swap":
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif what == "number":
        hits = [(k, m) for k, line in enumerate(lines) if (m := _NUMBER.search(line))]
        if hits:
            k, m = rng.choice(hits)
            lines[k] = lines[k][: m.start()] + rng.choice(EXTREMES) + lines[k][m.end() :]
    elif what == "ref" and step:
        refs = [k for k, line in enumerate(lines) if _REF.search(line)]
        if refs:
            k = rng.choice(refs)
            lines[k] = _REF.sub(b"#%d" % rng.randrange(1, 5000), lines[k], count=1)
    elif what == "truncate":
        return data[: rng.randrange(len(data))], f"truncate at {i}"
    elif what == "junk":
        lines.insert(i, bytes(rng.randrange(256) for _ in range(rng.randrange(1, 40))))
    elif what == "nest" and step:
        lines[i] = lines[i].replace(b"(", b"(" * 200, 1)
    return b"\n".join(lines), f"{what} at line {i}"
