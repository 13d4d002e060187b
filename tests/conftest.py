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


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Group the tests for pytest-xdist's `--dist loadgroup` (pyproject.toml's addopts): each
    test file runs whole on one worker, in its order, with its module fixtures made once, and
    the files that read tests/example_plans.py's plans (made once per process) share a worker,
    so no example is planned twice. Runs before xdist's own hook, which reads the groups."""
    for item in items:
        if item.get_closest_marker("xdist_group") is not None:
            continue
        module = getattr(item, "module", None)
        shares_plans = module is not None and any(
            getattr(value, "__module__", None) == "example_plans" for value in vars(module).values()
        )
        group = "example_plans" if shares_plans else item.nodeid.split("::")[0]
        item.add_marker(pytest.mark.xdist_group(group))
