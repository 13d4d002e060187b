"""Robots are data (issue 26, part 7): no code tests a robot's name, and the MZ07 built from its
library record is the robot it was before (FK, limits, speeds, link meshes).

- `name_tests(source)` finds every comparison (==, !=, in, not in, match/case) of anything
  with a string literal that is a library robot's preset name or title; the tree has none,
  and its twin shows that it finds planted ones (and not other string tests).
- The MZ07: its record's `DHRobot` equals, bit for bit, the robot the old special case built
  (``DHRobot(MZ07_DH, MZ07_LIMITS, name="NACHI MZ07", max_velocity=MZ07_MAX_VELOCITY,
  convention=MZ07_CONVENTION)``) at random joints, and a table pinned before the change
  (limits, speeds, FK at four seeded joint vectors, the link meshes' sizes and volumes).
- The library imports the robot class; `dh_robot.py` imports no library, not even in a function.
"""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np

from workbench.kinematics import DHRobot, presets
from workbench.kinematics.robot_library import LIBRARY, library_robot, preset_robot

WORKBENCH = Path(__file__).resolve().parents[2] / "workbench"
ROBOT_WORDS = {w.lower() for r in LIBRARY.values() for w in (r.name, r.title)}


def _literals(node: ast.AST) -> list[str]:
    """Return the string constants of `node`: itself, or the items of a tuple/list/set literal."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, ast.Tuple | ast.List | ast.Set):
        return [s for elt in node.elts for s in _literals(elt)]
    return []


def name_tests(source: str) -> list[tuple[int, str]]:
    """Return (line, literal) of every comparison of a value with a robot name or title literal."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
        elif isinstance(node, ast.MatchValue):
            sides = [node.value]
        else:
            continue
        for side in sides:
            found += [(node.lineno, s) for s in _literals(side) if s.lower() in ROBOT_WORDS]
    return found


def test_no_module_tests_a_robot_name() -> None:
    hits = {
        str(p.relative_to(WORKBENCH)): name_tests(p.read_text())
        for p in sorted(WORKBENCH.rglob("*.py"))
    }
    assert {p: h for p, h in hits.items() if h} == {}
    assert len(hits) > 100  # the scan read the package


def test_name_tests_finds_planted_ones_twin() -> None:
    planted = (
        "def f(self, robot, preset, name):\n"
        "    if self.name == 'mz07':\n"  # 2
        "        pass\n"
        "    if 'UR5e' != robot.name.lower():\n"  # 4: any case
        "        pass\n"
        "    ok = preset in ('m10ia', 'kr6_r900_2')\n"  # 6: two
        "    match name:\n"
        "        case 'NACHI MZ07':\n"  # 8: a title
        "            pass\n"
        "    return os.name == 'posix' or name == 'goal'\n"  # 10: not robots
    )
    assert name_tests(planted) == [
        (2, "mz07"),
        (4, "UR5e"),
        (6, "m10ia"),
        (6, "kr6_r900_2"),
        (8, "NACHI MZ07"),
    ]
    assert name_tests("x = 'mz07'\nf('mz07')\n") == []  # naming a preset is not testing one


def test_the_robot_class_imports_no_library() -> None:
    """The library imports `DHRobot`; dh_robot.py imports neither module of the library."""
    tree = ast.parse((WORKBENCH / "kinematics" / "dh_robot.py").read_text())
    imported = {
        n.module if isinstance(n, ast.ImportFrom) else a.name
        for n in ast.walk(tree)
        if isinstance(n, ast.Import | ast.ImportFrom)
        for a in n.names
    }
    assert "workbench.kinematics.robot_library" not in imported
    assert not any(m and "robot_library" in m for m in imported)
    library = ast.parse((WORKBENCH / "kinematics" / "robot_library.py").read_text())
    assert any(
        isinstance(n, ast.ImportFrom) and n.module == "workbench.kinematics.dh_robot"
        for n in library.body
    )


def _old_mz07() -> DHRobot:
    """The MZ07 as the name-tested special case built it before issue 26."""
    return DHRobot(
        presets.MZ07_DH,
        presets.MZ07_LIMITS,
        name="NACHI MZ07",
        max_velocity=presets.MZ07_MAX_VELOCITY,
        convention=presets.MZ07_CONVENTION,
    )


