"""Scene nodes of the robot, its tool and the cell; moved by pose, recoloured on collision; the
last motion plan's TCP path; the camera views (fit to the service's scene bounds, presets)."""

from __future__ import annotations

import logging
import traceback
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import trimesh
import viser
from numpy.typing import NDArray

from workbench.geometry.transforms import matrix_to_wxyz
from workbench.gui.notify import guarded
from workbench.service import SampledMotion, Workbench
from workbench.service.scene_bounds import scene_bounds

log = logging.getLogger("workbench.gui")
ROBOT_COLOR = (235, 235, 240)
COLLISION_COLOR = (230, 40, 40)
PATH_COLOR = (30, 110, 230)
VIEWS: dict[str, tuple[float, float, float]] = {
    "Front": (0.0, -1.0, 0.0),  # from -y, looking along +y
    "Top": (0.0, -0.01, 1.0),  # from above (a hair off the pole: the orbit controls keep +z up)
    "Side": (1.0, 0.0, 0.0),  # from +x, looking along -x
    "Iso": (1.0, -1.0, 0.8),
}
"""The view presets: the direction from the framed box's centre to the camera (world)."""
MIN_RADIUS = 0.15  # [m] the smallest sphere a view frames (a flat or tiny box)
DEFAULT_FOV = np.pi * 50 / 180  # [rad] vertical field of view before the client reports its own


def camera_pose(
    lo: NDArray[np.float64],
    hi: NDArray[np.float64],
    direction: tuple[float, float, float],
    fov: float,
    aspect: float,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return (position, look_at) [m] of a camera (up +z) looking along -`direction` at the
    box [`lo`, `hi`]'s centre from the nearest distance at which every corner is in view."""
    centre = (lo + hi) / 2
    half = np.maximum((hi - lo) / 2, MIN_RADIUS / 2)
    back = np.asarray(direction, float)
    back = back / np.linalg.norm(back)  # from the centre towards the camera
    right = np.cross(-back, (0.0, 0.0, 1.0))
    right = right / np.linalg.norm(right) if np.linalg.norm(right) > 1e-9 else np.array([1.0, 0, 0])
    up = np.cross(right, -back)
    signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)
    corners = signs * half  # relative to the centre
    tan_v = np.tan(fov / 2)
    tan_h = tan_v * max(aspect, 1e-3)
    # a corner at height u and depth d - w (w: its offset towards the camera) is in view when
    # |u| <= (d - w) tan: the distance is the largest such d over corners and both axes
    w = corners @ back
    d = np.max(
        np.concatenate([np.abs(corners @ up) / tan_v + w, np.abs(corners @ right) / tan_h + w])
    )
    return centre + back * d * 1.08, centre


def place(handle: viser.SceneNodeHandle, T: NDArray[np.float64]) -> None:
    """Move a scene node to the world pose `T` (4, 4) [m]."""
    handle.wxyz = matrix_to_wxyz(T[:3, :3])
    handle.position = np.asarray(T[:3, 3], float)


def _add_mesh(
    server: viser.ViserServer,
    name: str,
    mesh: trimesh.Trimesh,
    color: tuple[int, int, int],
    T: NDArray[np.float64],
) -> viser.MeshHandle:
    return server.scene.add_mesh_simple(
        name,
        np.asarray(mesh.vertices, np.float32),
        np.asarray(mesh.faces, np.uint32),
        color=color,
        flat_shading=False,
        wxyz=matrix_to_wxyz(T[:3, :3]),
        position=np.asarray(T[:3, 3], float),
    )


