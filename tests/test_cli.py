"""The command line: check, serve on a busy port, and clean one-line errors without tracebacks."""

from __future__ import annotations

import json
import socket
import subprocess
import sys
from pathlib import Path

import pytest
from cli_run import run_cli

ROOT = Path(__file__).resolve().parents[1]


def run(*args: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "workbench", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=ROOT,
    )


def test_check_example_is_collision_free() -> None:
    res = run_cli("check", "projects/mz07_cell.json")
    assert res.returncode == 0, res.stderr
    assert "collision-free" in res.stdout


def test_check_prints_the_controllers_joint_values(tmp_path: Path) -> None:
    """`check` shows the joints as the project file and the pendant hold them (the MZ07's
    model values of this posture are (0, 0, 0, 0, -0, -0): issue 28)."""
    data = json.loads((ROOT / "projects" / "mz07_cell.json").read_text())
    data["robot"]["joints"] = [0, 90, 0, 0, -90, 0]  # controller degrees
    path = tmp_path / "upright.json"
    path.write_text(json.dumps(data))
    res = run_cli("check", str(path))
    assert "Traceback" not in res.stderr
    assert "at [0.00, 90.00, 0.00, 0.00, -90.00, 0.00] deg (controller)" in res.stdout


def test_check_bad_project_gives_one_line_reason(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"schema_version": 1, "robot": {"preset": "mz07", "bogus": 1}}))
    res = run_cli("check", str(bad))
    assert res.returncode == 2
    assert "Traceback" not in res.stderr
    assert "robot.bogus: unknown field" in res.stderr
    bad.write_text('{"schema_version": 1,')
    res = run_cli("check", str(bad))
    assert res.returncode == 2 and "not valid JSON at line 1" in res.stderr


def test_check_colliding_configuration_exits_1(tmp_path: Path) -> None:
    data = json.loads((ROOT / "projects" / "mz07_cell.json").read_text())
    data["robot"]["joints"] = [0, 30, 0, 0, -90, 0]  # controller degrees: leaning onto the table
    path = tmp_path / "hit.json"
    path.write_text(json.dumps(data))
    res = run_cli("check", str(path))
    assert res.returncode == 1 and "table" in res.stdout


def test_serve_on_busy_port_fails_clearly() -> None:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        res = run("serve", "projects/mz07_cell.json", "--port", str(port), timeout=60)
    assert res.returncode == 2
    assert f"cannot listen on 127.0.0.1:{port}" in res.stderr and "--port" in res.stderr
    assert "Traceback" not in res.stderr


def _closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.mark.slow
def test_sweep_bending_prints_ranked_plans_and_first_reasons(tmp_path: Path) -> None:
    # The U-channel's known-bad order (the tall flange first) is rejected naming the punch;
    # the figures line names the engine. The plans printed are the service's.
    from workbench import Workbench

    res = run("sweep", "bending", "projects/u_channel_cell.json", timeout=600)
    assert res.returncode in (0, 1), res.stderr
    assert "Traceback" not in res.stderr
    assert "(serial, 1 worker(s)" in res.stdout
    assert "bA bB: bend 'bB': flange 'A' hits the punch" in res.stdout
    plans = Workbench.open(ROOT / "projects/u_channel_cell.json").bending.find_sequences().plans
    for rank, plan in enumerate(plans, 1):
        assert f"{rank}. {' '.join(plan.sequence)}: {plan.regrips} regrip(s)" in res.stdout
    assert res.returncode == (0 if plans else 1)


def test_sweep_with_a_ray_address_that_does_not_answer_names_it() -> None:
    addr = f"127.0.0.1:{_closed_port()}"
    res = run(
        "sweep", "bending", "projects/u_channel_cell.json", "--engine", "ray", "--address", addr
    )
    assert res.returncode == 2, res.stdout
    assert "Traceback" not in res.stderr
    assert addr in res.stderr


def test_sweep_needs_a_press() -> None:
    res = run_cli("sweep", "bending", "projects/bending_cell.json")
    assert res.returncode == 2
    assert "bending.press: the project has no press brake model" in res.stderr
