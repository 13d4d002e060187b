"""The workbench GUI: one viser server over one `Workbench`."""

from __future__ import annotations

import logging
import os
import signal
import socket
import threading
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import viser

from workbench.errors import ServerError, WorkbenchError
from workbench.gui import jobs as gui_jobs
from workbench.gui import project_upload, uploads
from workbench.gui.assembly_panel import AssemblyPanel
from workbench.gui.bending_panel import BendingPanel
from workbench.gui.calibration_panel import CalibrationPanel
from workbench.gui.collision_panel import CollisionPanel
from workbench.gui.import_panel import ImportPanel
from workbench.gui.jog_panel import JogPanel
from workbench.gui.motion_panel import MotionPanel
from workbench.gui.picker import Picker
from workbench.gui.polishing_panel import PolishingPanel
from workbench.gui.project_panel import ProjectPanel
from workbench.gui.project_undo import ProjectUndo
from workbench.gui.scene import CameraViews, RobotScene
from workbench.gui.server_guard import (
    PINNED_VISER,
    AccessPolicy,
    guard_gui_messages,
    guarded_serve,
    is_loopback,
    new_token,
)
from workbench.gui.timeline import Timeline
from workbench.gui.touchup_panel import TouchupPanel
from workbench.service import Workbench
from workbench.service.memory import release_memory
from workbench.service.project_files import open_into

log = logging.getLogger("workbench.gui")


def ensure_port_free(host: str, port: int) -> None:
    """Raise ServerError when `host:port` cannot be bound (viser would silently move on).

    The probe sets SO_REUSEADDR, as the server's own socket does (asyncio on POSIX): a port
    with only TIME-WAIT connections of a server just stopped is free, a port another program
    listens on is not.
    """
    if not 0 < port < 65536:
        raise ServerError(f"--port: {port} is not a valid port (1..65535)")
    with socket.socket(
        socket.AF_INET6 if ":" in host else socket.AF_INET, socket.SOCK_STREAM
    ) as sock:
        if os.name == "posix":  # on Windows SO_REUSEADDR would let two servers share a port
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind((host, port))
            sock.listen(1)  # bind alone succeeds beside a listener that also set SO_REUSEADDR
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
    """Scene and panels of one workbench on one server; rebuilt when the project is replaced.

    Every page shows the same session. Long jobs and project loads go through `jobs` (one at
    a time; the banner on top shows the running one). `picker` (a server started without a
    project) shows the example projects to open instead of the tabs. "Save as" writes in
    `save_folder` (default: the working folder).
    """

    def __init__(
        self,
        server: viser.ViserServer,
        wb: Workbench,
        *,
        picker: bool = False,
        save_folder: str | Path | None = None,
    ) -> None:
        self.server = server
        self.wb = wb
        self.lock = threading.RLock()
        self.jobs = gui_jobs.of(server)
        self.save_folder = Path(save_folder if save_folder is not None else Path.cwd()).resolve()
        self.allowed = tuple(wb.folders.allowed)  # the folders allowed at start (--allow-dir)
        self.upload_root: Path | None = None  # the folder of the uploaded project in use
        self.undo = ProjectUndo(lambda: self.wb)  # calibration and touch-up applies
        server.scene.set_up_direction("+z")
        server.scene.add_grid(
            "/grid", width=3.0, height=3.0, cell_size=0.1, plane="xy", position=(0.0, 0.0, 0.0005)
        )
        server.gui.configure_theme(control_width="large", dark_mode=False)
        self.banner = server.gui.add_markdown("", visible=False)
        self.jobs.attach(self.banner)
        self.views = CameraViews(server, wb)  # above the tabs: camera fit and view presets
        self.picker: Picker | None = None
        if picker:
            self.picker = Picker(server, lambda ex, event: self.project_panel.open(ex, event))
        self.tabs = server.gui.add_tab_group(visible=not picker)
        self.robot_tab = self.tabs.add_tab("Robot")
        self.motion_tab = self.tabs.add_tab("Motion")
        self.bending_tab = self.tabs.add_tab("Bending")
        self.assembly_tab = self.tabs.add_tab("Assembly")
        self.polishing_tab = self.tabs.add_tab("Polishing")
        self.project_tab = self.tabs.add_tab("Project")
        self.scene = RobotScene(server, wb)
        self.timeline = Timeline(server, show=self.scene.show)
        self._build_panels()
        with self.project_tab:
            self.project_panel = ProjectPanel(self)
            self.import_panel = ImportPanel(self)
            self.calibration = CalibrationPanel(self)
            self.touchup = TouchupPanel(self)

    def _build_panels(self) -> None:
        with self.robot_tab:
            self.jog = JogPanel(self.server, self.wb, on_moved=self.scene.update)
        self.scene.gizmo, self.scene.timeline = self.jog.gizmo, self.timeline
        with self.motion_tab:
            self.motion = MotionPanel(
                self.server, self.wb, self.timeline, on_replaced=self.rebuild, scene=self.scene
            )
        self._build_workflows()

    def _build_workflows(self) -> None:
        with self.robot_tab:
            self.collision = self._panel(CollisionPanel, "Collision")
        with self.bending_tab:
            self.bending = self._panel(BendingPanel, "Bending")
        with self.assembly_tab:
            self.assembly = self._panel(AssemblyPanel, "Assembly")
        with self.polishing_tab:
            self.polishing = self._panel(PolishingPanel, "Polishing")

    def _panel(self, cls: type, name: str) -> Any:
        """Build panel `cls`; one that fails shows its error in its tab, the others still build."""
        try:
            return cls(self)
        except WorkbenchError as exc:
            return _FailedPanel(self.server, f"**{name}: cannot show this section:** {exc}")

    # -- switching projects -------------------------------------------------------------------
    def open_file(self, path: Path, *, allowed: tuple[Path, ...] = ()) -> None:
        """Open the project file `path` (Busy while a job runs; on errors nothing changes)."""
        with self.jobs.job("loading a project"):
            open_into(self.wb, path, allowed=(*self.allowed, *allowed))
            self._replaced(None)

    def open_upload(self, json_path: Path, root: Path) -> None:
        """Open an uploaded project unpacked in `root` (it gets no file: Save needs a name)."""
        with self.jobs.job("loading a project"):
            open_into(self.wb, json_path, allowed=self.allowed, session=(root,), unsaved=True)
            self._replaced(root)

    def undo_last(self) -> str:
        """Undo the last calibration or touch-up applied (`project_undo.py`); return what."""

        def replace(previous: object) -> None:
            with self.jobs.job("undoing"):
                self.wb.replace_project(previous)  # type: ignore[arg-type]
                self.rebuild()

        return self.undo.undo(replace)

    def _replaced(self, upload_root: Path | None) -> None:
        old, self.upload_root = self.upload_root, upload_root
        self.undo.clear()  # another project: nothing of the last one to undo
        if hasattr(self, "calibration"):  # results of the previous project: gone
            self.calibration.clear()
            self.touchup.clear()
        if old is not None and old != upload_root:
            project_upload.remove_folder(old)
        if self.picker is not None:
            self.picker.remove()
            self.picker = None
            self.tabs.visible = True
        self.rebuild()

    def rebuild(self) -> None:
        """Recreate the scene and every panel after the workbench switched projects.

        Runs as a job (Busy while another job runs, so no running job loses its widgets); the
        timeline drops the previous project's motion.
        """
        with self.jobs.job("rebuilding the tabs"), self.lock:
            self.timeline.clear()
            self.jog.remove()
            self.motion.remove()
            for panel in (self.collision, self.bending, self.assembly, self.polishing):
                panel.remove()
            self.scene.clear()
            self.scene.build()
            self._build_panels()
            self.views.frame_all()
            if hasattr(self, "project_panel"):
                self.project_panel.refresh()
            if hasattr(self, "import_panel"):
                self.import_panel.refresh()
            if hasattr(self, "calibration"):
                self.calibration.refresh()
        release_memory()  # the replaced project's memory back to the OS


