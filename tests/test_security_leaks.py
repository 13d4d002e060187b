"""Issue 16 part 6: no leaks. Reloads free their engines, RSS stays flat, caches are bounded.

The in-memory LRU is checked against a brute-force model (a list replayed from scratch); the
disk cache's eviction against the files' own times; the RSS against /proc.
"""

from __future__ import annotations

import gc
import os
import random
import time
import weakref
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.bounded_cache import BoundedCache
from workbench.cli import main
from workbench.disk_cache import DEFAULT_CACHE_LIMIT, cache_limit_bytes, cache_size, clear, prune
from workbench.geometry.npz_cache import cache_path, load_entry, store_entry
from workbench.gui.uploads import UploadSlot, remove_all
from workbench.service.memory import release_memory

ROOT = Path(__file__).resolve().parents[1]
CELL = ROOT / "projects" / "mz07_cell.json"


def _rss_mb() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def test_a_replaced_project_frees_its_checker_and_engines() -> None:
    refs = []
    for _ in range(4):
        wb = Workbench.open(CELL)
        wb.plan_motion()
        engines = list(wb.checker.engines.values())
        assert engines  # the plan built (or fetched) its collision engine
        refs += [weakref.ref(wb.checker), *(weakref.ref(e) for e in engines)]
        del wb, engines
    gc.collect()
    assert [r for r in refs if r() is not None] == []


@pytest.mark.slow
def test_memory_is_flat_over_100_loads_and_plans() -> None:
    """RSS after 100 loads + plans within 100 MB of RSS after 5 (heap trimmed as the GUI does)."""
    for _ in range(5):
        Workbench.open(CELL).plan_motion()
    release_memory()
    before = _rss_mb()
    t0 = time.perf_counter()
    for _ in range(100):
        wb = Workbench.open(CELL)
        wb.plan_motion()
    del wb
    release_memory()
    growth = _rss_mb() - before
    print(f"RSS growth over 100 loads + plans: {growth:.1f} MB in {time.perf_counter() - t0:.0f} s")
    assert growth < 100


def _model_lru(ops: list[tuple[str, int, int]], max_items: int, max_bytes: int) -> dict[int, int]:
    """The brute-force twin: replay every operation on a plain list, oldest first."""
    entries: list[tuple[int, int]] = []
    for op, key, size in ops:
        hit = [e for e in entries if e[0] == key]
        if op == "get":
            if hit:
                entries.remove(hit[0])
                entries.append(hit[0])
            continue
        if hit:
            entries.remove(hit[0])
        if size > max_bytes:
            continue
        entries.append((key, size))
        while len(entries) > max_items or sum(s for _, s in entries) > max_bytes:
            entries.pop(0)
    return dict(entries)


def test_the_bounded_cache_is_an_lru_by_count_and_bytes() -> None:
    rng = random.Random(7)
    for trial in range(30):
        max_items, max_bytes = rng.randint(1, 6), rng.randint(5, 60)
        cache: BoundedCache[int] = BoundedCache(max_items, max_bytes, lambda v: v)
        ops = []
        for _ in range(200):
            key, size = rng.randint(0, 9), rng.randint(1, 25)
            if rng.random() < 0.4:
                ops.append(("get", key, 0))
                cache.get(key)
            else:
                ops.append(("put", key, size))
                cache.put(key, size)
        want = _model_lru(ops, max_items, max_bytes)
        got = {k: cache.get(k) for k in range(10) if cache.get(k) is not None}
        assert got == want, trial
        assert cache.nbytes == sum(want.values()) <= max_bytes and len(cache) <= max_items


def test_the_assembly_cell_grid_cache_is_bounded() -> None:
    from workbench.assembly import cells

    assert isinstance(cells._CACHE, BoundedCache)
    assert cells._CACHE.max_items == cells.CELL_GRID_CACHE_ITEMS
    assert cells._CACHE.max_bytes == cells.CELL_GRID_CACHE_BYTES


def _entry(folder: Path, i: int, size: int, age: float) -> Path:
    p = cache_path(folder, "sdf", [np.array([i])], {})
    store_entry(p, {"a": np.zeros(size, dtype=np.uint8)})
    t = time.time() - age
    os.utime(p, (t, t))
    return p


