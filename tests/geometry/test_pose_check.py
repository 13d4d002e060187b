"""check_transform / check_rotation: every malformed pose named with what was received."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.geometry import check_rotation, check_transform


def test_rigid_transforms_pass_unchanged() -> None:
    rng = np.random.default_rng(0)
    T = np.tile(np.eye(4), (20, 1, 1))
    T[:, :3, :3] = Rotation.random(20, random_state=rng).as_matrix()  # twin: scipy's rotations
    T[:, :3, 3] = rng.normal(size=(20, 3))
    np.testing.assert_array_equal(check_transform(T, batch=True), T)
    np.testing.assert_array_equal(check_transform(T[0].tolist()), T[0])
    np.testing.assert_array_equal(check_rotation(T[:, :3, :3]), T[:, :3, :3])


@pytest.mark.parametrize(
    ("edit", "match"),
    [
        (lambda T: T[:3], r"pose: expected one \(4, 4\) transform \[m\], got shape \(3, 4\)"),
        (lambda T: np.where(np.eye(4, dtype=bool), np.nan, T), "finite"),
        (lambda T: T + np.eye(4)[3] * 0.5, r"last row must be \[0, 0, 0, 1\]"),
        (lambda T: T @ np.diag([1.0, 1.0, 1.01, 1.0]), "not orthonormal"),
        (lambda T: T @ np.diag([1.0, 1.0, -1.0, 1.0]), "reflection"),
    ],
)
def test_malformed_transforms_are_named(edit, match) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InputError, match=match):
        check_transform(edit(np.eye(4)), "pose")


def test_batch_shape_and_garbage() -> None:
    with pytest.raises(InputError, match=r"\(\.\.\., 4, 4\), got \(4,\)"):
        check_transform(np.zeros(4), batch=True)
    with pytest.raises(InputError, match="homogeneous transform"):
        check_transform("not a pose")
    with pytest.raises(InputError, match=r"\(\.\.\., 3, 3\)"):
        check_rotation(np.eye(4))
