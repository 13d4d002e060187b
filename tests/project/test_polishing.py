"""The `polishing` section in SI (`PolishingSpec.to_si`) and set from SI (`updated`).

Twins: the values converted by hand (mm -> m, ms -> s, deg -> rad); the service's pose
conversion; the section's own validation on load for the same bad values.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import InputError, ProjectError
from workbench.project.io import project_from_dict
from workbench.project.polishing import PolishingSpec
from workbench.project.units import pose_to_matrix

EXAMPLE = Path(__file__).resolve().parents[2] / "projects" / "polishing_cell.json"


def _spec(**changes: object) -> PolishingSpec:
    data = json.loads(EXAMPLE.read_text())["polishing"]
    data.update(changes)
    return PolishingSpec.model_validate(data)


def test_to_si_converts_every_length_speed_and_angle() -> None:
    spec = _spec(pose={"xyz": [600, -20, 300], "rpy": [5, -10, 90]})
    si = spec.to_si()
    np.testing.assert_array_equal(si.T_world_workpiece, pose_to_matrix(spec.pose))
    assert (si.pattern, si.units, si.n_lead, si.workpiece) == (
        spec.pattern, spec.units, spec.n_lead, spec.workpiece,
    )  # fmt: skip
    for name in ("step", "spacing", "tool_radius", "lead_height", "feed"):
        assert getattr(si, name) == pytest.approx(getattr(spec, name) / 1000, rel=1e-15), name
    assert (si.force, si.max_force, si.dwell) == (spec.force, spec.max_force, spec.dwell)
    c, k = spec.controller, spec.contact
    p = si.control
    assert p.latency == pytest.approx(c.latency / 1000)
    assert (p.kfp, p.kfi) == pytest.approx((c.kfp / 1000, c.kfi / 1000))
    assert (p.max_speed, p.max_accel) == pytest.approx((c.max_speed / 1000, c.max_accel / 1000))
    assert (p.form_error, p.form_wavelength) == pytest.approx(
        (k.form_error / 1000, k.form_wavelength / 1000)
    )
    assert p.max_angular_speed == pytest.approx(math.radians(c.orientation.max_speed))
    assert (p.stiffness, p.max_force, p.kop) == (k.stiffness, spec.max_force, c.orientation.kp)


def test_updated_stores_si_values_in_the_files_units() -> None:
    spec = _spec()
    new = spec.updated(pattern="raster", step=0.004, spacing=0.025, force=35.0, feed=0.02)
    assert (new.pattern, new.step, new.spacing, new.force, new.feed) == (
        "raster", 4.0, 25.0, 35.0, 20.0,
    )  # fmt: skip
    assert new.tool_radius == spec.tool_radius and spec.pattern == "spiral"  # a copy
    for kw, where in (
        ({"force": 150.0}, "polishing.force: 150 N is above the tool's limit"),
        ({"force": float("nan")}, "polishing.force: must be a finite number"),
        ({"step": -0.001}, "polishing.step: "),
        ({"pattern": "zigzag"}, "polishing.pattern: "),
        ({"feed": 0.3}, "polishing: feed = 300 mm/s is above controller.max_speed"),
    ):
        with pytest.raises(InputError) as err:
            spec.updated(**kw)  # type: ignore[arg-type]
        assert str(err.value).startswith(where), (kw, str(err.value))


def test_the_live_model_is_checked_as_the_file_is() -> None:
    spec = _spec()
    spec.controller.orientation.kp = 600.0  # valid alone; the loop it belongs to is not
    with pytest.raises(InputError) as live:
        spec.to_si()
    data = json.loads(EXAMPLE.read_text())
    data["polishing"]["controller"]["orientation"]["kp"] = 600.0
    with pytest.raises(ProjectError) as on_load:
        project_from_dict(data)
    (path, msg), *_ = on_load.value.problems
    assert str(live.value) == f"{path}: {msg}"
    assert path == "polishing.controller.orientation"
