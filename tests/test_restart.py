"""Restarting the server on the port just used works at once; a port really held still fails.

The twin: the kernel's own TCP table (/proc/net/tcp) shows the TIME-WAIT sockets the first
server left, so the restart test is the situation that used to fail for about a minute.
"""

from __future__ import annotations

import socket
import time
from pathlib import Path

import pytest

from workbench.errors import ServerError
from workbench.gui.app import ensure_port_free, start_server
from workbench.gui.server_guard import AccessPolicy, new_token

TIME_WAIT = "06"  # the state column of /proc/net/tcp


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _time_wait_sockets(port: int) -> int:
    table = Path("/proc/net/tcp")
    if not table.exists():
        pytest.skip("no /proc/net/tcp to confirm TIME-WAIT sockets")
    n = 0
    for line in table.read_text().splitlines()[1:]:
        local, state = line.split()[1], line.split()[3]
        if int(local.split(":")[1], 16) == port and state == TIME_WAIT:
            n += 1
    return n


def _get(port: int, path: str) -> bytes:
    """Send a GET and read to the end: the server closes first, so its side keeps TIME-WAIT."""
    with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
        c.sendall(f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n".encode())
        chunks = []
        while chunk := c.recv(65536):
            chunks.append(chunk)
    return b"".join(chunks)


def test_a_restart_on_the_port_just_used_works_at_once() -> None:
    port = _free_port()
    server = start_server("127.0.0.1", port, access=AccessPolicy(new_token()))
    try:
        for _ in range(3):
            assert _get(port, "/").startswith(b"HTTP/1.1 403")  # no token: refused, closed
    finally:
        server.stop()
    stopped = time.monotonic()
    assert _time_wait_sockets(port) > 0, "the first server left no TIME-WAIT socket to test"
    again = start_server("127.0.0.1", port, access=AccessPolicy(new_token()))
    try:
        assert time.monotonic() - stopped < 1.0
        assert again.get_port() == port
        assert _get(port, "/healthz").split(b"\r\n\r\n", 1)[1] == b"ok\n"
    finally:
        again.stop()


@pytest.mark.parametrize("reuse", [False, True])
def test_a_port_held_by_another_program_fails_with_the_clear_message(reuse: bool) -> None:
    with socket.socket() as holder:
        if reuse:  # even a listener that allows address reuse holds its port
            holder.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        holder.bind(("127.0.0.1", 0))
        holder.listen(1)
        port = holder.getsockname()[1]
        with pytest.raises(ServerError, match=rf"cannot listen on 127\.0\.0\.1:{port}: .*in use"):
            ensure_port_free("127.0.0.1", port)
        with pytest.raises(ServerError, match=rf"Stop the other program using port {port}"):
            start_server("127.0.0.1", port, access=AccessPolicy(new_token()))


def test_the_health_path_answers_without_the_token_and_says_nothing_else() -> None:
    port = _free_port()
    server = start_server("127.0.0.1", port, access=AccessPolicy(new_token()))
    try:
        head, body = _get(port, "/healthz").split(b"\r\n\r\n", 1)
        assert head.startswith(b"HTTP/1.1 200") and body == b"ok\n"
        assert b"Set-Cookie" not in head  # no token handed out
        assert _get(port, "/healthz/../").startswith(b"HTTP/1.1 403")
        assert _get(port, "/?healthz").startswith(b"HTTP/1.1 403")
    finally:
        server.stop()
