"""Sheet-metal part: seed part (Fig. 7), random parts, solids against trimesh, bad input."""

from __future__ import annotations

import numpy as np
import pytest
from seed_part import seed_spec

from workbench.errors import InputError
from workbench.sheetmetal import SheetMetalPart, bend_allowance


def rect(w: float, h: float) -> list[list[float]]:
    return [[0, 0], [w, 0], [w, h], [0, h]]


def check_state(part: SheetMetalPart, state) -> None:
    mesh = state.solid()
    assert mesh.is_watertight and mesh.is_winding_consistent
    assert mesh.volume == pytest.approx(part.thickness * part.blank_area(), rel=5e-3)
    obbs = state.flange_obbs()
    inside = obbs.reshape(-1, 1).contains(mesh.vertices[None], tol=1e-9).any(axis=0)
    assert inside.all(), f"{(~inside).sum()} vertices outside the flange OBBs"


def test_seed_part_folds_without_intersection_and_blank_length() -> None:
    part = SheetMetalPart.from_spec(seed_spec())  # checks every step of the sequence
    assert [b.name for b in part.bends] == ["b23", "b45", "b12", "b14", "b16", "b17"]
    t = part.thickness
    flat = part.fold(0)
    corners = np.concatenate(
        [
            f.polygon @ flat.T_part_flange[i, :2, :2].T + flat.T_part_flange[i, :2, 3]
            for i, f in enumerate(part.flanges)
        ]
    )
    ba = {b.name: bend_allowance(b.inner_radius, t, b.angle) for b in part.bends}
    # y: lip 5, wall 4, base 1, wall 2, lip 3; x: wall 7, base 1, wall 6.
    length_y = 0.020 + 0.040 + 0.200 + 0.040 + 0.020 + ba["b45"] + ba["b14"] + ba["b12"] + ba["b23"]
    length_x = 0.040 + 0.300 + 0.040 + ba["b16"] + ba["b17"]
    assert np.ptp(corners[:, 1]) == pytest.approx(length_y, abs=1e-12)
    assert np.ptp(corners[:, 0]) == pytest.approx(length_x, abs=1e-12)
    for step in np.linspace(0, 6, 13):
        check_state(part, part.fold(step))
    # Folded: wall 2 stands on the base's +y edge, the lip 3 points back over the base.
    T = part.fold(6).T_part_flange
    np.testing.assert_allclose(T[1, :3, 1], [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(T[2, :3, 1], [0, -1, 0], atol=1e-12)


def test_solid_matches_closed_form_single_bend() -> None:
    t, r, w = 0.002, 0.004, 0.05
    spec = {
        "thickness": t,
        "flanges": [{"polygon": rect(w, 0.03)}, {"polygon": rect(w, 0.02)}],
        "bends": [
            {
                "parent": 0,
                "parent_edge": 2,
                "child": 1,
                "child_edge": 0,
                "included_angle": np.pi / 2,
                "inner_radius": r,
            }
        ],
    }
    part = SheetMetalPart.from_spec(spec)
    mesh = part.fold(1).solid()
    # Outer corner of a 90 deg up-bend: the outer surface's tangent lines meet at y = 0.03 + r + t.
    assert mesh.bounds[1, 1] == pytest.approx(0.03 + r + t, abs=1e-12)
    assert mesh.bounds[1, 2] == pytest.approx(r + t / 2 + 0.02, abs=1e-12)
    assert mesh.volume == pytest.approx(t * w * (0.05 + bend_allowance(r, t, np.pi / 2)), rel=1e-12)


def random_spec(rng: np.random.Generator, n_bends: int) -> dict:
    t = rng.uniform(0.0008, 0.003)
    W, H = rng.uniform(0.04, 0.12), rng.uniform(0.03, 0.1)
    flanges = [{"name": "base", "polygon": rect(W, H)}]
    bends = []
    sides = min(int(rng.integers(0, 3)), n_bends - 1)
    chain = n_bends - sides
    direction = rng.choice(["up", "down"])

    def bend(parent: int, pe: int, child: int, ce: int, d: str) -> dict:
        return {
            "parent": parent,
            "parent_edge": pe,
            "child": child,
            "child_edge": ce,
            "direction": d,
            "included_angle": np.radians(rng.uniform(15, 170)),
            "inner_radius": t * float(np.exp(rng.uniform(np.log(0.5), np.log(10)))),
        }

    for k in range(chain):
        L = rng.uniform(15, 40) * t
        last = k == chain - 1
        poly = (
            [[0, 0], [W, 0], [W - 0.2 * W, L], [0.2 * W, L]]
            if last and rng.random() < 0.5
            else rect(W, L)
        )
        flanges.append({"polygon": poly})
        bends.append(bend(k if k else 0, 2, len(flanges) - 1, 0, str(direction)))
        direction = "down" if direction == "up" else "up"
    for side_edge in (1, 3)[:sides]:
        flanges.append({"polygon": rect(H, rng.uniform(5, 15) * t)})
        bends.append(bend(0, side_edge, len(flanges) - 1, 0, str(rng.choice(["up", "down"]))))
    order = rng.permutation(len(bends))
    for i, b in enumerate(bends):
        b["name"] = f"b{i}"
    return {
        "thickness": t,
        "flanges": flanges,
        "bends": bends,
        "sequence": [f"b{i}" for i in order],
    }


def test_random_parts_watertight_volume_and_obb_cover() -> None:
    rng = np.random.default_rng(0)
    ok = rejected = 0
    for trial in range(30):
        spec = random_spec(rng, 1 + trial % 10)
        try:
            part = SheetMetalPart.from_spec(spec)
        except InputError as exc:
            assert "intersect" in str(exc)
            rejected += 1
            continue
        ok += 1
        n = len(part.bends)
        for step in sorted({0, n, int(rng.integers(0, n + 1)), float(rng.uniform(0, n))}):
            check_state(part, part.fold(step))
    assert ok >= 20


def test_intersecting_sequence_is_reported() -> None:
    # Two 160 deg up-bends on long flanges fold the third flange through the first.
    spec = {
        "thickness": 0.002,
        "flanges": [
            {"name": "A", "polygon": rect(0.05, 0.1)},
            {"name": "B", "polygon": rect(0.05, 0.02)},
            {"name": "C", "polygon": rect(0.05, 0.1)},
        ],
        "bends": [
            {
                "name": "b1",
                "parent": "A",
                "parent_edge": 2,
                "child": "B",
                "child_edge": 0,
                "included_angle": np.radians(20),
                "inner_radius": 0.002,
            },
            {
                "name": "b2",
                "parent": "B",
                "parent_edge": 2,
                "child": "C",
                "child_edge": 0,
                "included_angle": np.radians(20),
                "inner_radius": 0.002,
            },
        ],
    }
    with pytest.raises(InputError, match="'A' and 'C' intersect after bend 'b2'"):
        SheetMetalPart.from_spec(spec)


def base_spec() -> dict:
    return {
        "thickness": 0.002,
        "flanges": [
            {"name": "A", "polygon": rect(0.05, 0.05)},
            {"name": "B", "polygon": rect(0.05, 0.02)},
            {"name": "C", "polygon": rect(0.05, 0.02)},
        ],
        "bends": [
            {
                "name": "b1",
                "parent": "A",
                "parent_edge": 2,
                "child": "B",
                "child_edge": 0,
                "included_angle": np.pi / 2,
                "inner_radius": 0.002,
            },
            {
                "name": "b2",
                "parent": "A",
                "parent_edge": 0,
                "child": "C",
                "child_edge": 0,
                "included_angle": np.pi / 2,
                "inner_radius": 0.002,
            },
        ],
    }


@pytest.mark.parametrize(
    "change, word",
    [
        (lambda s: s.update(thickness=-0.001), "thickness"),
        (lambda s: s["bends"][0].update(inner_radius=0.0005), r"inner_radius.*below Table 1"),
        (lambda s: s["bends"][0].update(included_angle=np.pi), r"included_angle.*\(0, 180\)"),
        (lambda s: s["bends"][0].update(included_angle=0.0), r"included_angle.*\(0, 180\)"),
        (lambda s: s["bends"][1].update(included_angle=-0.5), "included_angle"),
        (lambda s: s.update(sequence=["b1", "b1"]), r"repeated \['b1'\], missing \['b2'\]"),
        (lambda s: s.update(sequence=["b2"]), r"missing \['b1'\]"),
        (lambda s: s["bends"][0].update(child="Z"), "no flange 'Z'"),
        (lambda s: s["bends"][0].update(parent_edge=7), "parent_edge"),
        (lambda s: s["flanges"][1].update(polygon=rect(0.04, 0.02)), "must match"),
        (lambda s: s["flanges"][1].update(polygon=rect(0.05, 0.02)[::-1]), "counter-clockwise"),
    ],
)
def test_bad_input(change, word) -> None:
    spec = base_spec()
    change(spec)
    with pytest.raises(InputError, match=word):
        SheetMetalPart.from_spec(spec)


def test_bad_grasp_and_step() -> None:
    part = SheetMetalPart.from_spec(base_spec())
    with pytest.raises(InputError, match=r"no flange 'Q'; valid are \['A', 'B', 'C'\]"):
        part.fold(2).obb_tree("Q")
    with pytest.raises(InputError, match="no flange 5"):
        part.fold(2).obb_tree(5)
    with pytest.raises(InputError, match="step"):
        part.fold(3)