class RobotScene:
    """The 3D nodes of one workbench: cell bodies, robot links, tool and TCP frame."""

    def __init__(self, server: viser.ViserServer, wb: Workbench) -> None:
        self.server = server
        self.wb = wb
        self.nodes: list[viser.SceneNodeHandle] = []
        self.links: dict[str, viser.MeshHandle] = {}
        self.bodies: dict[str, viser.MeshHandle] = {}  # the cell bodies drawn, by name
        # Called with the joints (None: the workbench's own) after every pose, for what
        # follows the robot (e.g. the collision spheres).
        self.on_show: list[Callable[[NDArray[np.float64] | None], None]] = []
        # The TCP gizmo (the Robot tab's) shows where it acts: on the robot's own joints and
        # on the playback of the last motion plan, which it follows; hidden elsewhere.
        self.gizmo: Any = None
        self.timeline: Any = None
        self.plan_samples: SampledMotion | None = None
        self.path_node: Any = None
        self.build()

    def build(self) -> None:
        """Create every node for the current project (after `clear`, or the first time)."""
        wb, s = self.wb, self.server
        for body in wb.cell:
            if not body.display:
                continue  # an envelope the robot is checked against (the ram's stroke)
            h = _add_mesh(s, f"/cell/{body.name}", body.mesh(), body.color, body.T_world_body)
            self.bodies[body.name] = h
            self.nodes.append(h)
        poses = wb.link_poses()
        names = wb.checker.link_names
        for name, mesh, T in zip(names, wb.setup.link_meshes, poses, strict=True):
            h = _add_mesh(s, f"/robot/{name}", mesh, ROBOT_COLOR, T)
            self.links[name] = h
            self.nodes.append(h)
        if wb.setup.tool_mesh is not None:
            h = _add_mesh(s, "/robot/tool", wb.setup.tool_mesh, self._tool_color(), poses[-1])
            self.links["tool"] = h
            self.nodes.append(h)
        self.tcp_frame = s.scene.add_frame("/tcp", axes_length=0.08, axes_radius=0.004)
        place(self.tcp_frame, wb.tcp_pose())
        self.nodes.append(self.tcp_frame)
        self.update()

    def clear(self) -> None:
        """Remove every node (before a project is replaced)."""
        for h in self.nodes:
            h.remove()
        self.nodes.clear()
        self.links.clear()
        self.bodies.clear()
        self.show_plan(None)
        self.gizmo = None  # the jog panel's, removed with it

    def show_plan(self, samples: SampledMotion | None) -> None:
        """Draw the TCP path through a motion plan's samples, red where it collides (None:
        remove it); the gizmo follows this motion's playback."""
        if self.path_node is not None:
            self.path_node.remove()
            self.path_node = None
        self.plan_samples = samples
        if samples is None or samples.tcp is None or len(samples.times) < 2:
            return
        tcp = np.asarray(samples.tcp, float)
        p = tcp[:, :3, 3] if tcp.ndim == 3 else tcp
        segments = np.stack([p[:-1], p[1:]], axis=1).astype(np.float32)  # (N - 1, 2, 3)
        hit = np.asarray(samples.colliding, bool)[:-1]
        colors = np.where(hit[:, None, None], COLLISION_COLOR, PATH_COLOR)
        self.path_node = self.server.scene.add_line_segments(
            "/motion/tcp_path",
            segments,
            np.broadcast_to(colors, segments.shape).astype(np.uint8),
            thickness=4.0,
            thickness_units="screen",
        )

    def update(self) -> None:
        """Move the robot to the workbench's joints and colour colliding bodies red."""
        self.show(None)

    def show(self, q: NDArray[np.float64] | None) -> None:
        """Pose the robot at joints `q` [rad] (None: the workbench's own), red where it collides."""
        wb = self.wb
        poses = wb.link_poses(q)
        report = wb.collision_status(q)
        hit = report.colliding_bodies()
        with self.server.atomic():
            for i, name in enumerate(wb.checker.link_names):
                h = self.links[name]
                place(h, poses[i])
                h.color = COLLISION_COLOR if name in hit else ROBOT_COLOR
            if "tool" in self.links:
                h = self.links["tool"]
                place(h, poses[-1])
                h.color = COLLISION_COLOR if "tool" in hit else self._tool_color()
            place(self.tcp_frame, wb.tcp_pose(q))
            self._place_gizmo(q)
        for listener in self.on_show:
            listener(q)

    def place_bodies(self, poses: Mapping[str, NDArray[np.float64]]) -> None:
        """Move the drawn cell bodies named in `poses` to their world poses (4, 4) [m] (the
        press's ram and back-gauge during a bending cycle); names not drawn are skipped."""
        with self.server.atomic():
            for name, T in poses.items():
                h = self.bodies.get(name)
                if h is not None:
                    place(h, T)

    def park_bodies(self) -> None:
        """Put every drawn cell body back at its pose in the project."""
        self.place_bodies({b.name: b.T_world_body for b in self.wb.cell if b.name in self.bodies})

    def _place_gizmo(self, q: NDArray[np.float64] | None) -> None:
        g = self.gizmo
        if g is None:
            return
        playing_plan = (
            self.plan_samples is not None
            and self.timeline is not None
            and self.timeline.motion is self.plan_samples
        )
        visible = q is None or playing_plan
        if q is not None and visible:
            place(g, self.wb.tcp_pose(q))
        if g.visible != visible:
            g.visible = visible

    def _tool_color(self) -> tuple[int, int, int]:
        r, g, b = self.wb.project.tool.color
        return (r, g, b)


