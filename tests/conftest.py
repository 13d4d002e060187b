"""Fixtures shared by the whole suite."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def engine_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Return one cache folder for the session's sphere fits, distance fields and pair tables.

    Collision tests that build engines of the same robot and cells share it, so each fit or
    field is computed once per run (entries are keyed by their inputs and checked on load);
    tests of the cache itself keep their own fresh folder.
    """
    return tmp_path_factory.mktemp("engine-cache")
