"""Only our page drives the server: the access token, the Origin check, and server-side GUI guards.

Who may connect (viser 1.1.1 has no hook for it). viser's `WebsockServer` starts
`websockets.asyncio.server.serve(..., process_request=viser_http_server)` inside its
background thread; `process_request` sees every HTTP request (the page) and every websocket
handshake before the connection exists. `guarded_serve` wraps that `process_request` for the
servers started inside it (`start_server` in app.py), and `start_server` fails loudly when the
wrap did not happen (`PINNED_VISER`, and tests/test_security_server.py pins the internals):

- the page: served only to a request carrying the token, in the query (`/?token=...`, the URL
  `workbench serve` prints) or in the cookie set when that page was served
  (HttpOnly, SameSite=Strict, named after the port); anything else gets 403 and no content;
- the websocket (the viser client connects to the page's own host, without the query): needs
  the token (cookie or `?token=`) and, when a browser sends an `Origin`, that origin must be the
  page's own (`http://` + the Host header) or one given with `--allow-origin`;
- without a token (`--no-token`, loopback only) the Host header must name the loopback too, so
  a DNS-rebound foreign name cannot reach the server.

What a connected client may do (`guard_gui_messages`): a GUI update may change only a
control's value, and only of a control that is enabled and shown (with its folders); button
holds likewise; uploads go only to enabled, shown upload buttons and stop at `max_upload_bytes()`.
"""

from __future__ import annotations

import hmac
import http
import http.cookies
import inspect
import ipaddress
import logging
import re
import secrets
import threading
import urllib.parse
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import viser
import viser._messages as vmsg
import websockets.asyncio.server
from websockets.datastructures import Headers
from websockets.http11 import Request, Response

from workbench.errors import ServerError
from workbench.service.mesh_files import mesh_size_limit

log = logging.getLogger("workbench.gui")

PINNED_VISER = "1.1.1"  # the version whose internals this module wraps (see the tests)
TOKEN_PATTERN = re.compile(r"[A-Za-z0-9._~-]{16,256}")
LOOPBACK_NAMES = frozenset({"localhost", "127.0.0.1", "::1", "[::1]"})


def max_upload_bytes() -> int:
    """Return the largest upload accepted [bytes]: the mesh file limit (docs/security.md)."""
    return mesh_size_limit()


def new_token() -> str:
    """Return a fresh random access token (32 bytes, URL-safe)."""
    return secrets.token_urlsafe(32)


def is_loopback(host: str) -> bool:
    """Return True when `host` (a name or address) is the loopback interface only."""
    h = host.strip("[]")
    if h == "localhost":
        return True
    try:
        return ipaddress.ip_address(h).is_loopback
    except ValueError:
        return False


def _hostname(host_header: str) -> str:
    """Return the host name of a Host header value (no port), lower case."""
    h = host_header.strip().lower()
    if h.startswith("["):
        return h[: h.find("]") + 1] if "]" in h else h
    return h.rsplit(":", 1)[0] if h.count(":") == 1 else h


