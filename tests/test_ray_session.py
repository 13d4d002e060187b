"""The local Ray lets no stranger in: token authentication on the instance a search starts,
the user's RAY_AUTH_MODE=disabled respected and reported, a Ray too old to authenticate refused.

The strangers are second processes with their own HOME and RAY_AUTH_MODE=disabled, attaching on
127.0.0.1 only. Run before any module-wide Ray starts (each test asserts it).
"""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from workbench import ray_session
from workbench.batch import engine_session, run_batches
from workbench.errors import InputError

ray = pytest.importorskip("ray")
ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])  # Ray workers cannot import tests

STRANGER = """
import sys
import ray
try:
    ray.init(address=sys.argv[1], log_to_driver=False)
    @ray.remote
    def probe():
        return 7
    print("ATTACHED", ray.get(probe.remote(), timeout=30))
except Exception as err:
    print("REFUSED", type(err).__name__, err)
"""


def _square(context: int, batch: list[int]) -> list[int]:
    return [context + x * x for x in batch]


def _stranger(port: int, home: Path) -> str:
    """Return what a process without the token printed on trying to attach at 127.0.0.1:port."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("RAY_")}
    env.update(HOME=str(home), RAY_AUTH_MODE="disabled")
    done = subprocess.run(
        [sys.executable, "-c", STRANGER, f"127.0.0.1:{port}"],
        env=env,
        capture_output=True,
        text=True,
        timeout=180,
    )
    return done.stdout + done.stderr


def _gcs_port() -> int:
    return int(ray.get_runtime_context().gcs_address.rpartition(":")[2])


@pytest.fixture
def own_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A HOME of the test's own, with no Ray token in it, and no RAY_AUTH_* set."""
    assert not ray.is_initialized(), "run this module before a shared Ray starts"
    home = tmp_path / "home"
    home.mkdir()
    monkeypatch.setenv("HOME", str(home))
    for key in ("RAY_AUTH_MODE", "RAY_AUTH_TOKEN", "RAY_AUTH_TOKEN_PATH"):
        monkeypatch.delenv(key, raising=False)
    yield home
    assert not ray.is_initialized()


@pytest.mark.slow
def test_a_client_without_the_token_cannot_attach_to_the_local_ray(
    own_home: Path, tmp_path: Path
) -> None:
    items = list(range(40))
    serial = run_batches(_square, items, context=3, batch_size=7)
    with engine_session("ray") as access:
        assert access == ray_session.TOKEN_ACCESS
        assert os.environ["RAY_AUTH_MODE"] == "token"
        said = _stranger(_gcs_port(), tmp_path)
        run = run_batches(_square, items, context=3, engine="ray", batch_size=7)
    assert "REFUSED" in said and "ATTACHED" not in said, said
    assert "token" in said.lower(), said  # refused for its missing token, not by accident
    assert run.results == serial.results == [3 + x * x for x in items]
    assert ray_session.TOKEN_ACCESS in run.stats.describe()
    # nothing changed for other programs: the environment is back, no token file was written
    assert "RAY_AUTH_MODE" not in os.environ and "RAY_AUTH_TOKEN" not in os.environ
    assert not (own_home / ".ray" / "auth_token").exists()


@pytest.mark.slow
def test_ray_auth_mode_disabled_is_respected_and_reported(
    own_home: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The twin of the test above: with the user's RAY_AUTH_MODE=disabled the same stranger
    attaches (so the refusal above is the token's doing), and the report says so."""
    monkeypatch.setenv("RAY_AUTH_MODE", "disabled")
    with engine_session("ray") as access:
        said = _stranger(_gcs_port(), tmp_path)
        run = run_batches(_square, [1, 2], context=0, engine="ray")
    assert "ATTACHED 7" in said, said
    assert "any client" in access and "RAY_AUTH_MODE=disabled" in access
    assert "any client" in run.stats.describe()
    assert os.environ["RAY_AUTH_MODE"] == "disabled"


@pytest.mark.parametrize("version", ["2.9.3", "2.51.1", "2.51.9rc1", "1.13.0"])
def test_a_ray_older_than_the_floor_is_refused_naming_it_and_the_fix(version: str) -> None:
    with pytest.raises(InputError) as caught:
        ray_session.check_ray_version(version)
    message = str(caught.value)
    assert f"Ray {version} is older than 2.52.0" in message
    assert 'pip install -U "ray>=2.52.0"' in message
    assert "serial engine" in message


@pytest.mark.parametrize("version", ["2.52.0", "2.52.1", "2.60.0", "3.0.0.dev0"])
def test_a_ray_at_or_past_the_floor_is_accepted(version: str) -> None:
    assert ray_session.check_ray_version(version) == version


def test_the_floor_is_pyprojects() -> None:
    text = Path(__file__).resolve().parents[1].joinpath("pyproject.toml").read_text()
    floor = ".".join(str(n) for n in ray_session.RAY_FLOOR[:2])
    assert f'"ray>={floor}"' in text
    assert "ray-security/token-auth" in text  # the source of the floor, cited beside it


def test_an_old_ray_is_refused_before_any_ray_starts_and_serial_keeps_working(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    assert not ray.is_initialized(), "run this module before a shared Ray starts"
    monkeypatch.setattr(ray_session.metadata, "version", lambda name: "2.51.1")
    with pytest.raises(InputError, match="Ray 2.51.1 is older"):
        run_batches(_square, [1, 2], context=0, engine="ray")
    with pytest.raises(InputError, match="Ray 2.51.1 is older"):
        with engine_session("ray"):
            pass
    assert not ray.is_initialized()
    assert run_batches(_square, [1, 2], context=0).results == [1, 4]

    from workbench.cli import main

    code = main(["sweep", "bending", "projects/u_channel_cell.json", "--engine", "ray"])
    err = capsys.readouterr().err
    assert code == 2
    assert "workbench sweep: error: engine 'ray': the installed Ray 2.51.1" in err
    assert "Traceback" not in err
    assert not ray.is_initialized()
