"""Issue 16 part 1: only our page drives the server.

A raw websocket client (the `websockets` package viser uses) plays the foreign page: claiming
`Origin: http://evil.example`, or lacking the token, it is refused at the handshake (no scene,
nothing it can click). Its twin, the same client with the token from the page's own origin,
gets the scene and can save: the refusals are the checks, not a broken server. Connected
clients cannot click disabled buttons or flip a control's `disabled` prop.
"""

from __future__ import annotations

import inspect
import json
import shutil
import socket
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import msgspec
import pytest
import viser
import viser._gui_api
import viser._messages as vmsg
import viser.infra._infra as infra
import websockets.exceptions
import websockets.sync.client
import zstandard
from websockets.datastructures import Headers
from websockets.http11 import Request
from websockets.typing import Subprotocol

from workbench import Workbench
from workbench.errors import ServerError
from workbench.gui.app import WorkbenchApp, start_server
from workbench.gui.server_guard import PINNED_VISER, AccessPolicy, new_token

ROOT = Path(__file__).resolve().parents[1]
TOKEN = "t0ken-for-the-tests-" + "x" * 20


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="module")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, Any]]:
    folder = tmp_path_factory.mktemp("served")
    project = folder / "cell.json"
    shutil.copy(ROOT / "projects" / "mz07_cell.json", project)
    wb = Workbench.open(project)
    port = _free_port()
    access = AccessPolicy(TOKEN)
    server = start_server("127.0.0.1", port, access=access)
    app = WorkbenchApp(server, wb)
    yield {"app": app, "port": port, "project": project, "access": access}
    app.timeline.close()
    server.stop()


def _connect(port: int, headers: dict[str, str], path: str = "/") -> Any:
    return websockets.sync.client.connect(
        f"ws://127.0.0.1:{port}{path}",
        subprotocols=[Subprotocol(f"viser-v{viser.__version__}")],
        additional_headers=headers,
        open_timeout=10,
        max_size=None,
    )


def _message_types(frame: bytes) -> list[str]:
    """Return the message types in one server-to-client frame (viser's wire format)."""
    n_inner = int.from_bytes(frame[:8], "little")
    n_comp = int.from_bytes(frame[8:16], "little")
    inner = zstandard.ZstdDecompressor().decompress(frame[16 : 16 + n_comp], n_inner)
    return [m["type"] for m in msgspec.msgpack.decode(inner)["messages"]]


def _send(ws: Any, message: vmsg.Message) -> None:
    ws.send(msgspec.msgpack.encode(message.as_serializable_dict()))


def _refused(port: int, headers: dict[str, str], path: str = "/") -> int:
    with pytest.raises(websockets.exceptions.InvalidStatus) as err:
        _connect(port, headers, path).close()
    return int(err.value.response.status_code)


def test_a_foreign_origin_or_a_missing_token_gets_no_connection(served: dict[str, Any]) -> None:
    port, app = served["port"], served["app"]
    own = f"http://127.0.0.1:{port}"
    cookie = f"workbench-token-{port}={TOKEN}"
    before = served["project"].read_text()
    cases = [
        ({"Origin": "http://evil.example", "Cookie": cookie}, "/"),  # token stolen, other site
        ({"Origin": "http://evil.example"}, f"/?token={TOKEN}"),
        ({"Origin": f"http://127.0.0.1:{port + 1}", "Cookie": cookie}, "/"),  # another local port
        ({"Origin": own}, "/"),  # the page's origin, no token
        ({"Origin": own, "Cookie": f"workbench-token-{port}=wrong"}, "/?token=wrong"),
        ({}, "/"),  # a raw client, no token
    ]
    for headers, path in cases:
        assert _refused(port, headers, path) == 403, headers
    assert app.server.get_clients() == {}
    assert served["project"].read_text() == before  # nothing could press "Save on server"


def test_the_page_needs_the_token_and_then_sets_the_cookie(served: dict[str, Any]) -> None:
    port, access = served["port"], served["access"]
    with pytest.raises(urllib.error.HTTPError) as err:
        urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=10)
    assert err.value.code == 403 and b"?token=" in err.value.read()
    with urllib.request.urlopen(access.url("127.0.0.1", port), timeout=10) as ok:
        assert ok.status == 200 and b"<html" in ok.read(2000)
        cookie = ok.headers["Set-Cookie"]
    assert f"workbench-token-{port}={TOKEN}" in cookie
    assert "HttpOnly" in cookie and "SameSite=Strict" in cookie
    again = urllib.request.Request(
        f"http://127.0.0.1:{port}/", headers={"Cookie": cookie.split(";")[0]}
    )
    with urllib.request.urlopen(again, timeout=10) as ok:
        assert ok.status == 200