class _FailedPanel:
    """What a tab shows when its panel could not be built (the project's section is unusable)."""

    def __init__(self, server: viser.ViserServer, text: str) -> None:
        self.note = server.gui.add_markdown(text)

    def remove(self) -> None:
        self.note.remove()


def _exit_on_sigterm(signum: int, frame: object) -> None:
    raise SystemExit(128 + signum)


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
    started = time.time()
    if threading.current_thread() is threading.main_thread():
        # `docker stop`, systemd, kill: a normal exit, so the `finally` below and atexit
        # remove the upload folders (Python's default for SIGTERM ends without either)
        signal.signal(signal.SIGTERM, _exit_on_sigterm)
    for folder in uploads.remove_stale(started):
        logging.getLogger(__name__).info("removed %s, left behind by a server that is gone", folder)
    access = AccessPolicy(
        None if no_token else (token or new_token()),
        frozenset(o.strip().lower().rstrip("/") for o in allowed_origins),
    )
    if project is not None:
        wb = Workbench.open(project, allowed_dirs=list(allowed_dirs))
    else:  # the page opens on the project picker (examples and upload)
        wb = Workbench.from_dict({"schema_version": 1, "name": "no project"})
        wb.folders = wb.folders.with_allowed(*allowed_dirs)
    server = start_server(host, port, access=access)
    WorkbenchApp(server, wb, picker=project is None)
    shown = "localhost" if host in ("127.0.0.1", "0.0.0.0", "::") else host
    what = repr(wb.project.name) if project is not None else "the project picker"
    print(f"workbench: serving {what} on {access.url(shown, port)}", flush=True)
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
