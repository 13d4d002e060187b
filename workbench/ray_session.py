"""Starting or attaching the batch runner's Ray, and keeping strangers out of the local one.

- **Version floor**: Ray's token authentication exists from Ray 2.52.0 ("Token
  authentication is available in Ray 2.52.0 or later",
  https://docs.ray.io/en/latest/ray-security/token-auth.html). An installed Ray older than
  `RAY_FLOOR` is refused (`check_ray_version`) before `ray` is imported, so no Ray process
  starts; the serial engine does not need Ray at all.
- **The local Ray asks every client for a token.** A local Ray's GCS server and raylets
  listen on every network interface, and a client that attaches may run any code on this
  machine (CVE-2023-48022). Ray 2.52 leaves authentication off unless ``RAY_AUTH_MODE=token``;
  newer versions turn it on for ``ray.init()`` and write ``~/.ray/auth_token``. Where the
  environment does not decide (``RAY_AUTH_MODE`` unset), `start_ray` turns it on for the
  instance it starts, on every accepted version, with a fresh random token of its own held in
  this process's environment (``RAY_AUTH_TOKEN``, inherited by the instance's processes) and
  nowhere on disk; `stop_ray` puts the environment back, so nothing changes for other
  programs or for a later attach to a cluster. ``RAY_AUTH_MODE=disabled`` set by the user is
  respected, and `access` says that such a Ray accepts any client (the search's report shows
  it).
- **A cluster by address** is secured by the cluster (``RAY_AUTH_MODE=token`` on every node
  and the cluster's token here, ``~/.ray/auth_token`` or ``RAY_AUTH_TOKEN``); the address is
  tried with a plain socket first so a closed port is an error in seconds.
"""

from __future__ import annotations

import os
import re
import secrets
import socket
import threading
import time
from importlib import metadata
from typing import Any

from workbench.errors import InputError, WorkbenchError

__all__ = ["RAY_FLOOR", "TOKEN_ACCESS", "access", "check_ray_version", "start_ray", "stop_ray"]

# Token authentication: https://docs.ray.io/en/latest/ray-security/token-auth.html
# ("Token authentication is available in Ray 2.52.0 or later"); pyproject.toml's floor.
RAY_FLOOR = (2, 52, 0)
_AUTH_VARS = ("RAY_AUTH_MODE", "RAY_AUTH_TOKEN", "RAY_AUTH_TOKEN_PATH")
_FIX = "start a cluster with `ray start --head` or leave the address out for a local Ray"

# The environment before `start_ray` set this process's token; None while it set none.
_saved_env: dict[str, str | None] | None = None


def _floor_text() -> str:
    return ".".join(str(n) for n in RAY_FLOOR)


def check_ray_version(installed: str | None = None) -> str:
    """Return the installed Ray's version; InputError naming it and the fix if it is older than
    `RAY_FLOOR` (no token authentication) or Ray is missing. `installed` overrides the lookup
    (tests)."""
    fix = f'pip install -U "ray>={_floor_text()}"'
    if installed is None:
        try:
            installed = metadata.version("ray")
        except metadata.PackageNotFoundError:
            raise InputError(
                f"engine 'ray': Ray is not installed; {fix}, or use the serial engine"
            ) from None
    match = re.match(r"(\d+)(?:\.(\d+))?(?:\.(\d+))?", installed)
    numbers = tuple(int(n or 0) for n in match.groups()) if match else (0, 0, 0)
    if numbers < RAY_FLOOR:
        raise InputError(
            f"engine 'ray': the installed Ray {installed} is older than {_floor_text()}, the"
            " first with token authentication: its local instance would let any client on the"
            f" network run code on this machine; {fix}, or use the serial engine"
        )
    return installed


def _refresh_ray_config() -> None:
    """Make this process's Ray see the environment's authentication settings again."""
    from ray._raylet import AuthenticationTokenLoader, Config  # type: ignore[attr-defined]

    # The config first: the token loader reads the mode from it (ray's own test utilities
    # refresh in this order).
    Config.initialize("")
    AuthenticationTokenLoader.instance().reset_cache()


def _protect_local() -> None:
    """Turn token authentication on, with a fresh token, unless the environment decides."""
    global _saved_env
    if os.environ.get("RAY_AUTH_MODE") is not None:
        return  # the user's choice, respected ("disabled" included: see `access`)
    _saved_env = {k: os.environ.get(k) for k in _AUTH_VARS}
    os.environ["RAY_AUTH_MODE"] = "token"
    os.environ["RAY_AUTH_TOKEN"] = secrets.token_hex(32)  # 256 bits, as Ray's own generator
    os.environ.pop("RAY_AUTH_TOKEN_PATH", None)
    _refresh_ray_config()


def _restore_env() -> None:
    """Put back the environment `_protect_local` changed (a no-op where it changed none)."""
    global _saved_env
    if _saved_env is None:
        return
    for key, value in _saved_env.items():
        if value is None:
            os.environ.pop(key, None)
        else:
            os.environ[key] = value
    _saved_env = None
    _refresh_ray_config()


TOKEN_ACCESS = "token authentication"