def test_the_disk_cache_evicts_the_oldest_first(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert cache_limit_bytes() == DEFAULT_CACHE_LIMIT == 1 << 30
    paths = [_entry(tmp_path, i, 10_000, age=1000 - i) for i in range(6)]  # 0 is the oldest
    one = paths[0].stat().st_size
    load_entry(paths[1])  # a read: now the most recently used
    monkeypatch.setenv("WORKBENCH_CACHE_MAX_BYTES", str(4 * one + one // 2))
    new = _entry(tmp_path, 99, 10_000, age=0)  # storing prunes the folder
    left = {p for p in tmp_path.iterdir()}
    assert new in left and paths[1] in left  # the new one and the one just read stay
    assert paths[0] not in left and paths[2] not in left  # the oldest went first
    assert cache_size(tmp_path) <= 4 * one + one // 2
    assert prune(tmp_path, limit=0, keep=new) and set(tmp_path.iterdir()) == {new}
    monkeypatch.setenv("WORKBENCH_CACHE_MAX_BYTES", "lots")
    from workbench.errors import InputError

    with pytest.raises(InputError, match="WORKBENCH_CACHE_MAX_BYTES"):
        cache_limit_bytes()


def test_cache_clear_removes_entries_only(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("WORKBENCH_CACHE", str(tmp_path))
    (tmp_path / "sdf").mkdir()
    for i in range(3):
        _entry(tmp_path / "sdf", i, 1000, age=0)
    (tmp_path / "sdf" / ".sdf-x.npz.123.abc.tmp").write_bytes(b"x")
    (tmp_path / "notes.txt").write_text("mine")
    assert main(["cache", "clear"]) == 0
    assert "removed 4 cache files" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.rglob("*") if p.is_file()) == ["notes.txt"]
    assert clear(tmp_path / "missing") == (0, 0)


def test_upload_folders_go_when_replaced_failed_or_at_exit(tmp_path: Path) -> None:
    wb = Workbench.open(CELL)
    slot = UploadSlot("workpiece")
    with slot.new_file(wb, "a.stl", b"solid a") as first:
        assert wb.folders.resolve(str(first), "polishing.workpiece") == first.resolve()
    with slot.new_file(wb, "b.stl", b"solid b") as second:
        pass
    assert not first.parent.exists() and second.exists()  # replaced: the old folder is gone
    from workbench.errors import InputError

    with pytest.raises(InputError, match="outside"):
        wb.folders.resolve(str(first), "polishing.workpiece")  # no longer allowed
    with pytest.raises(RuntimeError), slot.new_file(wb, "c.stl", b"bad") as third:
        raise RuntimeError("did not load")
    assert not third.parent.exists() and second.exists()  # a failed one goes, the last stays
    remove_all()  # what runs at exit
    assert not second.parent.exists()


def test_upload_folders_left_by_a_server_that_is_gone_are_removed_at_the_next_start() -> None:
    import subprocess
    import sys
    import tempfile

    from workbench.gui.uploads import remove_stale

    gone = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    )
    dead = int(gone.stdout)
    root = Path(tempfile.gettempdir())
    started = time.time()
    left = root / f"workbench-project-{dead}-test"  # its server was killed (SIGKILL, a crash)
    mine = root / f"workbench-workpiece-{os.getpid()}-test"  # a running server's: stays
    old = root / "workbench-project-legacytest"  # named before the pid was: by its age
    new = root / "workbench-project-newtest"
    other = root / "workbench-cache-test"  # not an upload folder
    for folder in (left, mine, old, new, other):
        folder.mkdir(exist_ok=True)
        (folder / "a.stl").write_text("solid a")
    os.utime(old, (started - 3600, started - 3600))
    os.utime(new, (started + 60, started + 60))
    try:
        removed = remove_stale(started)
        assert set(removed) >= {left, old}
        assert not left.exists() and not old.exists()
        assert mine.exists() and new.exists() and other.exists()
        remove_all()  # at exit: this process's own folders go too
        assert not mine.exists() and new.exists()
    finally:
        import shutil

        for folder in (left, mine, old, new, other):
            shutil.rmtree(folder, ignore_errors=True)


def test_sigterm_stops_the_server_and_removes_its_upload_folders(tmp_path: Path) -> None:
    """`docker stop` sends SIGTERM: the server exits normally, and its upload folders go."""
    import signal
    import socket
    import subprocess
    import sys
    import tempfile

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen(
        [sys.executable, "-m", "workbench", "serve", str(CELL), "--port", str(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        cwd=tmp_path,
    )
    try:
        assert proc.stdout is not None
        for line in proc.stdout:
            if "serving" in line:
                break
        upload = Path(tempfile.gettempdir()) / f"workbench-project-{proc.pid}-sigterm"
        upload.mkdir()
        (upload / "block.stl").write_text("solid a")
        proc.send_signal(signal.SIGTERM)
        code = proc.wait(timeout=60)
    finally:
        proc.kill()
    assert code == 128 + signal.SIGTERM
    assert not upload.exists()
