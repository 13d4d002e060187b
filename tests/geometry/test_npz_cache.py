"""The array cache: keys change with any input byte, shape or parameter; broken entries are misses."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench.geometry.npz_cache import cache_path, load_entry, store_entry


def test_the_key_changes_with_values_shapes_dtypes_and_params(tmp_path: Path) -> None:
    v = np.arange(12, dtype=float).reshape(4, 3)
    f = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)
    key = cache_path(tmp_path, "x", [v, f], {"h": 0.1})
    assert key == cache_path(tmp_path, "x", [v.copy(), f.copy()], {"h": 0.1})
    others = [
        cache_path(tmp_path, "x", [v + 1e-12, f], {"h": 0.1}),
        cache_path(tmp_path, "x", [v, f[::-1]], {"h": 0.1}),
        cache_path(tmp_path, "x", [v, f], {"h": 0.2}),
        cache_path(tmp_path, "y", [v, f], {"h": 0.1}),
        cache_path(tmp_path, "x", [v, f.astype(np.int32)], {"h": 0.1}),
        cache_path(tmp_path, "x", [v.reshape(3, 4), f], {"h": 0.1}),
    ]
    assert len({key, *others}) == len(others) + 1
    # The same bytes split differently between the inputs are different inputs.
    x = np.arange(6.0)
    assert cache_path(tmp_path, "x", [x[:2], x[2:]], {}) != cache_path(
        tmp_path, "x", [x[:3], x[3:]], {}
    )


def test_store_then_load_round_trips_and_leaves_no_temporary(tmp_path: Path) -> None:
    path = tmp_path / "sub" / "e.npz"
    arrays = {"a": np.arange(5.0), "b": np.eye(3, dtype=np.int32)}
    store_entry(path, arrays)
    got = load_entry(path, required=("a", "b"))
    assert got is not None and set(got) == {"a", "b"}
    for k, a in arrays.items():
        np.testing.assert_array_equal(got[k], a)
        assert got[k].dtype == a.dtype
    assert sorted(p.name for p in path.parent.iterdir()) == ["e.npz"]


@pytest.mark.parametrize(
    "content", [b"", b"not a zip file", b"PK\x03\x04 truncated zip header"], ids=repr
)
def test_an_unreadable_entry_is_a_miss(tmp_path: Path, content: bytes) -> None:
    path = tmp_path / "e.npz"
    path.write_bytes(content)
    assert load_entry(path) is None


def test_a_truncated_entry_is_a_miss_and_is_overwritten(tmp_path: Path) -> None:
    path = tmp_path / "e.npz"
    store_entry(path, {"a": np.arange(1000.0)})
    path.write_bytes(path.read_bytes()[:300])
    assert load_entry(path) is None
    store_entry(path, {"a": np.arange(3.0)})
    got = load_entry(path)
    assert got is not None
    np.testing.assert_array_equal(got["a"], np.arange(3.0))


def test_an_entry_missing_a_required_array_is_a_miss(tmp_path: Path) -> None:
    path = tmp_path / "e.npz"
    store_entry(path, {"a": np.zeros(2)})
    assert load_entry(path, required=("a",)) is not None
    assert load_entry(path, required=("a", "b")) is None
    assert load_entry(tmp_path / "absent.npz") is None


def test_a_failed_write_keeps_the_old_entry(tmp_path: Path) -> None:
    path = tmp_path / "e.npz"
    store_entry(path, {"a": np.arange(4.0)})

    class Boom:
        def __array__(self, *args: object, **kwargs: object) -> np.ndarray:
            raise RuntimeError("disk full")

    with pytest.raises(RuntimeError, match="disk full"):
        store_entry(path, {"a": Boom()})  # type: ignore[dict-item]
    got = load_entry(path)
    assert got is not None
    np.testing.assert_array_equal(got["a"], np.arange(4.0))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.npz"]
