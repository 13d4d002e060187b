"""The Calibration folder's dispatch without a browser: each kind (work object by three points
and by a fit to known points, the robot's base) computed from the boxes' text, shown, applied and
undone; a missing name refused naming its box. The browser test (tests/e2e/) does the TCP."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from browser_helpers import free_port
from calibration_synth import known_csv, point_csv

from workbench.errors import InputError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.gui.app import WorkbenchApp, start_server
from workbench.service import Workbench

pytestmark = pytest.mark.slow  # ~4 s: a server, and every apply and undo rebuilds the tabs
ROOT = Path(__file__).resolve().parents[2]
EVENT = SimpleNamespace(client=None)  # what the handlers read of viser's event
LOCAL = np.array([[0, 0, 0], [0.2, 0, 0], [0.05, 0.15, 0], [0.2, 0.15, 0.02], [0.1, 0.05, 0.04]])


@pytest.fixture(scope="module")
def app():  # type: ignore[no-untyped-def]
    server = start_server("127.0.0.1", free_port())
    application = WorkbenchApp(server, Workbench.open(ROOT / "projects" / "mz07_cell.json"))
    yield application
    application.timeline.close()
    server.stop()


def _points(T: np.ndarray, local: np.ndarray = LOCAL) -> np.ndarray:
    return local @ T[:3, :3].T + T[:3, 3]  # the world is the robot's base in this cell


def _compute(app: WorkbenchApp, kind: str, readings: str, **values: str):  # type: ignore[no-untyped-def]
    panel = app.calibration
    panel.kind.value = kind  # type: ignore[misc]
    for name, value in values.items():
        getattr(panel, name).value = value
    panel.readings.text = readings
    panel._on_compute(EVENT)
    return panel.result


def test_work_object_three_point_applied_and_undone(app: WorkbenchApp) -> None:
    wb, panel = app.wb, app.calibration
    T = xyz_rpy_to_transform([0.45, 0.05, 0.3], np.radians([0, 0, 20]))
    text = point_csv(wb, ["origin", "x", "y"], _points(T, LOCAL[:3]), np.random.default_rng(1))
    with pytest.raises(InputError, match="^Work object name: type the work object's name"):
        _compute(app, "Work object", text, name="  ", method="3point")
    assert not panel.known_folder.visible  # 3point takes no known points
    result = _compute(app, "Work object", text, name="table", method="3point")
    assert np.allclose(result.T, T, atol=1e-7)
    assert panel.marks.labels == ["origin  0.00 mm", "x  0.00 mm", "y  0.00 mm", "table"]
    assert "3-point method" in panel.summary.content and not panel.apply.disabled
    wb.replace_project(wb.project.model_copy(deep=True))  # as an import or a load does
    with pytest.raises(InputError, match="changed since Compute"):
        panel._on_apply(EVENT)
    assert not wb.project.work_objects
    _compute(app, "Work object", text, name="table", method="3point")
    panel._on_apply(EVENT)
    table = next(w for w in wb.project.work_objects if w.name == "table")
    assert np.allclose(table.pose.xyz, T[:3, 3] * 1000, atol=1e-3)
    assert "Work object **table**" in panel.in_use.content
    assert panel.undo.label == "Undo calibration: table" and panel.apply.disabled
    panel._on_undo(EVENT)
    assert not wb.project.work_objects and "table" not in panel.in_use.content


def test_work_object_fit_names_the_outlier_and_the_base_is_fitted(app: WorkbenchApp) -> None:
    wb, panel = app.wb, app.calibration
    labels = [f"p{k}" for k in range(len(LOCAL))]
    T = xyz_rpy_to_transform([0.5, -0.1, 0.25], np.radians([0, 0, -15]))
    measured = _points(T)
    measured[3, 2] += 0.004  # p3 measured 4 mm off
    panel.known.text = known_csv(labels, LOCAL)
    text = point_csv(wb, labels, measured, np.random.default_rng(2))
    result = _compute(app, "Work object", text, name="fixture", method="fit")
    assert panel.known_folder.visible and result.dropped == ("p3",)
    assert np.allclose(result.T, T, atol=1e-6)
    assert panel.marks.labels[3].startswith("p3  4.")  # drawn red: an outlier
    # The robot's base: the same points given in the world, measured in the base.
    T_world_base = xyz_rpy_to_transform([0.01, -0.02, 0.0], np.radians([0, 0, 1.5]))
    world = _points(xyz_rpy_to_transform([0.5, 0.0, 0.2], [0, 0, 0]))
    panel.known.text = known_csv(labels, world)
    base_pts = (world - T_world_base[:3, 3]) @ T_world_base[:3, :3]
    result = _compute(app, "Robot base", point_csv(wb, labels, base_pts, np.random.default_rng(3)))
    assert np.allclose(result.T, T_world_base, atol=1e-6)
    panel._on_apply(EVENT)
    assert np.allclose(wb.project.robot.base.xyz, [10.0, -20.0, 0.0], atol=1e-3)
    panel._on_undo(EVENT)
    assert wb.project.robot.base.xyz == [0.0, 0.0, 0.0]
    # Another project opened: the last result, its marks and the undo of the last one go.
    _compute(app, "Robot base", point_csv(wb, labels, base_pts, np.random.default_rng(3)))
    panel._on_apply(EVENT)
    _compute(app, "Robot base", point_csv(wb, labels, base_pts, np.random.default_rng(4)))
    assert panel.marks.nodes and app.undo.last is not None
    app.open_file(ROOT / "projects" / "mz07_cell.json")
    assert panel.result is None and not panel.marks.nodes and panel.apply.disabled
    assert app.undo.last is None and panel.undo.disabled