def test_our_page_gets_the_scene_and_disabled_buttons_stay_dead(served: dict[str, Any]) -> None:
    port, app, project = served["port"], served["app"], served["project"]
    save = app.project_panel.save
    headers = {"Origin": f"http://127.0.0.1:{port}", "Cookie": f"workbench-token-{port}={TOKEN}"}
    with _connect(port, headers) as ws:
        seen: set[str] = set()
        deadline = time.monotonic() + 20
        while "ReplayDoneMessage" not in seen and time.monotonic() < deadline:
            seen.update(_message_types(ws.recv(timeout=20)))
        assert any("Mesh" in t for t in seen) and "GuiButtonMessage" in seen, seen
        # viser counts a client as connected after its first camera message.
        _send(
            ws,
            vmsg.ViewerCameraMessage(
                (1, 0, 0, 0), (2, 2, 2), 1.0, 0.01, 100, 480, 640, (0, 0, 0), (0, 0, 1)
            ),
        )
        deadline = time.monotonic() + 20
        while not app.server.get_clients() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert len(app.server.get_clients()) == 1
        app.wb.set_joints(app.wb.joints + 0.01)  # something new to save
        before = project.read_text()
        save.disabled = True
        uuid = save._impl.uuid
        _send(ws, vmsg.GuiUpdateMessage(uuid, {"value": True}))  # a click on a disabled button
        _send(ws, vmsg.GuiUpdateMessage(uuid, {"disabled": False}))  # or enabling it
        time.sleep(1.0)
        assert save.disabled and project.read_text() == before
        save.visible = False
        save.disabled = False
        _send(ws, vmsg.GuiUpdateMessage(uuid, {"value": True}))  # a hidden button
        time.sleep(1.0)
        assert project.read_text() == before
        save.visible = True
        _send(ws, vmsg.GuiUpdateMessage(uuid, {"value": True}))  # the twin: shown and enabled
        deadline = time.monotonic() + 20
        while project.read_text() == before and time.monotonic() < deadline:
            time.sleep(0.1)
        assert project.read_text() != before
        assert (
            json.loads(project.read_text())["robot"]["joints"]
            != json.loads(before)["robot"]["joints"]
        )


def _request(path: str = "/", **headers: str) -> Request:
    return Request(path, Headers(list(headers.items())))


def test_the_policy_rules() -> None:
    p = AccessPolicy(TOKEN, frozenset({"https://cell.example"}), port=8080)
    ok = {"Host": "127.0.0.1:8080", "Cookie": f"workbench-token-8080={TOKEN}"}
    assert p.refusal(_request(**ok, Origin="http://127.0.0.1:8080"), websocket=True) is None
    assert p.refusal(_request(**ok, Origin="https://cell.example"), websocket=True) is None
    assert p.refusal(_request(**ok, Origin="http://localhost:8080"), websocket=True) is not None
    assert p.refusal(_request(f"/?token={TOKEN}", Host="x:1"), websocket=True) is None
    other_port = {"Host": "127.0.0.1:8080", "Cookie": f"workbench-token-8081={TOKEN}"}
    assert p.refusal(_request(**other_port), websocket=False) is not None
    # Without a token (loopback only), a foreign Host (DNS rebinding) is refused.
    open_ = AccessPolicy(None, port=8080)
    assert open_.refusal(_request(Host="127.0.0.1:8080"), websocket=True) is None
    rebound = _request(Host="evil.example:8080", Origin="http://evil.example:8080")
    assert open_.refusal(rebound, websocket=True) is not None
    assert p.url("127.0.0.1", 8080) == f"http://127.0.0.1:8080/?token={TOKEN}"
    assert len(new_token()) >= 40 and new_token() != new_token()


def test_no_token_only_on_loopback_and_tokens_are_checked() -> None:
    with pytest.raises(ServerError, match="--no-token"):
        start_server("0.0.0.0", _free_port(), access=AccessPolicy(None))
    for bad in ("short", "has space" * 4, "semi;colon" * 3):
        with pytest.raises(ServerError, match="--token"):
            AccessPolicy(bad)


def test_the_viser_internals_we_wrap_are_still_there() -> None:
    """Fails loudly when viser changes what server_guard.py wraps: re-check it, then re-pin."""
    assert viser.__version__ == PINNED_VISER
    worker = inspect.getsource(infra.WebsockServer._background_worker)
    assert "websockets.asyncio.server.serve(" in worker
    assert "process_request=" in worker and 'headers.get("Upgrade") == "websocket"' in worker
    gui = inspect.getsource(viser._gui_api.GuiApi.__init__)
    for name in (
        "_handle_gui_updates",
        "_handle_gui_button_hold",
        "_handle_file_transfer_start",
        "_handle_file_transfer_part",
    ):
        assert name in gui
    client = (Path(viser.__file__).parent / "client" / "src" / "App.tsx").read_text()
    # The client connects to the page's own host without the query: hence the cookie.
    assert 'server = server.split("?")[0];' in client