def test_mz07_from_its_data_is_the_old_special_case_bit_for_bit() -> None:
    new, old = preset_robot("mz07"), _old_mz07()
    assert new.name == old.name == "NACHI MZ07"
    for field in ("dh", "limits", "max_velocity", "max_acceleration", "max_jerk"):
        assert getattr(new, field).tobytes() == getattr(old, field).tobytes(), field
    assert new.controller_limits is None and old.controller_limits is None
    assert new.convention == old.convention
    assert np.array_equal(library_robot("mz07").model_limits, presets.MZ07_LIMITS)
    q = np.random.default_rng(7).uniform(old.limits[:, 0], old.limits[:, 1], (200, 6))
    assert new.fk(q).tobytes() == old.fk(q).tobytes()
    for row in q[:20]:
        assert new.fk(row).tobytes() == old.fk(row).tobytes()  # the single-pose (pinocchio) path
    for a, b in zip(new.link_meshes(), old.link_meshes(), strict=True):
        assert a.vertices.tobytes() == b.vertices.tobytes()
        assert np.array_equal(a.faces, b.faces)


# Pinned before the change (old `DHRobot.preset("mz07")`, numpy default_rng(26) joints).
PINNED_Q = [
    [-0.04985302649875445, -1.47662014672268, -1.7640012678956825, 1.4117290690972193,
     -0.2592224383288668, 0.6074166927629205],
    [0.7970044886869387, -1.7212789310072019, 0.6145808713971181, -2.150096457824163,
     -1.5432821888797625, -1.9854140327505858],
    [2.744043818161554, -0.4057237494110679, -1.1054718221886004, -1.6096195011237178,
     -1.3597053416092493, 4.375956407866898],
    [-0.966367339239619, 1.0375649166633183, -0.9198592966992003, 2.767475729110289,
     -0.6116844846713057, 5.428505239240643],
]  # fmt: skip
PINNED_FLANGE_M = [
    [0.018422929429857498, 0.0850824631554496, 0.3758602446937793],
    [0.4279097167376785, 0.43499487393946284, -0.0732091148449537],
    [-0.22448996886413486, 0.11470191274472367, 0.21869134782105834],
    [0.10253976075026199, -0.10108450874592764, 0.6665409681806369],
]
PINNED_X_AXIS = [
    [-0.8536109383851194, -0.48420464931078494, -0.1920786907886856],
    [0.4956064538935959, 0.7998368540164477, 0.3385782772359838],
    [-0.765161513731146, 0.6435315953131546, 0.019873191448969593],
    [0.8095393068619776, 0.27361395998659743, 0.5194049591079017],
]
PINNED_LIMITS = [
    [-2.9670597283903604, 2.9670597283903604],
    [-2.356194490192345, 1.3962634015954636],
    [-1.1344640137963142, 3.3161255787892263],  # issue 28: J3 -65..190 (was -120..160)
    [-3.3161255787892263, 3.3161255787892263],
    [-3.6651914291880923, 0.5235987755982988],
    [-6.283185307179586, 6.283185307179586],
]
PINNED_VELOCITY = [
    7.853981633974483, 6.632251157578453, 9.075712110370514,
    9.599310885968812, 9.599310885968812, 17.453292519943297,
]  # fmt: skip
PINNED_MESHES = [  # (vertices, volume [m^3]), re-pinned for issue 28's real MZ07F frames
    (48, 0.006948896499020133),
    (76, 0.01245478307488041),
    (72, 0.00971645166469614),
    (48, 0.0033190073552236917),
    (72, 0.002571771530037798),
    (48, 0.0007928196266859621),
    (48, 2.2951919117403884e-05),
]


def test_mz07_matches_the_table_pinned_before_the_change() -> None:
    robot = preset_robot("mz07")
    assert robot.limits.tolist() == PINNED_LIMITS
    assert robot.max_velocity.tolist() == PINNED_VELOCITY
    T = robot.fk(np.array(PINNED_Q))
    # Issue 28 moved the preset to the real MZ07F (J2 axis 355 mm up, not 340; flange 78 mm
    # from the wrist centre, not 90): the same orientation, the flange 15 mm higher and
    # 12 mm back towards the wrist along its own z.
    moved = np.array(PINNED_FLANGE_M) + [0.0, 0.0, 0.015] - 0.012 * T[:, :3, 2]
    assert np.allclose(T[:, :3, 3], moved, rtol=0.0, atol=1e-15)
    assert np.allclose(T[:, 0, :3], PINNED_X_AXIS, rtol=0.0, atol=1e-15)
    meshes = robot.link_meshes()
    assert [len(m.vertices) for m in meshes] == [n for n, _ in PINNED_MESHES]
    assert np.allclose([m.volume for m in meshes], [v for _, v in PINNED_MESHES], rtol=1e-12)
