"""The batch runner: serial and Ray engines give the same results, stop the same way.

The serial engine is the obviously-right twin of the Ray engine, and both are checked
against evaluating each item on its own. Ray tests share one local Ray (2 CPUs) started
by a module fixture; the tests that need no Ray running (an embedded start, an address
that does not answer) come first in this file, before that fixture starts it.
"""

from __future__ import annotations

import math
import os
import socket
import sys
import time
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest

from workbench.batch import ENGINES, BatchRun, BatchStats, batches_of, engine_session, run_batches
from workbench.errors import InputError, PlanningError, UnreachableError, WorkbenchError

ray = pytest.importorskip("ray")

# Ray's workers cannot import this test module by name: ship its functions by value.
ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])


# --- evaluation functions: pure, module level ------------------------------------------


def _noisy(context: dict[str, Any], batch: list[int]) -> list[float]:
    """Return, per item, a projection of the item's own seeded random vector on the weights."""
    weights = np.asarray(context["weights"])
    return [
        float(np.random.default_rng([context["seed"], item]).normal(size=weights.shape) @ weights)
        for item in batch
    ]


def _sleepy(seconds: float, batch: list[int]) -> list[int]:
    """Return the batch unchanged after sleeping `seconds` [s]."""
    time.sleep(seconds)
    return list(batch)


def _refuses(bad: int, batch: list[int]) -> list[int]:
    """Return the batch, or raise UnreachableError when it holds `bad`."""
    if bad in batch:
        raise UnreachableError(f"item {bad} has no solution")
    return list(batch)


def _breaks(bad: int, batch: list[int]) -> list[int]:
    """Return the batch, or raise a plain ValueError when it holds `bad`."""
    if bad in batch:
        raise ValueError(f"item {bad} is broken")
    return list(batch)


def _short(bad: int, batch: list[int]) -> list[int]:
    """Return the batch, one result short when it holds `bad`."""
    return list(batch[:-1]) if bad in batch else list(batch)


CONTEXT = {"seed": 7, "weights": np.linspace(-1.0, 1.0, 16)}
ITEMS = list(range(200))


def _one_by_one() -> list[float]:
    return [_noisy(CONTEXT, [item])[0] for item in ITEMS]


def _closed_port() -> int:
    with socket.socket() as s:  # bound then closed: nothing listens there
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


# --- tests that need no Ray running: before the shared fixture starts it --------------


@pytest.mark.slow
def test_ray_without_an_address_starts_and_shuts_down_its_own_local_ray() -> None:
    assert not ray.is_initialized(), "run this test before the shared Ray fixture starts"
    run = run_batches(_noisy, ITEMS, context=CONTEXT, engine="ray", batch_size=50)
    assert not ray.is_initialized()
    assert run.results == _one_by_one()
    assert run.stats.address is None
    assert run.stats.workers == os.cpu_count()
    assert run.stats.startup_s > 0


def test_an_address_that_does_not_answer_is_an_input_error_naming_it() -> None:
    assert not ray.is_initialized(), "run this test before the shared Ray fixture starts"
    address = f"127.0.0.1:{_closed_port()}"
    start = time.perf_counter()
    with pytest.raises(InputError, match=address) as caught:
        run_batches(_sleepy, [1, 2], context=0.0, engine="ray", address=address)
    assert time.perf_counter() - start < 15
    assert "ray start --head" in str(caught.value)
    assert "leave the address out" in str(caught.value)
    assert not ray.is_initialized()


def test_an_address_that_is_not_host_port_is_an_input_error() -> None:
    with pytest.raises(InputError, match="host:port"):
        run_batches(_sleepy, [1], context=0.0, engine="ray", address="nowhere")


# --- argument checks and the serial engine ---------------------------------------------