def access() -> str:
    """Return who may use the Ray this process is attached to: `TOKEN_ACCESS`, or a phrase
    saying that any client may attach, with the ``RAY_AUTH_MODE`` that decided it."""
    from ray._raylet import AuthenticationMode, get_authentication_mode  # type: ignore[attr-defined]

    if get_authentication_mode() == AuthenticationMode.TOKEN:
        return TOKEN_ACCESS
    mode = os.environ.get("RAY_AUTH_MODE")
    return (
        "NO authentication: any client that reaches this machine may attach and run code"
        f" (RAY_AUTH_MODE={mode if mode is not None else 'unset'})"
    )


def start_ray(address: str | None, connect_timeout: float) -> bool:
    """Return whether this call started (or attached) Ray and so must `stop_ray` it.

    A Ray already initialised in this process is reused (False). Without `address` a new
    local instance on all cores, protected by a token unless ``RAY_AUTH_MODE`` says otherwise;
    with one, the cluster there. On any failure Ray is shut down again and the environment
    restored, so no half-initialised Ray is left behind.
    """
    check_ray_version()
    import ray

    if ray.is_initialized():
        return False
    if address is None:
        # "local": a new instance even where RAY_ADDRESS is set or `ray start` ran on this
        # machine (a bare ray.init() would attach to that cluster, or to its stale address).
        options: dict[str, Any] = {
            "address": "local",
            "num_cpus": os.cpu_count(),
            "include_dashboard": False,
        }
        _protect_local()
    else:
        _check_answers(address, connect_timeout)
        options = {"address": address}
    try:
        ray.init(**options, log_to_driver=False, configure_logging=False)
        if address is None and _saved_env is not None and access() != TOKEN_ACCESS:
            raise WorkbenchError(
                f"engine 'ray': Ray {ray.__version__} started its local instance without token"
                " authentication although RAY_AUTH_MODE=token was set; set RAY_AUTH_MODE=token"
                " yourself, or use the serial engine"
            )
    except Exception as err:
        stop_ray()
        if address is None:
            raise
        raise InputError(_attach_failure(address, err)) from err
    return True


def stop_ray() -> None:
    """Shut this process's Ray down and restore the environment `start_ray` changed."""
    import ray

    try:
        ray.shutdown()
    finally:
        _restore_env()


def _attach_failure(address: str, err: BaseException) -> str:
    """Return the message for a failed ``ray.init(address=...)``, naming the address and fix."""
    chain: list[BaseException] = []
    link: BaseException | None = err
    while link is not None and link not in chain:
        chain.append(link)
        link = link.__cause__ or link.__context__
    if any(_wants_token(e) for e in chain):
        return (
            f"the Ray cluster at {address!r} answers but wants an authentication token: set "
            "RAY_AUTH_MODE=token and make the cluster's token available (~/.ray/auth_token or "
            "RAY_AUTH_TOKEN), or leave the address out for a local Ray"
        )
    return f"could not attach to the Ray cluster at {address!r} ({err}); {_FIX}"


def _wants_token(err: BaseException) -> bool:
    """Return whether `err` says the cluster refused this process's (missing) auth token."""
    # Ray raises AuthenticationError, or, from its connect loop, a RuntimeError whose text
    # holds that error's traceback.
    return "AuthenticationError" in f"{type(err).__name__} {err}" or "InvalidAuthToken" in str(err)


def _check_answers(address: str, timeout: float) -> None:
    """Raise InputError unless a Ray head (GCS) answers at `address` within `timeout` [s].

    ``ray.init(address=...)`` retries for minutes against a port that is closed or held by
    something else, so the port is tried with a plain socket first, then with Ray's GCS
    client in a thread that is given up on (not waited for) after the timeout.
    """
    host, _, port = address.rpartition(":")
    if not host or not port.isdigit():
        raise InputError(
            f"Ray address {address!r} is not host:port (e.g. '127.0.0.1:6379'); {_FIX}"
        )
    deadline = time.perf_counter() + timeout
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=timeout):
            pass
    except OSError as err:
        why = err.strerror or type(err).__name__
        raise InputError(
            f"no Ray cluster answers at {address!r} ({why}, waited up to {timeout:g} s); {_FIX}"
        ) from None
    # Any reply, even an error, shows a Ray GCS is there; only silence means something else
    # holds the port. A refused token is reported now (ray.init would retry it for ~20 s);
    # anything else is left to ray.init, which does the real handshake.
    replied = threading.Event()
    failures: list[Exception] = []

    def probe() -> None:
        try:
            from ray._raylet import GcsClient  # type: ignore[attr-defined]

            GcsClient(address=address)
        except Exception as err:
            failures.append(err)
        replied.set()

    threading.Thread(target=probe, name="ray-gcs-probe", daemon=True).start()
    if not replied.wait(max(0.5, deadline - time.perf_counter())):
        raise InputError(
            f"something answers at {address!r} but it is not a Ray cluster head (no GCS reply "
            f"within {timeout:g} s); {_FIX}"
        )
    if failures and _wants_token(failures[0]):
        raise InputError(_attach_failure(address, failures[0])) from failures[0]
