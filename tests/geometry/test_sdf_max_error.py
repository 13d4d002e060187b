"""`SparseSDF.max_error` is computed once per field (at build or load), kept as an attribute,
and equals the brute-force rescan of the values (issue 14 part 3: it rescanned 675k values on
every read, twice per single-configuration check)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

import workbench.geometry.sdf as sdf_module
from workbench.geometry.sdf import SparseSDF


def test_max_error_is_computed_once_and_equals_the_rescan(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    calls = []
    real = sdf_module._max_error

    def counted(values, fine):  # type: ignore[no-untyped-def]
        calls.append(1)
        return real(values, fine)

    monkeypatch.setattr(sdf_module, "_max_error", counted)
    mesh = trimesh.creation.box((0.4, 0.3, 0.2))
    sdf = SparseSDF.from_mesh(mesh, resolution=12, cache_dir=tmp_path)
    assert len(calls) == 1
    values = [sdf.max_error for _ in range(1000)]
    assert len(calls) == 1 and len(set(values)) == 1
    assert "max_error" in vars(sdf)  # a stored attribute, not a property
    # Brute force: half the fine diagonal plus float32 rounding of the largest |value|.
    v = np.asarray(sdf.values, float)
    want = np.sqrt(3.0) / 2.0 * sdf.cell_size / sdf.subdivisions
    want += 4.0 * float(np.finfo(np.float32).eps) * float(np.abs(v).max())
    assert sdf.max_error == pytest.approx(want, rel=1e-15)
    # Loaded from the cache: computed once there too, the same value.
    again = SparseSDF.from_mesh(mesh, resolution=12, cache_dir=tmp_path)
    assert len(calls) == 2 and again.max_error == sdf.max_error
    # The values it bounds cannot change under it.
    with pytest.raises(ValueError):
        sdf.values[0, 0, 0, 0] = 1.0