def test_batches_of_cuts_consecutive_chunks_in_order() -> None:
    assert batches_of(list(range(7)), 3) == [[0, 1, 2], [3, 4, 5], [6]]
    assert batches_of([], 3) == []
    for size in (1, 7, 64, 200, 500):
        chunks = batches_of(ITEMS, size)
        assert [x for c in chunks for x in c] == ITEMS
        assert len(chunks) == math.ceil(len(ITEMS) / size)
    with pytest.raises(InputError, match="batch_size"):
        batches_of(ITEMS, 0)


def test_an_unknown_engine_is_an_input_error_naming_the_allowed_ones() -> None:
    assert ENGINES == ("serial", "ray")
    with pytest.raises(InputError, match="'serial', 'ray'.*'dask'"):
        run_batches(_sleepy, [1], context=0.0, engine="dask")


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"batch_size": 0}, "batch_size"),
        ({"time_limit": 0.0}, "time_limit"),
        ({"connect_timeout": -1.0}, "connect_timeout"),
        ({"address": "127.0.0.1:6379"}, "address"),  # the serial engine has no cluster
    ],
)
def test_bad_arguments_are_input_errors_naming_the_field(
    kwargs: dict[str, Any], field: str
) -> None:
    with pytest.raises(InputError, match=field):
        run_batches(_sleepy, [1], context=0.0, **kwargs)


def test_the_serial_engine_matches_evaluating_each_item_alone() -> None:
    run = run_batches(_noisy, ITEMS, context=CONTEXT, batch_size=7)
    assert run.results == _one_by_one()
    assert run.done() == [True] * len(ITEMS)
    assert not run.cancelled and not run.timed_out


def test_no_items_give_no_results() -> None:
    fractions: list[float] = []
    run = run_batches(_noisy, [], context=CONTEXT, progress=lambda f, _m: fractions.append(f))
    assert run.results == [] and run.done() == []
    assert run.stats.batches == 0 and run.stats.items == 0
    assert fractions == [1.0]


def test_describe_is_one_line_with_the_numbers() -> None:
    stats = BatchStats("ray", None, 2, 12, 480, 3.1, 2.5, 6.0, 0.004)
    line = stats.describe()
    assert "\n" not in line
    assert line.startswith("ray (local, 2 workers): 12 batches, 480 items in 3.1 s")
    assert "overhead 0.004 s per batch (0.8 % of a batch)" in line
    assert (
        BatchStats("serial", None, 1, 1, 1, 0.1, 0, 0.1, 0)
        .describe()
        .startswith("serial (1 worker)")
    )


def test_a_run_built_by_hand_counts_non_none_results_as_done() -> None:
    stats = BatchStats("serial", None, 1, 1, 1, 0.1, 0.0, 0.1, 0.0)
    assert BatchRun([1, None], stats, cancelled=True, timed_out=False).done() == [True, False]


# --- both engines: the serial one is the Ray one's twin --------------------------------


@pytest.fixture(scope="module")
def local_ray() -> Iterator[None]:
    """Start one local Ray for this module's Ray tests, as a search does; shut it down after."""
    with engine_session("ray"):  # as a search starts it: local, on all cores, a token
        yield


@pytest.fixture(params=ENGINES)
def engine(request: pytest.FixtureRequest) -> str:
    """Return each engine in turn; "ray" runs on the shared local Ray."""
    if request.param == "ray":
        request.getfixturevalue("local_ray")
    return str(request.param)


@pytest.mark.parametrize("batch_size", [1, 7, 64])
def test_serial_and_ray_give_identical_results(local_ray: None, batch_size: int) -> None:
    serial = run_batches(_noisy, ITEMS, context=CONTEXT, batch_size=batch_size)
    on_ray = run_batches(_noisy, ITEMS, context=CONTEXT, engine="ray", batch_size=batch_size)
    assert on_ray.results == serial.results == _one_by_one()
    assert on_ray.done() == [True] * len(ITEMS)
    assert ray.is_initialized()  # a Ray that was already running is reused, not shut down
    assert on_ray.stats.startup_s < 1.0


