"""`wb.calibration` end to end: readings made from a known truth by the robot's kinematics (IK,
checked by pinocchio), written as a pendant shows them, recovered within the noise's bound."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from calibration_synth import joint_csv, known_csv, point_csv, touch_flanges
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform, make_transform
from workbench.kinematics.robot_library import library_robot
from workbench.project.calibration_readings import parse_readings
from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[2]
MZ07 = ROOT / "projects" / "mz07_cell.json"


_OPENED: dict[str, Workbench] = {}


def _seeds(n: int) -> list[object]:
    """Return seeds 0..n-1, all but the first marked slow (the unit suite keeps one)."""
    return [0, *(pytest.param(s, marks=pytest.mark.slow) for s in range(1, n))]


def _opened(preset: str) -> Workbench:
    """Return a workbench on the MZ07 cell with the library robot `preset` (one per preset;
    calibrations do not change the project, tests that apply use `wb`)."""
    if preset not in _OPENED:
        wb = Workbench.open(MZ07)
        if preset != "mz07":
            wb.use_robot(preset)
        _OPENED[preset] = wb
    return _OPENED[preset]


@pytest.fixture
def wb() -> Workbench:
    return _opened("mz07")


def _with_robot(_: Workbench, preset: str) -> Workbench:
    return _opened(preset)


def _read_back(wb: Workbench, text: str, T_ft: np.ndarray) -> np.ndarray:
    """Return the tip positions (n, 3) [m] the CSV's joints give with TCP `T_ft`, by pinocchio."""
    import pinocchio as pin

    readings = parse_readings(text, source="r", robot=wb.project.robot, dof=wb.robot.dof)
    model, data = wb.robot.pinocchio_model()
    out = []
    for q in readings.joints:
        pin.framesForwardKinematics(model, data, q)
        M = data.oMf[model.nframes - 1]
        out.append(M.rotation @ T_ft[:3, 3] + M.translation)
    return np.array(out)


