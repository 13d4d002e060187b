"""Fuzzed project files (issue 16): seeded mutations of the example projects.

Each case mutates one example project 1-3 times (a wrong type, a missing or an extra field,
an extreme magnitude, a hostile string or path, deep nesting, a repeated key), loads it and,
for a fraction of the cases that load, builds a workbench and runs the plans of its sections
(`wb.plan_motion`, `wb.bending.plan`, `wb.assembly.plan_part`/`plan_sequence`,
`wb.polishing.plan_path`/`plan_motion`). Every case must end in a result or a
`WorkbenchError`: never another exception type, never over `CASE_SECONDS`, never a peak
memory growth over `CASE_MEMORY`.

The default run is `CASES` cases (a few hundred, under a minute on two cores); the slow
marker runs `SLOW_CASES` more with other seeds. A failure prints the seed and the mutations,
so `case(seed)` reproduces it.
"""

from __future__ import annotations

import copy
import json
import math
import random
import resource
import signal
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest

from workbench.errors import WorkbenchError
from workbench.project.io import parse_project_json

ROOT = Path(__file__).resolve().parent.parent
PROJECTS = ROOT / "projects"
EXAMPLES = ("mz07_cell", "bending_cell", "assembly_cell", "polishing_cell")

CASES = 300  # default run
PLAN_EVERY = 5  # one case in PLAN_EVERY of those that load also runs its plans
SLOW_CASES = 1500
CASE_SECONDS = 30.0
CASE_MEMORY = 2 * 1024**3  # bytes of peak RSS growth in one case

NUMBERS: tuple[Any, ...] = (0, -1, 1e-9, -1e-9, 1e9, -1e9, 1e308, -1e308, 2**64, 0.5, 1e-300)
# values at the edges of many ranges (workbench.project.bounds): they load, so the plans see them
EDGES: tuple[Any, ...] = (0.1, 1, 10, 100, 1000, 1e5, -1e5, 720, -720, 3600, 60)
STRINGS: tuple[str, ...] = (
    "",
    "NaN",
    "Infinity",
    "-inf",
    "../../../../etc/passwd",
    "/etc/passwd",
    "/dev/zero",
    "/proc/self/environ",
    "a\x00b",
    "x" * 300,
    "ü∂ß\u202e\ufeff",
    "$(rm -rf /)",
    "<script>alert(1)</script>",
    "C:\\Windows\\system32",
    "~/.ssh/id_rsa",
    "\\\\server\\share\\x.stl",
    "parts/seed_part.json",
)
OTHERS: tuple[Any, ...] = (None, True, False, [], {}, [1, 2], {"a": 1}, [[[]]], [None] * 3)


@dataclass
class Case:
    """One fuzzed project: its seed, the example it came from, its mutations and JSON text."""

    seed: int
    example: str
    mutations: list[str] = field(default_factory=list)
    text: str = ""


