"""Scene nodes of the robot, its tool and the cell; moved by pose, recoloured on collision."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import trimesh
import viser
from numpy.typing import NDArray

from workbench.geometry.transforms import matrix_to_wxyz
from workbench.service import Workbench

ROBOT_COLOR = (235, 235, 240)
COLLISION_COLOR = (230, 40, 40)


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
        # Called with the joints (None: the workbench's own) after every pose, for what
        # follows the robot (e.g. the collision spheres).
        self.on_show: list[Callable[[NDArray[np.float64] | None], None]] = []
        self.build()

    def build(self) -> None:
        """Create every node for the current project (after `clear`, or the first time)."""
        wb, s = self.wb, self.server
        for body in wb.cell:
            self.nodes.append(
                _add_mesh(s, f"/cell/{body.name}", body.mesh(), body.color, body.T_world_body)
            )
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
        for listener in self.on_show:
            listener(q)

    def _tool_color(self) -> tuple[int, int, int]:
        r, g, b = self.wb.project.tool.color
        return (r, g, b)
