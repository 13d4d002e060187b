"""Cache entries are written atomically without fsync; a torn entry is a miss, rebuilt."""

from __future__ import annotations

import os

import numpy as np

from workbench.geometry.npz_cache import cache_path, load_entry, store_entry


def test_store_is_atomic_and_does_not_fsync(tmp_path, monkeypatch):
    calls = []
    monkeypatch.setattr(os, "fsync", lambda fd: calls.append(fd))
    path = cache_path(tmp_path, "x", [np.arange(5.0)], {"a": 1})
    store_entry(path, {"v": np.arange(5.0)})
    assert calls == []
    assert [p.name for p in tmp_path.iterdir()] == [path.name]  # no temporary file left
    np.testing.assert_array_equal(load_entry(path, ("v",))["v"], np.arange(5.0))


def test_a_torn_entry_is_a_miss(tmp_path):
    """What a power cut may leave of an entry written without fsync: empty, cut short, or
    a block of zeros; every one reads as a miss (None), never as wrong arrays."""
    path = cache_path(tmp_path, "x", [np.arange(1000.0)], {})
    store_entry(path, {"v": np.arange(1000.0)})
    whole = path.read_bytes()
    for torn in (b"", whole[: len(whole) // 2], whole[:-30], b"\0" * len(whole)):
        path.write_bytes(torn)
        assert load_entry(path, ("v",)) is None
    damaged = bytearray(whole)
    damaged[len(whole) // 3] ^= 0xFF  # one flipped byte inside the array's data: zip CRC
    path.write_bytes(bytes(damaged))
    assert load_entry(path, ("v",)) is None
