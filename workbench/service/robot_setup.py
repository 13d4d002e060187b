"""Building the robot, its link meshes and its tool from the project's robot and tool sections."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import ProjectError
from workbench.kinematics.model import RobotModel
from workbench.kinematics.robot_library import preset_robot
from workbench.project.cad import CadSpec, step_tolerance
from workbench.project.models import Robot, RobotSI, Tool, ToolSI
from workbench.project.paths import ProjectFolders
from workbench.project.units import to_deg
from workbench.service.mesh_files import load_mesh_file

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class RobotSetup:
    """A robot ready to use: kinematics, link meshes (base first), tool mesh and frames."""

    model: RobotModel  # DHRobot or URDFRobot
    link_meshes: list[trimesh.Trimesh]
    T_world_base: NDArray[np.float64]
    T_flange_tcp: NDArray[np.float64]
    tool_mesh: trimesh.Trimesh | None
    q0: NDArray[np.float64]


def _per_joint(
    values: NDArray[np.float64] | None, dof: int, field: str
) -> NDArray[np.float64] | None:
    if values is None:
        return None
    if len(values) != dof:
        raise ProjectError(
            f"{field}: expected {dof} values (one per joint), got {len(values)}",
            [(field, f"expected {dof} values")],
        )
    return values


def build_robot_model(spec: Robot | RobotSI, base_dir: Path | ProjectFolders) -> RobotModel:
    """Return the kinematic model (DHRobot or URDFRobot) of the project's robot section."""
    from workbench.kinematics import DHRobot

    if isinstance(spec, Robot):
        spec = spec.to_si()
    if spec.preset is not None:
        return preset_robot(spec.preset)
    if spec.dh is not None and spec.limits is not None:
        return DHRobot(spec.dh, spec.limits, name=spec.name)
    from workbench.kinematics import URDFRobot

    assert spec.urdf is not None
    return URDFRobot.from_file(
        ProjectFolders.of(base_dir).check_urdf(spec.urdf, "robot.urdf"), field="robot.urdf"
    )


def build_tool_mesh(
    tool: ToolSI, base_dir: Path | ProjectFolders, cad: CadSpec | None = None
) -> trimesh.Trimesh | None:
    """Return the tool's mesh in the flange frame [m]: the file (a STEP file tessellated with
    the `cad` tolerances), a box, or a rod to the TCP."""
    if tool.mesh is not None:
        tolerance = step_tolerance(cad)
        return load_mesh_file(
            tool.mesh, base_dir, tool.mesh_scale, "tool.mesh", tolerance=tolerance
        )
    if tool.size is not None:
        ext = tool.size
        box = trimesh.creation.box(extents=ext)
        box.apply_translation([0.0, 0.0, ext[2] / 2])
        return box
    tip = tool.T_flange_tcp[:3, 3]
    length = float(np.linalg.norm(tip))
    if length < 1e-3:
        return None
    # A rod from the flange to the TCP, a little short of it so that touching a part at the
    # TCP is not a collision of the tool.
    rod = trimesh.creation.cylinder(
        radius=0.012, segment=np.stack([np.zeros(3), tip * (1 - 0.01 / length)])
    )
    return rod