@dataclass
class AccessPolicy:
    """Who may load the page and open the websocket; see the module doc."""

    token: str | None
    allowed_origins: frozenset[str] = frozenset()
    port: int = 0
    installed: bool = field(default=False, compare=False)  # set when a server was wrapped

    def __post_init__(self) -> None:
        if self.token is not None and not TOKEN_PATTERN.fullmatch(self.token):
            raise ServerError(
                "--token: use 16 to 256 letters, digits, '-', '_', '.' or '~' (a URL- and"
                " cookie-safe text); or leave it out for a random one"
            )

    @property
    def cookie_name(self) -> str:
        """Return the name of the token cookie (per port: two servers on one host differ)."""
        return f"workbench-token-{self.port}"

    def url(self, host: str, port: int, **params: str) -> str:
        """Return the page's address on `host:port`, with the token and `params` in the query."""
        query = {"token": self.token} if self.token is not None else {}
        query.update(params)
        shown = f"[{host}]" if ":" in host and not host.startswith("[") else host
        tail = f"?{urllib.parse.urlencode(query)}" if query else ""
        return f"http://{shown}:{port}/{tail}"

    def _token_given(self, request: Request) -> tuple[bool, bool]:
        """Return (token in the query, token in the cookie), each True only when it matches."""
        if self.token is None:
            return True, True
        query = urllib.parse.parse_qs(urllib.parse.urlsplit(request.path).query)
        in_query = any(
            hmac.compare_digest(t.encode(), self.token.encode()) for t in query.get("token", [])
        )
        in_cookie = False
        for raw in request.headers.get_all("Cookie"):
            jar = http.cookies.SimpleCookie()
            try:
                jar.load(raw)
            except http.cookies.CookieError:
                continue
            morsel = jar.get(self.cookie_name)
            if morsel is not None and hmac.compare_digest(
                morsel.value.encode(), self.token.encode()
            ):
                in_cookie = True
        return in_query, in_cookie

    def _host_ok(self, request: Request) -> bool:
        if self.token is not None:
            return True
        return _hostname(request.headers.get("Host", "")) in LOOPBACK_NAMES

    def origin_ok(self, request: Request) -> bool:
        """Return True when the request's Origin (if any) is the page's own or an allowed one."""
        origins = request.headers.get_all("Origin")
        if not origins:
            return True  # not a browser: the token decides
        if len(origins) > 1:
            return False
        origin = origins[0].strip().lower().rstrip("/")
        if origin in self.allowed_origins:
            return True
        host = request.headers.get("Host", "").strip().lower()
        return bool(host) and origin in (f"http://{host}", f"https://{host}")

    def refusal(self, request: Request, *, websocket: bool) -> Response | None:
        """Return the 403 response for a request that may not proceed, or None to let it through."""
        in_query, in_cookie = self._token_given(request)
        if not self._host_ok(request):
            return _forbidden("this server answers on its loopback address only")
        if websocket and not self.origin_ok(request):
            log.warning("refused a websocket from origin %r", request.headers.get("Origin"))
            return _forbidden("connections from another site's page are refused")
        if not (in_query or in_cookie):
            if websocket:
                log.warning("refused a websocket without the access token")
            return _forbidden(
                "this workbench needs its access token: open the URL that `workbench serve`"
                " printed (it ends in ?token=...)"
            )
        return None

    def wrap(self, inner: Callable[..., Any] | None) -> Callable[..., Any]:
        """Return viser's `process_request` with the checks in front and the cookie added."""

        async def process_request(connection: Any, request: Request) -> Response | None:
            websocket = request.headers.get("Upgrade", "").lower() == "websocket"
            if not websocket and urllib.parse.urlsplit(request.path).path == HEALTH_PATH:
                return _health()  # token-free: says only that the server answers
            refused = self.refusal(request, websocket=websocket)
            if refused is not None:
                return refused
            response = inner(connection, request) if inner is not None else None
            if inspect.isawaitable(response):
                response = await response
            if response is not None and not websocket and self.token is not None:
                response.headers["Set-Cookie"] = (
                    f"{self.cookie_name}={self.token}; Path=/; HttpOnly; SameSite=Strict"
                )
                response.headers["Cache-Control"] = "no-store"
                response.headers["Referrer-Policy"] = "no-referrer"
            return response

        self.installed = True
        return process_request


HEALTH_PATH = "/healthz"  # answers "ok" without the token (the Dockerfile's HEALTHCHECK)


def _health() -> Response:
    body = b"ok\n"
    headers = Headers(
        [("Content-Type", "text/plain; charset=utf-8"), ("Content-Length", str(len(body)))]
    )
    return Response(http.HTTPStatus.OK.value, "OK", headers, body)


def _forbidden(why: str) -> Response:
    body = f"403 Forbidden: {why}.\n".encode()
    headers = Headers(
        [("Content-Type", "text/plain; charset=utf-8"), ("Content-Length", str(len(body)))]
    )
    return Response(http.HTTPStatus.FORBIDDEN.value, "Forbidden", headers, body)


# -- the wrap of viser's serve() -------------------------------------------------------------
_REAL_SERVE = websockets.asyncio.server.serve
_PENDING: dict[str, AccessPolicy] = {}  # host -> policy, while a guarded server starts
_START_LOCK = threading.Lock()