class CameraViews:
    """The "View" buttons (Fit, Front, Top, Side, Iso) and the camera fit of each page.

    The box comes from the service (`service.scene_bounds`); only the camera placement, a
    display matter, is computed here. Each page (client) has its own camera."""

    def __init__(self, server: viser.ViserServer, wb: Workbench) -> None:
        self.server, self.wb = server, wb
        self.buttons = server.gui.add_button_group("View", options=("Fit", *VIEWS))
        self.buttons.on_click(guarded(server, "View")(self._on_click))
        server.on_client_connect(self._on_connect)

    def _on_connect(self, client: viser.ClientHandle) -> None:
        try:
            self.frame(client)
        except Exception:  # the default camera is still a view; say why in the log
            log.warning("camera fit on connect failed:\n%s", traceback.format_exc())

    def frame(
        self,
        client: viser.ClientHandle,
        focus: str = "all",
        direction: tuple[float, float, float] | None = None,
    ) -> None:
        """Point `client`'s camera at the scene's `focus` box (default: everything), from
        `direction` (default: the camera's own, iso before it has one)."""
        box = scene_bounds(self.wb, focus)
        cam = client.camera
        if direction is None:
            try:  # keep the user's viewing direction when fitting
                d = np.asarray(cam.position, float) - np.asarray(cam.look_at, float)
                direction = tuple(d) if np.linalg.norm(d) > 1e-6 else VIEWS["Iso"]  # type: ignore[assignment]
            except AssertionError:  # the client has not reported its camera yet
                direction = VIEWS["Iso"]
        try:
            fov, aspect = float(cam.fov) or DEFAULT_FOV, float(cam.aspect) or 16 / 9
        except (AssertionError, ZeroDivisionError):
            fov, aspect = DEFAULT_FOV, 16 / 9
        position, look_at = camera_pose(box.lo, box.hi, direction, fov, aspect)  # type: ignore[arg-type]
        with client.atomic():
            cam.up_direction = (0.0, 0.0, 1.0)
            # viser's position setter moves look_at along with the camera: set look_at last
            cam.position = position
            cam.look_at = look_at

    def frame_bending(self, client: viser.ClientHandle | None) -> None:
        """Point `client`'s camera at the die and the part, from the robot's side and above
        (the press brake's upper tool stands behind the bend line, not between)."""
        if client is None:
            return
        R_world_die = self.wb.bending.si().die.T_world_die[:3, :3]
        direction = R_world_die @ np.array([0.35, -1.0, 0.7])  # die frame: robot on -y
        self.frame(client, "bending", tuple(direction))  # type: ignore[arg-type]

    def frame_all(self, focus: str = "all") -> None:
        """Frame `focus` on every page (after a project is loaded)."""
        for client in list(self.server.get_clients().values()):
            self.frame(client, focus, VIEWS["Iso"])

    def _on_click(self, event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        choice = str(self.buttons.value)
        self.frame(event.client, "all", None if choice == "Fit" else VIEWS[choice])

    def remove(self) -> None:
        """Remove the buttons."""
        self.buttons.remove()