def build_robot(
    spec: Robot | RobotSI,
    tool: Tool | ToolSI,
    base_dir: Path | ProjectFolders,
    cad: CadSpec | None = None,
) -> RobotSetup:
    """Return the robot setup for the project's robot and tool sections (SI specs, or the
    sections themselves, converted here); STEP meshes tessellated with the `cad` tolerances."""
    if isinstance(spec, Robot):
        spec = spec.to_si()
    if isinstance(tool, Tool):
        tool = tool.to_si()
    model = build_robot_model(spec, base_dir)
    dof = model.dof
    rates = {
        name: _per_joint(getattr(spec, name), dof, f"robot.{name}")
        for name in ("max_velocity", "max_acceleration", "max_jerk")
    }
    if any(v is not None for v in rates.values()):
        from workbench.kinematics import DHRobot

        if isinstance(model, DHRobot):
            # Through the constructor: it validates the rates and derives the missing ones.
            given = {k: v for k, v in rates.items() if v is not None}
            if "max_velocity" not in given:
                given["max_velocity"] = model.max_velocity
            model = DHRobot(
                model.dh,
                model.limits,
                name=model.name,
                convention=model.convention,
                controller_limits=model.controller_limits,
                **given,
            )
        else:
            for name, values in rates.items():
                if values is not None:
                    setattr(model, name, values)
    meshes = list(model.link_meshes())
    if spec.link_meshes is not None:
        if len(spec.link_meshes) != dof + 1:
            raise ProjectError(
                f"robot.link_meshes: expected {dof + 1} entries (base first, null keeps the"
                f" generated mesh), got {len(spec.link_meshes)}",
                [("robot.link_meshes", f"expected {dof + 1} entries")],
            )
        for i, path in enumerate(spec.link_meshes):
            if path is not None:
                meshes[i] = load_mesh_file(
                    path,
                    base_dir,
                    spec.link_mesh_scale,
                    f"robot.link_meshes[{i}]",
                    tolerance=step_tolerance(cad),
                )
    q0 = _per_joint(spec.joints, dof, "robot.joints")  # model convention (RobotSI)
    if q0 is None:
        q0 = np.clip(np.zeros(dof), model.limits[:, 0], model.limits[:, 1])
    _check_start_joints(model, q0)
    return RobotSetup(
        model=model,
        link_meshes=meshes,
        T_world_base=spec.T_world_base,
        T_flange_tcp=tool.T_flange_tcp,
        tool_mesh=build_tool_mesh(tool, base_dir, cad),
        q0=q0,
    )


def _check_start_joints(model: RobotModel, q0: FloatArray) -> None:
    """Raise ProjectError naming `robot.joints[j]` and the limit it breaks, in the controller's
    values: the controller's own limits first, then the model's box, which a coupled
    convention (FANUC's J3 counted from the horizontal) states as a rule on two joints."""
    from workbench.kinematics import DHRobot

    conv = model.convention  # the message shows the values of the file: controller's
    qc = conv.to_controller(q0)
    own = model.controller_limits if isinstance(model, DHRobot) else None
    if own is not None:
        bad = np.flatnonzero((qc < own[:, 0] - 1e-12) | (qc > own[:, 1] + 1e-12))
        if bad.size:
            _refuse_joint(int(bad[0]), qc, own)
    lo, hi = model.limits[:, 0], model.limits[:, 1]
    bad = np.flatnonzero((q0 < lo - 1e-12) | (q0 > hi + 1e-12))
    if not bad.size:
        return
    j = int(bad[0])
    rule = conv.coupled_rule(j, qc, model.limits)
    if rule is None:
        _refuse_joint(j, qc, conv.limits_to_controller(model.limits))
    text, value, lo_c, hi_c = rule
    msg = (
        f"J{j + 1} = {to_deg(qc[j]):.3f} deg breaks the coupled limit of the controller,"
        f" which counts J{j + 1} from an earlier joint: {text} = {to_deg(value):.3f} deg"
        f" must lie within [{to_deg(lo_c):.3f}, {to_deg(hi_c):.3f}] deg; move J{j + 1}"
        " or the joint it counts from"
    )
    raise ProjectError(f"robot.joints[{j}]: {msg}", [(f"robot.joints[{j}]", msg)])


def _refuse_joint(j: int, qc: FloatArray, lim: FloatArray) -> NoReturn:
    msg = (
        f"{to_deg(qc[j]):.3f} deg is outside the joint limits"
        f" [{to_deg(lim[j, 0]):.3f}, {to_deg(lim[j, 1]):.3f}] deg; move it inside"
    )
    raise ProjectError(f"robot.joints[{j}]: {msg}", [(f"robot.joints[{j}]", msg)])
