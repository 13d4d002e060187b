"""Issue 16 part 5: saves keep the file as it was (mode, owner, symlink), only replace files.

Each property is read back with os.stat / os.lstat, an independent look at what the save did.
"""

from __future__ import annotations

import json
import os
import shutil
import stat
import time
from pathlib import Path

import pytest

from workbench import Workbench
from workbench.atomic_file import STALE_TEMP_SECONDS, atomic_write_text
from workbench.errors import InputError, WorkbenchError

ROOT = Path(__file__).resolve().parents[1]


def _mode(p: Path) -> int:
    return stat.S_IMODE(os.stat(p).st_mode)


@pytest.fixture
def umask022():
    old = os.umask(0o022)
    yield
    os.umask(old)


@pytest.mark.parametrize("mode", [0o644, 0o600, 0o640, 0o664])
def test_a_save_keeps_the_mode(tmp_path: Path, mode: int) -> None:
    p = tmp_path / "cell.json"
    p.write_text("{}")
    os.chmod(p, mode)
    atomic_write_text(p, '{"a": 1}\n')
    assert _mode(p) == mode and p.read_text() == '{"a": 1}\n'


def test_a_new_file_gets_the_umask_mode(tmp_path: Path, umask022: None) -> None:
    p = tmp_path / "new.json"
    atomic_write_text(p, "x")
    assert _mode(p) == 0o644  # what open() gives under umask 022, not mkstemp's 0600


def test_a_project_saved_over_a_0644_file_stays_0644(tmp_path: Path) -> None:
    p = tmp_path / "cell.json"
    shutil.copy(ROOT / "projects" / "mz07_cell.json", p)
    os.chmod(p, 0o644)
    wb = Workbench.open(p)
    wb.set_joints(wb.joints + 0.01)
    wb.save()
    assert _mode(p) == 0o644
    assert Workbench.open(p).joints == pytest.approx(wb.joints)


@pytest.mark.skipif(os.geteuid() != 0, reason="giving a file to another owner needs root")
def test_a_save_keeps_the_owner(tmp_path: Path) -> None:
    p = tmp_path / "cell.json"
    p.write_text("{}")
    os.chown(p, 1234, 4321)
    atomic_write_text(p, "{}\n")
    st = os.stat(p)
    assert (st.st_uid, st.st_gid) == (1234, 4321)


def test_a_save_over_a_symlink_keeps_the_link_and_updates_its_target(tmp_path: Path) -> None:
    real_dir = tmp_path / "store"
    real_dir.mkdir()
    target = real_dir / "cell.json"
    shutil.copy(ROOT / "projects" / "mz07_cell.json", target)
    os.chmod(target, 0o640)
    link = tmp_path / "cell.json"
    link.symlink_to(os.path.relpath(target, tmp_path))  # a relative link
    chain = tmp_path / "latest.json"
    chain.symlink_to(link)  # a link to the link
    wb = Workbench.open(chain)
    wb.set_joints(wb.joints + 0.02)
    wb.save()
    assert chain.is_symlink() and link.is_symlink()
    assert os.readlink(link) == os.path.relpath(target, tmp_path)
    assert stat.S_ISREG(os.lstat(target).st_mode) and _mode(target) == 0o640
    saved = json.loads(target.read_text())
    assert saved["robot"]["joints"] == json.loads(link.read_text())["robot"]["joints"]
    assert Workbench.open(target).joints == pytest.approx(wb.joints)
    assert sorted(os.listdir(tmp_path)) == ["cell.json", "latest.json", "store"]
    assert sorted(os.listdir(real_dir)) == ["cell.json"]  # no temporary files left


def test_only_regular_files_are_replaced(tmp_path: Path) -> None:
    folder = tmp_path / "a_folder.json"
    folder.mkdir()
    fifo = tmp_path / "pipe.json"
    os.mkfifo(fifo)
    for p in (folder, fifo, Path("/dev/null")):
        with pytest.raises(InputError, match="refusing to replace it"):
            atomic_write_text(p, "{}")
    assert folder.is_dir() and stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert stat.S_ISCHR(os.lstat("/dev/null").st_mode)
    # A link to a device is followed and refused too.
    (tmp_path / "null.json").symlink_to("/dev/null")
    with pytest.raises(WorkbenchError):
        Workbench.open(ROOT / "projects" / "mz07_cell.json").save(tmp_path / "null.json")
    assert stat.S_ISCHR(os.lstat("/dev/null").st_mode)


def _dead_pid() -> int:
    for pid in range(4_000_000, 3_000_000, -7919):
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return pid
        except PermissionError:
            continue
    pytest.skip("no free pid found")


def test_stale_temporary_files_are_removed_by_the_next_save(tmp_path: Path) -> None:
    p = tmp_path / "cell.json"
    p.write_text("{}")
    dead = tmp_path / f".cell.json.{_dead_pid()}.k3j2h1g0.tmp"  # its writer was killed
    old = tmp_path / ".cell.json.a1b2c3d4.tmp"  # the pid-less names of earlier versions
    live = tmp_path / f".cell.json.{os.getppid()}.q9w8e7r6.tmp"  # a live writer's, just now
    other = tmp_path / ".other.json.a1b2c3d4.tmp"  # another file's
    for t in (dead, old, live, other):
        t.write_bytes(b"x" * 1000)
    hour_ago = time.time() - STALE_TEMP_SECONDS - 60
    os.utime(old, (hour_ago, hour_ago))
    os.utime(other, (hour_ago, hour_ago))
    atomic_write_text(p, "{}\n")
    left = sorted(x.name for x in tmp_path.iterdir())
    assert left == sorted(["cell.json", live.name, other.name])


def test_an_interrupted_write_leaves_the_old_file_and_no_temporary(tmp_path: Path) -> None:
    from workbench.atomic_file import atomic_write

    p = tmp_path / "cell.json"
    p.write_text("old")

    def boom(fh: object) -> None:
        raise RuntimeError("disk on fire")

    with pytest.raises(RuntimeError):
        atomic_write(p, boom, binary=False)
    assert p.read_text() == "old" and os.listdir(tmp_path) == ["cell.json"]


def test_a_long_file_name_saves(tmp_path: Path) -> None:
    p = tmp_path / ("x" * 250 + ".json")
    atomic_write_text(p, "{}")
    atomic_write_text(p, "{}\n")
    assert p.read_text() == "{}\n" and len(os.listdir(tmp_path)) == 1