# -- TCP ---------------------------------------------------------------------------------------
def _tcp_case(wb: Workbench, seed: int, n: int = 5) -> tuple[str, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    T_ft = make_transform(np.eye(3), rng.uniform([-0.03, -0.03, 0.12], [0.03, 0.03, 0.22]))
    P = rng.uniform([0.35, -0.15, 0.1], [0.5, 0.15, 0.3])
    flanges = []
    for _ in range(n):
        R = Rotation.from_rotvec(rng.uniform(-0.6, 0.6, 3)) * Rotation.from_euler("x", np.pi)
        flanges.append(make_transform(R.as_matrix(), P) @ invert_transform(T_ft))
    return joint_csv(wb, [f"p{i}" for i in range(n)], flanges, rng, 0.01), T_ft, P


@pytest.mark.parametrize("preset", ["mz07", "m10ia", "irb1200_7_70"])
@pytest.mark.parametrize("seed", _seeds(6))
def test_tcp_is_recovered_within_the_noise_bound(wb: Workbench, preset: str, seed: int) -> None:
    wb = _with_robot(wb, preset)
    text, T_ft, P = _tcp_case(wb, seed)
    result = wb.calibration.tcp(text)
    # The bound: the noise moved each true tip by e_i (read back through pinocchio); the
    # least-squares TCP misses the truth by at most ||A^+|| |e| (tests/calibration/test_tcp.py).
    tips = _read_back(wb, text, T_ft)
    readings = parse_readings(text, source="r", robot=wb.project.robot, dof=wb.robot.dof)
    R = wb.robot.fk(readings.joints)[:, :3, :3]
    A = np.concatenate([R, -np.broadcast_to(np.eye(3), (len(R), 3, 3))], axis=2).reshape(-1, 6)
    bound = np.linalg.norm(np.linalg.pinv(A), 2) * np.linalg.norm(tips - P)
    assert np.linalg.norm(result.T[:3, 3] - T_ft[:3, 3]) <= bound + 1e-9
    assert 0.0 < bound < 2e-3  # not vacuous: 0.01 deg of joint noise, a bound under 2 mm
    assert result.kind == "tcp" and result.labels == tuple(f"p{i}" for i in range(5))
    assert "mean error" in result.summary() and "max error" in result.summary()


def test_tcp_and_z_x_through_the_readings_file(wb: Workbench) -> None:
    rng = np.random.default_rng(5)
    R_ft = Rotation.from_euler("xyz", [0.0, 0.4, 0.2]).as_matrix()
    T_ft = make_transform(R_ft, [0.01, 0.0, 0.16])
    P = np.array([0.45, 0.0, 0.2])
    flanges = []
    for _ in range(4):
        R = Rotation.from_rotvec(rng.uniform(-0.5, 0.5, 3)) * Rotation.from_euler("x", np.pi)
        flanges.append(make_transform(R.as_matrix(), P) @ invert_transform(T_ft))
    T_z, T_x = flanges[-1].copy(), flanges[-1].copy()
    T_z[:3, 3] -= T_z[:3, :3] @ R_ft[:, 2] * 0.1
    T_x[:3, 3] -= T_x[:3, :3] @ R_ft[:, 0] * 0.1
    text = joint_csv(wb, ["a", "b", "c", "d", "z", "x"], [*flanges, T_z, T_x], rng)
    result = wb.calibration.tcp(text)
    assert np.allclose(result.T, T_ft, atol=1e-6)
    assert "TCP and Z, X" in result.summary()


def test_tcp_refuses_position_readings_and_alike_orientations(wb: Workbench) -> None:
    with pytest.raises(InputError, match="needs joint readings"):
        wb.calibration.tcp("label,x,y,z\na,1,2,3\nb,1,2,3\nc,1,2,3\nd,1,2,3\n")
    rng = np.random.default_rng(1)
    T_ft = wb.setup.T_flange_tcp
    P = np.array([0.45, 0.0, 0.2])
    R = Rotation.from_euler("x", np.pi).as_matrix()
    same = [make_transform(R, P) @ invert_transform(T_ft)] * 4
    with pytest.raises(InputError, match="orientations are too alike"):
        wb.calibration.tcp(joint_csv(wb, ["a", "b", "c", "d"], same, rng, 0.01))


# -- work objects ------------------------------------------------------------------------------
def _frame(rng: np.random.Generator) -> np.ndarray:
    R = Rotation.from_euler("xyz", [*rng.uniform(-0.1, 0.1, 2), rng.uniform(-1, 1)]).as_matrix()
    return make_transform(R, rng.uniform([0.35, -0.15, 0.05], [0.45, 0.15, 0.2]))


def _bound(noise: np.ndarray, local: np.ndarray) -> tuple[float, float]:
    """Return (position [m], angle [rad]) bounds of a three-point frame from point errors (3,)
    [m] and the points (3, 3) in the frame: the X axis turns by at most the sum of the errors
    over the shortest baseline, the origin moves by the errors plus that turn over the reach."""
    baseline = min(np.linalg.norm(local[1] - local[0]), abs(local[2][1]))
    angle = 2.0 * noise.sum() / (baseline - noise.sum())
    return noise.sum() + np.linalg.norm(local, axis=1).max() * angle, angle


@pytest.mark.parametrize(
    ("preset", "labels", "local"),
    [
        ("kr6_r900_2", ["origin", "x", "y"], [[0, 0, 0], [0.2, 0, 0], [0.05, 0.15, 0]]),
        ("m10ia", ["origin", "x", "y"], [[0, 0, 0], [0.15, 0, 0], [-0.03, 0.12, 0]]),
        ("irb1200_7_70", ["x1", "x2", "y1"], [[-0.05, 0, 0], [0.15, 0, 0], [0, 0.12, 0]]),
    ],
)
@pytest.mark.parametrize("kind", ["joints", "points"])
@pytest.mark.parametrize("seed", _seeds(4))
def test_three_point_work_object_within_the_noise_bound(
    wb: Workbench, preset: str, labels: list[str], local: list[list[float]], kind: str, seed: int
) -> None:
    wb = _with_robot(wb, preset)
    rng = np.random.default_rng(seed)
    T_world_wobj = _frame(rng)
    pts = np.asarray(local) @ T_world_wobj[:3, :3].T + T_world_wobj[:3, 3]  # world = base here
    if kind == "joints":
        text = joint_csv(wb, labels, touch_flanges(wb, pts, rng), rng, 0.01)
        noise = np.linalg.norm(_read_back(wb, text, wb.setup.T_flange_tcp) - pts, axis=1)
    else:
        text = point_csv(wb, labels, pts, rng, rng.uniform(0.02, 0.1))
        T_bc = library_robot(preset).T_base_controller
        rows = [line.split(",")[1:] for line in text.splitlines()[1:]]
        read = np.array(rows, float) * 1e-3 + T_bc[:3, 3]
        noise = np.linalg.norm(read - pts, axis=1)
    result = wb.calibration.work_object(text, name="fixture")
    pos_bound, angle_bound = _bound(noise, np.asarray(local))
    dR = result.T[:3, :3].T @ T_world_wobj[:3, :3]
    assert np.linalg.norm(result.T[:3, 3] - T_world_wobj[:3, 3]) <= pos_bound
    assert np.arccos(np.clip((np.trace(dR) - 1) / 2, -1, 1)) <= angle_bound
    assert result.kind == "work_object" and result.name == "fixture"


def test_three_point_refuses_collinear_points_naming_them(wb: Workbench) -> None:
    text = "label,x,y,z\norigin,400,0,100\nx,500,0,100\ny,600,0.5,100\n"
    with pytest.raises(InputError, match=r"collinear: y lies 0\.50 mm from the line origin-x"):
        wb.calibration.work_object(text, name="w")
    with pytest.raises(InputError, match="points origin and x are 2.00 mm apart"):
        wb.calibration.work_object("label,x,y,z\norigin,400,0,0\nx,402,0,0\ny,400,90,0", name="w")


def _fit_case(
    wb: Workbench, seed: int, outlier: str | None
) -> tuple[str, str, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    T_world_wobj = _frame(rng)
    labels = [f"h{i}" for i in range(6)]
    local = rng.uniform([-0.1, -0.1, 0.0], [0.1, 0.1, 0.05], (6, 3))
    pts = local @ T_world_wobj[:3, :3].T + T_world_wobj[:3, 3]
    measured = pts.copy()
    if outlier is not None:
        measured[labels.index(outlier)] += [0.005, 0.0, 0.0]  # a point touched 5 mm off
    text = point_csv(wb, labels, measured, rng, rng.uniform(0.02, 0.1))
    return text, known_csv(labels, local), T_world_wobj, local


@pytest.mark.parametrize(
    "seed", [0, 1, *(pytest.param(s, marks=pytest.mark.slow) for s in range(2, 12))]
)
def test_fit_work_object_within_the_noise_bound_and_names_an_outlier(
    wb: Workbench, seed: int
) -> None:
    text, known, T_true, local = _fit_case(wb, seed, "h3" if seed % 2 else None)
    result = wb.calibration.work_object(text, name="part", method="fit", known_csv=known)
    assert result.dropped == (("h3",) if seed % 2 else ())
    noise = np.array([float(v) for line in text.splitlines()[1:] for v in line.split(",")[1:]])
    noise = np.linalg.norm(
        noise.reshape(-1, 3) * 1e-3 - (local @ T_true[:3, :3].T + T_true[:3, 3]), axis=1
    )
    kept = [i for i in range(6) if f"h{i}" not in result.dropped]
    mapped = local @ result.T[:3, :3].T + result.T[:3, 3]
    truth = local @ T_true[:3, :3].T + T_true[:3, 3]
    assert np.max(np.linalg.norm(mapped - truth, axis=1)) <= 3.0 * noise[kept].max()
    if seed % 2:
        assert "dropped as outliers: h3" in result.summary()


def test_fit_needs_known_points_for_every_reading(wb: Workbench) -> None:
    text, known, _, _ = _fit_case(wb, 0, None)
    with pytest.raises(InputError, match="give the known points"):
        wb.calibration.work_object(text, name="part", method="fit")
    short = "\n".join(known.splitlines()[:-1])
    with pytest.raises(
        InputError, match=r"readings line 7, column 1 \(label\): reading 'h5' has no"
    ):
        wb.calibration.work_object(text, name="part", method="fit", known_csv=short)


# -- the robot's place -------------------------------------------------------------------------
@pytest.mark.parametrize("seed", _seeds(6))
def test_robot_base_is_recovered_within_the_noise_bound(wb: Workbench, seed: int) -> None:
    rng = np.random.default_rng(seed)
    T_true = make_transform(
        Rotation.from_euler("z", rng.uniform(-0.02, 0.02)).as_matrix(), rng.uniform(-0.01, 0.01, 3)
    )  # the robot stands a little off
    world = rng.uniform([0.3, -0.2, 0.0], [0.5, 0.2, 0.2], (5, 3))  # marks on the press
    in_base = world @ T_true[:3, :3] - T_true[:3, 3] @ T_true[:3, :3]
    labels = [f"m{i}" for i in range(5)]
    text = joint_csv(wb, labels, touch_flanges(wb, in_base, rng), rng, 0.01)
    read = _read_back(wb, text, wb.setup.T_flange_tcp)
    noise = np.linalg.norm(read - in_base, axis=1)
    result = wb.calibration.base(text, known_csv=known_csv(labels, world))
    mapped = in_base @ result.T[:3, :3].T + result.T[:3, 3]
    assert np.max(np.linalg.norm(mapped - world, axis=1)) <= 3.0 * noise.max()
    seen = read @ result.T[:3, :3].T + result.T[:3, 3]  # the measured points in the world
    assert result.kind == "base" and np.allclose(result.points_world, seen, atol=1e-9)


# -- apply -------------------------------------------------------------------------------------
def test_apply_changes_only_its_field_and_returns_the_old_project() -> None:
    wb = Workbench.open(MZ07)
    before = wb.project.model_dump(mode="json")
    text, _, _ = _tcp_case(wb, 9)
    previous = wb.calibration.apply(wb.calibration.tcp(text))
    assert previous.model_dump(mode="json") == before
    after = wb.project.model_dump(mode="json")
    assert after["tool"]["tcp"] != before["tool"]["tcp"]
    assert {k: v for k, v in after.items() if k != "tool"} == {
        k: v for k, v in before.items() if k != "tool"
    }
    assert {k: v for k, v in after["tool"].items() if k != "tcp"} == {
        k: v for k, v in before["tool"].items() if k != "tcp"
    }
    three = "label,x,y,z\norigin,400,0,100\nx,500,0,100\ny,420,80,100\n"
    wb.calibration.apply(wb.calibration.work_object(three, name="table"))
    wb.calibration.apply(wb.calibration.work_object(three.replace("400,0", "410,0"), name="t2"))
    again = wb.calibration.apply(wb.calibration.work_object(three, name="t2"))
    assert [w.name for w in wb.project.work_objects] == ["table", "t2"]
    assert again.work_objects[1].pose.xyz == [410.0, 0.0, 100.0]
    assert wb.project.work_objects[0].pose.xyz == [400.0, 0.0, 100.0]
    wb.replace_project(previous)  # undo
    assert wb.project.model_dump(mode="json") == before


def test_a_joint_outside_its_range_is_noted_in_the_summary(wb: Workbench) -> None:
    # J4 turned a whole turn further: the same flange pose, the same frame, and a note that no
    # real MZ07 shows that value.
    text = (ROOT / "examples" / "calibration" / "fixture_3point.csv").read_text()
    head, *rows = [line for line in text.splitlines() if not line.startswith("#")]
    cells = rows[2].split(",")
    cells[4] = f"{float(cells[4]) + 360.0:.3f}"
    turned = "\n".join([head, rows[0], rows[1], ",".join(cells)])
    plain = wb.calibration.work_object(text, name="fixture")
    noted = wb.calibration.work_object(turned, name="fixture")
    assert np.allclose(noted.T, plain.T, atol=1e-9)
    assert "note: readings line 4: y j4 = " in noted.summary()
    assert "note:" not in plain.summary()
