"""The workbench GUI: one viser server over one `Workbench`."""

from __future__ import annotations

import logging
import socket
import threading
import time
from collections.abc import Sequence
from pathlib import Path

import viser

from workbench.errors import ServerError
from workbench.gui import uploads
from workbench.gui.assembly_panel import AssemblyPanel
from workbench.gui.bending_panel import BendingPanel
from workbench.gui.collision_panel import CollisionPanel
from workbench.gui.jog_panel import JogPanel
from workbench.gui.motion_panel import MotionPanel
from workbench.gui.polishing_panel import PolishingPanel
from workbench.gui.project_panel import ProjectPanel
from workbench.gui.scene import RobotScene
from workbench.gui.server_guard import (
    PINNED_VISER,
    AccessPolicy,
    guard_gui_messages,
    guarded_serve,
    is_loopback,
    new_token,
)
from workbench.gui.timeline import Timeline
from workbench.service import Workbench
from workbench.service.memory import release_memory

log = logging.getLogger("workbench.gui")


def ensure_port_free(host: str, port: int) -> None:
    """Raise ServerError when `host:port` cannot be bound (viser would silently move on)."""
    if not 0 < port < 65536:
        raise ServerError(f"--port: {port} is not a valid port (1..65535)")
    with socket.socket(
        socket.AF_INET6 if ":" in host else socket.AF_INET, socket.SOCK_STREAM
    ) as sock:
        try:
            sock.bind((host, port))
        except OSError as exc:
            raise ServerError(
                f"cannot listen on {host}:{port}: {exc.strerror}. Stop the other program using"
                f" port {port}, or pick another with --port."
            ) from None


def start_server(
    host: str = "127.0.0.1", port: int = 8080, *, access: AccessPolicy | None = None
) -> viser.ViserServer:
    """Return a running viser server bound exactly to `host:port`; raises ServerError otherwise.

    Only requests `access` allows reach it (default: a new random token; see server_guard.py):
    `access.url(host, port)` is the page's address. GUI messages are guarded too.
    """
    access = access if access is not None else AccessPolicy(new_token())
    if access.token is None and not is_loopback(host):
        raise ServerError(
            f"--no-token: refused with --host {host}; a server reachable from other machines"
            " needs its token (drop --no-token, or bind to 127.0.0.1)"
        )
    ensure_port_free(host, port)
    access.port = port
    if viser.__version__ != PINNED_VISER:
        log.warning(
            "viser %s: the access checks were written for viser %s", viser.__version__, PINNED_VISER
        )
    with guarded_serve(host, access):
        server = viser.ViserServer(host=host, port=port, label="Robot workbench", verbose=False)
    if not access.installed:
        server.stop()
        raise ServerError(
            f"viser {viser.__version__} no longer starts its server where workbench/gui/"
            "server_guard.py checks the token and origin; refusing to serve without them"
        )
    if server.get_port() != port:
        actual = server.get_port()
        server.stop()
        raise ServerError(f"port {port} was taken while starting (viser moved to {actual}); retry")
    guard_gui_messages(server)
    return server


class WorkbenchApp:
    """Scene and panels of one workbench on one server; rebuilt when the project is replaced."""

    def __init__(self, server: viser.ViserServer, wb: Workbench) -> None:
        self.server = server
        self.wb = wb
        self.lock = threading.RLock()
        server.scene.set_up_direction("+z")
        server.scene.add_grid(
            "/grid", width=3.0, height=3.0, cell_size=0.1, plane="xy", position=(0.0, 0.0, 0.0005)
        )
        server.gui.configure_theme(control_width="large", dark_mode=False)
        self.tabs = server.gui.add_tab_group()
        self.robot_tab = self.tabs.add_tab("Robot")
        self.motion_tab = self.tabs.add_tab("Motion")
        self.bending_tab = self.tabs.add_tab("Bending")
        self.assembly_tab = self.tabs.add_tab("Assembly")
        self.polishing_tab = self.tabs.add_tab("Polishing")
        self.project_tab = self.tabs.add_tab("Project")
        self.scene = RobotScene(server, wb)
        self.timeline = Timeline(server, show=self.scene.show)
        with self.robot_tab:
            self.jog = JogPanel(server, wb, on_moved=self.scene.update)
        with self.motion_tab:
            self.motion = MotionPanel(server, wb, self.timeline, on_replaced=self.rebuild)
        self._build_workflows()
        with self.project_tab:
            self.project_panel = ProjectPanel(server, wb, on_replaced=self.rebuild)

    def _build_workflows(self) -> None:
        with self.robot_tab:
            self.collision = CollisionPanel(self)
        with self.bending_tab:
            self.bending = BendingPanel(self)
        with self.assembly_tab:
            self.assembly = AssemblyPanel(self)
        with self.polishing_tab:
            self.polishing = PolishingPanel(self)

    def rebuild(self) -> None:
        """Recreate the scene and jog panel after the workbench switched projects."""
        with self.lock:
            self.timeline.pause()
            self.jog.remove()
            self.motion.remove()
            for panel in (self.collision, self.bending, self.assembly, self.polishing):
                panel.remove()
            self.scene.clear()
            self.scene.build()
            with self.robot_tab:
                self.jog = JogPanel(self.server, self.wb, on_moved=self.scene.update)
            with self.motion_tab:
                self.motion = MotionPanel(
                    self.server, self.wb, self.timeline, on_replaced=self.rebuild
                )
            self._build_workflows()
        release_memory()  # the replaced project's memory back to the OS


def serve(
    project: str | Path | None,
    *,
    host: str = "127.0.0.1",
    port: int = 8080,
    token: str | None = None,
    no_token: bool = False,
    allowed_origins: Sequence[str] = (),
    allowed_dirs: Sequence[str | Path] = (),
) -> None:
    """Serve the workbench on `host:port` until interrupted (Ctrl-C).

    The printed URL carries the access token (`token`, default a random one; `no_token` only
    with a loopback host); `allowed_origins` are other origins whose pages may connect;
    `allowed_dirs` are folders the project's files may lie in besides its own (docs/security.md).
    """
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    access = AccessPolicy(
        None if no_token else (token or new_token()),
        frozenset(o.strip().lower().rstrip("/") for o in allowed_origins),
    )
    if project is not None:
        wb = Workbench.open(project, allowed_dirs=list(allowed_dirs))
    else:
        wb = Workbench.from_dict({"schema_version": 1})
        wb.folders = wb.folders.with_allowed(*allowed_dirs)
    server = start_server(host, port, access=access)
    WorkbenchApp(server, wb)
    shown = "localhost" if host in ("127.0.0.1", "0.0.0.0", "::") else host
    print(f"workbench: serving {wb.project.name!r} on {access.url(shown, port)}", flush=True)
    if not is_loopback(host):
        print(
            f"workbench: WARNING: listening on {host}: anyone who has this URL can edit the"
            " project and save it on this machine; share it only with people you trust",
            flush=True,
        )
    try:
        while True:
            time.sleep(3600)
    finally:
        server.stop()
        uploads.remove_all()