def _paths(node: Any, path: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    """Yield the path of every node below the root (dict keys, list indices), 20 levels deep."""
    if len(path) >= 20:
        return
    if isinstance(node, dict):
        for k, v in node.items():
            yield (*path, k)
            yield from _paths(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield (*path, i)
            yield from _paths(v, (*path, i))


def _get(node: Any, path: tuple[Any, ...]) -> Any:
    for k in path:
        node = node[k]
    return node


def _label(path: tuple[Any, ...]) -> str:
    return "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in path).lstrip(".")


def _mutate(data: Any, rng: random.Random, case: Case) -> None:
    """Apply one random mutation to `data` in place (or to `case.text` markers)."""
    paths = list(_paths(data))
    path = rng.choice(paths)
    parent, key = _get(data, path[:-1]), path[-1]
    old = parent[key]
    op = rng.choices(
        ["number", "edge", "scale", "string", "type", "delete", "extra", "nest", "duplicate"],
        weights=[24, 12, 12, 12, 12, 10, 6, 3, 3],
    )[0]
    where = _label(path)
    if op in ("number", "edge") or (op == "scale" and not isinstance(old, int | float)):
        new = rng.choice(EDGES if op == "edge" else NUMBERS)
        parent[key] = new
        case.mutations.append(f"{where} = {new!r}")
    elif op == "scale":
        f = rng.choice((0.0, -1.0, 1e-6, 1e-3, 1e3, 1e6, 1e12))
        parent[key] = old * f
        case.mutations.append(f"{where} *= {f:g}")
    elif op == "string":
        new = rng.choice(STRINGS)
        parent[key] = new
        case.mutations.append(f"{where} = {new[:40]!r}")
    elif op == "type":
        new = copy.deepcopy(rng.choice(OTHERS))
        parent[key] = new
        case.mutations.append(f"{where} = {new!r}")
    elif op == "delete":
        del parent[key]
        case.mutations.append(f"del {where}")
    elif op == "extra":
        target = parent if isinstance(parent, dict) else data
        name = rng.choice(("extra", "__proto__", "Name", "schema_version ", "x" * 100))
        target[name] = rng.choice((1, "x", None, [1]))
        case.mutations.append(f"extra key {name[:20]!r} beside {where}")
    elif op == "nest":
        depth = rng.choice((70, 500, 5000))
        v: Any = old
        for _ in range(depth):
            v = [v]
        parent[key] = v
        case.mutations.append(f"{where} nested in {depth} lists")
    else:  # duplicate: marked here, written into the text by _text
        if isinstance(parent, dict):
            parent[f"\x01dup\x01{key}"] = rng.choice((old, 0, "x"))
            case.mutations.append(f"{where} repeated")
        else:
            parent[key] = rng.choice(NUMBERS)
            case.mutations.append(f"{where} = number (no object to repeat a key in)")


def _text(data: Any) -> str:
    """Return `data` as JSON; keys marked for repetition become a second copy of the key."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 10_000))
    try:
        text = json.dumps(data, allow_nan=True)
    finally:
        sys.setrecursionlimit(old)
    return text.replace('"\\u0001dup\\u0001', '"')


def case(seed: int) -> Case:
    """Return fuzz case `seed`: an example project mutated 1-3 times, as JSON text."""
    rng = random.Random(seed)
    c = Case(seed, EXAMPLES[seed % len(EXAMPLES)])
    data = json.loads((PROJECTS / f"{c.example}.json").read_text())
    for _ in range(rng.choice((1, 1, 2, 3))):
        _mutate(data, rng, c)
    c.text = _text(data)
    return c


def _plans(wb: Any) -> list[str]:
    """Run every plan of the project's sections; return what ran."""
    p = wb.project
    ran = []
    if p.program is not None:
        wb.plan_motion()
        ran.append("plan_motion")
    if p.bending is not None:
        wb.bending.plan()
        ran.append("bending.plan")
    if p.assembly is not None and p.assembly.parts:
        wb.assembly.plan_part(p.assembly.parts[0].name)
        ran.append("assembly.plan_part")
    if p.polishing is not None:
        wb.polishing.plan_path()
        wb.polishing.plan_motion()
        ran.append("polishing.plan_path+plan_motion")
    return ran


class _Timeout(BaseException):
    """Raised by the alarm: a case ran over CASE_SECONDS (not an Exception: nothing catches it)."""


def _alarm(signum: int, frame: Any) -> None:
    raise _Timeout()


def _rss() -> int:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def run_case(seed: int, *, plan: bool) -> str:
    """Run case `seed`; return "loaded", "refused", "planned" or "plan refused".

    Raises AssertionError naming the seed and mutations for any other outcome."""
    from workbench.service import Workbench

    c = case(seed)
    what = f"seed {seed} ({c.example}: {'; '.join(c.mutations)})"
    before = _rss()
    t0 = time.perf_counter()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, CASE_SECONDS)
    outcome = "loaded"
    try:
        try:
            project = parse_project_json(c.text, source=f"{c.example}.json")
        except WorkbenchError as exc:
            assert str(exc).strip(), f"{what}: an empty message"
            return "refused"
        if plan:
            try:
                wb = Workbench(project, base_dir=PROJECTS)
                _plans(wb)
                outcome = "planned"
            except WorkbenchError as exc:
                assert str(exc).strip(), f"{what}: an empty message"
                outcome = "plan refused"
    except _Timeout:
        raise AssertionError(f"{what}: ran over {CASE_SECONDS:g} s") from None
    except AssertionError:
        raise
    except BaseException as exc:  # the point of the test: name any other type with its case
        raise AssertionError(f"{what}: {type(exc).__name__}: {exc}") from exc
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    grown = _rss() - before
    assert grown < CASE_MEMORY, f"{what}: peak memory grew by {grown / 1024**3:.1f} GB"
    assert time.perf_counter() - t0 < CASE_SECONDS
    return outcome


def _run(seeds: range) -> dict[str, int]:
    counts: dict[str, int] = {}
    failures = []
    loaded = 0
    for seed in seeds:
        try:
            out = run_case(seed, plan=False)
            if out == "loaded":
                loaded += 1
                if loaded % PLAN_EVERY == 1:
                    out = run_case(seed, plan=True)
        except AssertionError as exc:
            failures.append(str(exc))
            continue
        counts[out] = counts.get(out, 0) + 1
    assert not failures, f"{len(failures)} case(s) failed:\n" + "\n".join(failures)
    return counts


def test_mutations_are_seeded_and_varied() -> None:
    assert case(7).text == case(7).text
    texts = {case(s).text for s in range(40)}
    assert len(texts) >= 35
    ops = " ".join(m for s in range(200) for m in case(s).mutations)
    for word in ("del ", "extra key", "nested in", "repeated", "=", "*="):
        assert word in ops, word


def test_fuzzed_projects_load_or_fail_cleanly() -> None:
    """CASES cases: each loads (one in PLAN_EVERY of those plans) or raises a WorkbenchError."""
    t0 = time.perf_counter()
    counts = _run(range(CASES))
    # Both outcomes occur: the mutations are neither all harmless nor all refused.
    assert counts.get("refused", 0) > CASES // 4, counts
    assert counts.get("loaded", 0) + counts.get("planned", 0) + counts.get("plan refused", 0) > 20
    assert counts.get("planned", 0) + counts.get("plan refused", 0) >= 2, counts
    print(f"{CASES} cases in {time.perf_counter() - t0:.1f} s: {counts}")


@pytest.mark.slow
def test_more_fuzzed_projects_load_and_plan_or_fail_cleanly() -> None:
    counts = _run(range(CASES, CASES + SLOW_CASES))
    print(counts)


def test_the_case_runner_catches_other_exception_types(monkeypatch: pytest.MonkeyPatch) -> None:
    """The runner is not a test that cannot fail: a crash in load is reported with its seed."""
    me = sys.modules[__name__]

    def boom(text: str, *, source: str) -> None:
        raise ZeroDivisionError("boom")

    monkeypatch.setattr(me, "parse_project_json", boom)
    with pytest.raises(AssertionError, match=r"seed 3 .*ZeroDivisionError: boom"):
        me.run_case(3, plan=False)


def test_nan_strings_are_not_numbers() -> None:
    assert not any(isinstance(s, float) and math.isnan(s) for s in STRINGS)