class _GuardedServe(_REAL_SERVE):  # type: ignore[misc, valid-type]
    """`websockets.asyncio.server.serve` that puts a pending policy in front of viser's handler."""

    def __init__(self, handler: Any, host: Any = None, port: Any = None, **kwargs: Any) -> None:
        policy = _PENDING.get(str(host))
        if policy is not None:
            kwargs["process_request"] = policy.wrap(kwargs.get("process_request"))
        super().__init__(handler, host, port, **kwargs)


def _install() -> None:
    if websockets.asyncio.server.serve is not _GuardedServe:
        websockets.asyncio.server.serve = _GuardedServe  # type: ignore[misc]


@contextmanager
def guarded_serve(host: str, policy: AccessPolicy) -> Iterator[None]:
    """Within the block, a viser server started on `host` answers only as `policy` allows."""
    with _START_LOCK:
        _install()
        _PENDING[host] = policy
        try:
            yield
        finally:
            _PENDING.pop(host, None)


# -- what a connected client may do ----------------------------------------------------------
def _shown_and_enabled(server: viser.ViserServer, handle: Any) -> bool:
    if getattr(handle, "disabled", False) or not getattr(handle, "visible", True):
        return False
    containers = server.gui._container_handle_from_uuid
    parent = getattr(handle._impl, "parent_container_id", "root")
    for _ in range(64):
        container = containers.get(parent)
        if container is None:
            return True
        if not getattr(container, "visible", True):
            return False
        impl = getattr(container, "_impl", None)
        parent = getattr(impl, "parent_container_id", None)
        if parent is None:
            return True
    return False


def guard_gui_messages(server: viser.ViserServer) -> None:
    """Put the checks of the module doc in front of viser's GUI message handlers."""
    gui = server.gui
    handlers = server._websock_server._incoming_handlers
    inputs = gui._gui_input_handle_from_uuid

    def replace(cls: type, original: Callable[..., Any], new: Callable[..., Any]) -> None:
        lst = handlers[cls]
        lst[lst.index(original)] = new

    on_update, on_hold = gui._handle_gui_updates, gui._handle_gui_button_hold
    on_start, on_part = gui._handle_file_transfer_start, gui._handle_file_transfer_part

    async def update(client_id: Any, message: vmsg.GuiUpdateMessage) -> None:
        handle = inputs.get(message.uuid)
        if handle is None:
            return
        if set(message.updates) != {"value"} or not _shown_and_enabled(server, handle):
            log.info("ignored an update of a disabled or hidden control (%s)", message.uuid)
            return
        await on_update(client_id, message)

    async def hold(client_id: Any, message: vmsg.GuiButtonHoldMessage) -> None:
        handle = inputs.get(message.uuid)
        if handle is not None and _shown_and_enabled(server, handle):
            await on_hold(client_id, message)

    def start(client_id: Any, message: vmsg.FileTransferStartUpload) -> None:
        handle = inputs.get(message.source_component_uuid)
        if handle is None or not _shown_and_enabled(server, handle):
            return
        size, parts = int(message.size_bytes), int(message.part_count)
        if not (0 <= size <= max_upload_bytes()) or not (0 <= parts <= size // 1024 + 1):
            log.warning("refused an upload of %d bytes in %d parts", size, parts)
            return
        on_start(client_id, message)

    def part(client_id: Any, message: vmsg.FileTransferPart) -> None:
        state = gui._current_file_upload_states.get(message.transfer_uuid)
        if state is None or state["client_id"] != client_id:
            return
        if state["transferred_bytes"] + len(message.content) > state["total_bytes"]:
            gui._current_file_upload_states.pop(message.transfer_uuid, None)
            log.warning("dropped an upload that sent more than it declared")
            return
        on_part(client_id, message)

    replace(vmsg.GuiUpdateMessage, on_update, update)
    replace(vmsg.GuiButtonHoldMessage, on_hold, hold)
    replace(vmsg.FileTransferStartUpload, on_start, start)
    replace(vmsg.FileTransferPart, on_part, part)
