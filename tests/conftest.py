"""Fixtures shared by the whole suite."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def engine_cache(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Return one cache folder for the sphere fits, distance fields and pair tables of the
    collision tests' engines, kept between runs in pytest's cache (.pytest_cache/d/engine-cache;
    `--cache-clear` empties it), as the workbench keeps its own in ~/.cache/workbench.

    Collision tests that build engines of the same robot and cells share it, so each fit or
    field is computed once, not once per test or per run (entries are keyed by their inputs and
    a version bumped when the fit changes, and checked on load); tests of the cache itself keep
    their own fresh folder. Without pytest's cache (-p no:cacheprovider) it is a fresh folder.
    """
    cache = getattr(request.config, "cache", None)
    if cache is None:
        return tmp_path_factory.mktemp("engine-cache")
    return Path(cache.mkdir("engine-cache"))
