"""The B-rep as plain data (cad/sheet_brep.py) and the example parts' generator (bent_profile.py).

Against the generator's closed forms: the U-channel of projects/parts/u_channel.step has 14 faces
(2 caps, 8 flange faces and tips, 4 bend cylinders of radii r and r + t spanning 90 deg), its
volume is t L (Σ runs + Σ θ (r + t/2)), its box is the profile's; every loop edge's face lists
the loop's face as a neighbour. The committed STEP files are byte for byte what the generator writes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from bent_parts import PROFILES, brep_of_step, profile_step

from workbench.cad.bent_profile import profile_solid, step_bytes, tab_bracket, u_channel

ROOT = Path(__file__).resolve().parents[2]


def test_u_channel_faces() -> None:
    p = PROFILES["U"]
    brep = brep_of_step(profile_step("U"))
    assert brep.solids == 1 and len(brep.faces) == 14
    assert [f.index for f in brep.faces] == list(range(1, 15))
    kinds = [f.kind for f in brep.faces]
    assert kinds.count("cylinder") == 4 and kinds.count("plane") == 10
    cyl = [f for f in brep.faces if f.kind == "cylinder"]
    r, t = p.radii[0], p.thickness
    assert sorted(round(f.radius, 12) for f in cyl) == [r, r, r + t, r + t]
    assert all(f.convex == (f.radius > r + t / 2) for f in cyl)
    assert all(f.span == pytest.approx(np.pi / 2, abs=1e-12) for f in cyl)
    assert all(abs(f.axis @ [1, 0, 0]) == pytest.approx(1.0) for f in cyl)  # type: ignore[operator]
    exact = t * p.length * (sum(p.runs) + sum(a * (r + t / 2) for a in p.angles))
    assert brep.volume == pytest.approx(exact, rel=1e-12)
    c = r + t / 2
    lo = [0, -(c + t / 2), -t / 2]
    hi = [p.length, 0.100 + c + t / 2, c + 0.110]
    assert np.allclose(brep.bbox, [lo, hi], atol=1e-9)
    for f in brep.faces:
        if f.loop is not None:
            assert f.loop_faces is not None and len(f.loop_faces) == len(f.loop)
            for g in f.loop_faces:
                assert f.index in brep.faces[g - 1].neighbours
            assert np.abs((f.loop - f.origin) @ f.normal).max() < 1e-12  # on its plane


def test_the_example_step_is_what_the_generator_writes() -> None:
    p = u_channel(0.100, 0.110, 0.025, thickness=0.002, radius=0.00192, length=0.200)
    data = step_bytes(profile_solid(p), "u_channel")
    assert data == step_bytes(profile_solid(p), "u_channel")  # no time stamp
    assert data == (ROOT / "projects" / "parts" / "u_channel.step").read_bytes()
    bracket = step_bytes(tab_bracket(), "tab_bracket")
    assert bracket == (ROOT / "projects" / "parts" / "tab_bracket.step").read_bytes()