def test_progress_is_monotone_and_ends_at_one(engine: str) -> None:
    reports: list[tuple[float, str]] = []
    run_batches(
        _noisy,
        ITEMS,
        context=CONTEXT,
        engine=engine,
        batch_size=30,
        progress=lambda f, m: reports.append((f, m)),
    )
    fractions = [f for f, _ in reports]
    assert len(fractions) == 7  # one per batch
    assert all(0 < a < b <= 1 for a, b in zip(fractions, fractions[1:], strict=False))
    assert fractions[-1] == 1.0
    assert reports[-1][1] == "7 of 7 batches, 200 of 200 items"


def test_cancel_after_the_first_batch_leaves_the_rest_unevaluated(engine: str) -> None:
    finished: list[float] = []
    run = run_batches(
        _noisy,
        ITEMS,
        context=CONTEXT,
        engine=engine,
        batch_size=20,
        progress=lambda f, _m: finished.append(f),
        cancel=lambda: len(finished) >= 1,
    )
    assert run.cancelled and not run.timed_out
    done = run.done()
    assert sum(done) == 20 == run.stats.items and run.stats.batches == 1
    expected = _one_by_one()
    assert all(
        r == e if d else r is None for r, e, d in zip(run.results, expected, done, strict=True)
    )
    if engine == "serial":
        assert done == [True] * 20 + [False] * 180  # Ray may finish any batch first


def test_a_time_limit_stops_the_run_and_keeps_the_results_so_far(engine: str) -> None:
    run = run_batches(_sleepy, ITEMS[:20], context=0.2, engine=engine, batch_size=1, time_limit=0.5)
    assert run.timed_out and not run.cancelled
    done = run.done()
    assert 0 < sum(done) < 20
    assert all(
        r == i if d else r is None for i, (r, d) in enumerate(zip(run.results, done, strict=True))
    )
    assert run.stats.wall_s < 2.0  # 0.5 s limit plus at most one 0.2 s batch, with slack


def test_a_workbench_error_in_fn_arrives_as_itself(engine: str) -> None:
    with pytest.raises(UnreachableError) as caught:
        run_batches(_refuses, ITEMS, context=42, engine=engine, batch_size=10)
    assert type(caught.value) is UnreachableError
    assert isinstance(caught.value, WorkbenchError)
    assert str(caught.value) == "item 42 has no solution"


def test_another_error_in_fn_arrives_as_its_own_type(engine: str) -> None:
    with pytest.raises(ValueError, match="item 42 is broken"):
        run_batches(_breaks, ITEMS, context=42, engine=engine, batch_size=10)


def test_a_result_list_of_the_wrong_length_is_a_planning_error_naming_the_batch(
    engine: str,
) -> None:
    with pytest.raises(PlanningError, match=r"batch 4 \(items 40\.\.49\).*9 results for 10"):
        run_batches(_short, ITEMS, context=42, engine=engine, batch_size=10)


def test_stats_are_consistent(engine: str) -> None:
    run = run_batches(_sleepy, ITEMS[:10], context=0.02, engine=engine, batch_size=3)
    stats = run.stats
    assert stats.engine == engine
    assert stats.address is None
    assert stats.workers == (1 if engine == "serial" else 2)
    assert stats.items == sum(run.done()) == 10
    assert stats.batches == 4
    assert stats.compute_s >= 4 * 0.02  # the time fn itself took, four sleeps
    assert stats.wall_s >= stats.compute_s / stats.workers
    used = min(stats.workers, stats.batches)
    expected = max(0.0, (stats.wall_s * used - stats.compute_s) / stats.batches)
    assert stats.overhead_per_batch_s == pytest.approx(expected)
    assert stats.overhead_per_batch_s >= 0
    assert stats.startup_s < 1.0  # serial: 0; ray: the shared Ray is reused
    assert stats.describe().startswith(f"{engine} (")
