"""A fresh install works: a new virtual environment, `pip install` of this tree (pyproject.toml
alone, non-editable, as the Dockerfile installs it), then every example project opens and
reads its files there, and each planner plans and exports one example
(tests/install/fresh_check.py).

The machine's own packages are not visible in the venv, so a runtime import that
pyproject.toml does not declare (networkx for trimesh's fix_normals, issue 23) fails here
even where the developer's machine has it. Slow (minutes: it installs the dependencies from
the package index or pip's cache), run by .ci/run.
"""

from __future__ import annotations

import os
import subprocess
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _run(cmd: list[str], cwd: Path, timeout: float) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return subprocess.run(
        cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False
    )


@pytest.mark.slow
@pytest.mark.timeout(2400)
def test_a_fresh_venv_installs_and_plans_every_example(tmp_path: Path) -> None:
    env_dir = tmp_path / "venv"
    venv.create(env_dir, with_pip=True, system_site_packages=False)
    python = env_dir / "bin" / "python"
    # A copy of the tree: the build writes build/ and *.egg-info, which must not land here.
    src = tmp_path / "src"
    _copy_tree(ROOT, src)
    install = _run([str(python), "-m", "pip", "install", "-q", str(src)], tmp_path, 1800)
    assert install.returncode == 0, install.stdout[-3000:] + install.stderr[-3000:]
    check = _run(
        [str(python), str(ROOT / "tests" / "install" / "fresh_check.py"), str(src)], tmp_path, 1200
    )
    out = check.stdout + check.stderr
    assert check.returncode == 0, out[-6000:]
    assert "every import" in check.stdout and " planned and exported" in check.stdout, out[-3000:]


def _copy_tree(root: Path, dest: Path) -> None:
    """Copy what git tracks and what is new but not ignored (the files a clean clone has)."""
    listed = subprocess.run(
        ["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        capture_output=True,
        check=True,
    ).stdout.split(b"\0")
    for rel in filter(None, listed):
        src = root / os.fsdecode(rel)
        if not src.is_file():  # deleted in the work tree
            continue
        target = dest / os.fsdecode(rel)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(src.read_bytes())
