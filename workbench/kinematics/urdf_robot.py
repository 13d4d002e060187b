"""URDFRobot: a serial arm read from a URDF through pinocchio (FK, numeric IK, link meshes)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, MeshError, UnreachableError
from workbench.kinematics import presets
from workbench.kinematics.dh_chain import joint_array, transform_array
from workbench.kinematics.joint_convention import JointConvention, model_convention
from workbench.kinematics.numeric_ik import numeric_ik

FloatArray = NDArray[np.float64]


class URDFRobot:
    """A robot from a URDF: revolute/prismatic joints only, tip = `tip_link` (default: last link).

    Same interface as DHRobot where it makes sense: `dof`, `limits` (n, 2) [rad or m],
    `fk`, `link_transforms` (frame i = body moved by joint i, 0 = base), numeric `ik`,
    `jacobian`, `pinocchio_model`, and `link_meshes` from the URDF's collision (else visual)
    geometry. FK loops over the batch in pinocchio (about 1 us per pose). `convention`
    relates the URDF's joint values to the controller's (identity unless given).
    """

    def __init__(
        self,
        model: pin.Model,
        geometry: pin.GeometryModel | None,
        tip_frame: str,
        *,
        name: str = "robot",
        convention: JointConvention | None = None,
    ) -> None:
        for j in model.joints[1:]:
            if j.nq != 1 or j.nv != 1:
                raise InputError(
                    f"urdf: joint {model.names[j.id]!r} has nq={j.nq}; URDFRobot supports revolute "
                    "and prismatic joints (give continuous joints a <limit>, making them revolute)"
                )
        if not model.existFrame(tip_frame):
            names = [f.name for f in model.frames]
            raise InputError(f"tip_link: {tip_frame!r} is not a link of the URDF; links: {names}")
        self.model = model
        self.data = model.createData()
        self.geometry = geometry
        self.name = name
        self.dof = int(model.nq)
        self.joint_names = list(model.names[1:])
        self.tip_frame = tip_frame
        self._tip = model.getFrameId(tip_frame)
        lo, hi = np.array(model.lowerPositionLimit), np.array(model.upperPositionLimit)
        bad = np.nonzero(~(np.isfinite(lo) & np.isfinite(hi) & (lo < hi)))[0]
        if bad.size:
            j = int(bad[0])
            raise InputError(
                f"urdf: joint {self.joint_names[j]!r} has limits [{lo[j]}, {hi[j]}]; "
                "give it a <limit lower=... upper=...> with lower < upper"
            )
        self.limits = np.column_stack([lo, hi])
        vel = np.array(model.velocityLimit, dtype=float)
        self.max_velocity = np.where(vel > 0, vel, presets.DEFAULT_MAX_VELOCITY)
        self.max_acceleration = self.max_velocity / presets.ACCELERATION_TIME
        self.max_jerk = self.max_acceleration / presets.JERK_TIME
        self.convention = model_convention(convention, self.dof)

    @classmethod
    def from_file(
        cls,
        path: str | Path,
        *,
        tip_link: str | None = None,
        name: str | None = None,
        package_dirs: list[str] | None = None,
        field: str = "path",
    ) -> URDFRobot:
        """Return the robot of a URDF file; raise InputError/MeshError naming what is wrong,
        prefixed with `field` (the caller's name for the file, e.g. "robot.urdf")."""
        p = Path(path)
        if not p.is_file():
            raise InputError(f"URDF file {str(p)!r} does not exist", field=field)
        try:
            model = pin.buildModelFromUrdf(str(p))
        except Exception as exc:  # pinocchio raises plain RuntimeError/ValueError
            raise InputError(f"cannot read URDF {str(p)!r}: {exc}", field=field) from exc
        dirs = [str(p.parent)] + list(package_dirs or [])
        geometry = None
        for kind in (pin.GeometryType.COLLISION, pin.GeometryType.VISUAL):
            try:
                geom = pin.buildGeomFromUrdf(model, str(p), kind, package_dirs=dirs)
            except Exception as exc:
                raise MeshError(
                    f"URDF {str(p)!r} refers to a mesh that cannot be loaded: {exc}", field=field
                ) from exc
            if geom.ngeoms:
                geometry = geom
                break
        if tip_link is None:
            bodies = [f.name for f in model.frames if f.type == pin.FrameType.BODY]
            tip_link = bodies[-1]
        return cls(model, geometry, tip_link, name=name or model.name or p.stem)

    def __repr__(self) -> str:
        return f"URDFRobot(name={self.name!r}, dof={self.dof}, tip={self.tip_frame!r})"

    @property
    def is_analytic(self) -> bool:
        """Return False: a URDF arm gets the numeric IK (`ik` per pose, no `ik_batch`)."""
        return False

    def ik_batch(
        self, Ts: ArrayLike, *, q_near: ArrayLike | None = None
    ) -> tuple[FloatArray, NDArray[np.bool_]]:
        """Raise InputError: the numeric IK has no branches; call `ik` per pose."""
        raise InputError(
            f"ik_batch: robot {self.name!r} (URDF) has no analytic IK; call ik() per pose"
        )

    def pinocchio_model(self) -> tuple[pin.Model, pin.Data]:
        """Return (pin.Model, pin.Data) of the URDF."""
        return self.model, self.data

    def fk(self, q: ArrayLike) -> FloatArray:
        """Return base -> tip transforms (..., 4, 4) [m] for joint values q (..., n)."""
        qa = joint_array(q, self.dof)
        flat = qa.reshape(-1, self.dof)
        out = np.empty((len(flat), 4, 4))
        for k, qk in enumerate(flat):
            pin.forwardKinematics(self.model, self.data, qk)
            out[k] = pin.updateFramePlacement(self.model, self.data, self._tip).homogeneous
        return out.reshape(qa.shape[:-1] + (4, 4))

    def link_transforms(self, q: ArrayLike) -> FloatArray:
        """Return base -> body frames (..., n+1, 4, 4): 0 = base, i = the body moved by joint i."""
        qa = joint_array(q, self.dof)
        flat = qa.reshape(-1, self.dof)
        out = np.empty((len(flat), self.dof + 1, 4, 4))
        for k, qk in enumerate(flat):
            pin.forwardKinematics(self.model, self.data, qk)
            for i in range(self.dof + 1):
                out[k, i] = self.data.oMi[i].homogeneous
        return out.reshape(qa.shape[:-1] + (self.dof + 1, 4, 4))

    def jacobian(self, q: ArrayLike) -> FloatArray:
        """Return the tip Jacobian (6, n): rows [v m/s; omega rad/s], LOCAL_WORLD_ALIGNED."""
        qa = joint_array(q, self.dof).reshape(-1)
        if qa.shape != (self.dof,):
            raise InputError(f"q: expected shape ({self.dof},), got {np.shape(q)}")
        J = pin.computeFrameJacobian(self.model, self.data, qa, self._tip, pin.LOCAL_WORLD_ALIGNED)
        return np.array(J)

    def ik(self, T: ArrayLike, *, q_near: ArrayLike | None = None) -> FloatArray:
        """Return numeric IK solutions (k, n) within limits with fk(row) == T to 1e-8, nearest first."""
        T_arr = transform_array(T)
        if T_arr.shape != (4, 4):
            raise InputError(f"T: expected one (4, 4) transform, got shape {T_arr.shape}")
        lo, hi = self.limits[:, 0], self.limits[:, 1]
        ref = np.clip(0.0, lo, hi) if q_near is None else joint_array(q_near, self.dof, "q_near")
        rng = np.random.default_rng(0)
        seeds = np.vstack([ref, 0.5 * (lo + hi), rng.uniform(lo, hi, (12, self.dof))])
        sols = numeric_ik(self.model, self.data, self._tip, T_arr, seeds)
        if len(sols):
            sols = sols[np.abs(self.fk(sols) - T_arr).max(axis=(1, 2)) < 1e-8]
        if not len(sols):
            dist = float(np.linalg.norm(T_arr[:3, 3])) * 1000.0
            raise UnreachableError(
                f"pose is unreachable: numeric IK (pinocchio CLIK from {len(seeds)} seeds) found no "
                f"solution within the joint limits; the target is {dist:.1f} mm from the base origin"
            )
        return sols[np.argsort(np.linalg.norm(sols - ref, axis=1), kind="stable")]

    def link_meshes(self) -> list[trimesh.Trimesh]:
        """Return n+1 meshes [m] from the URDF geometry, mesh i in body frame i (empty if none)."""
        parts: list[list[trimesh.Trimesh]] = [[] for _ in range(self.dof + 1)]
        if self.geometry is not None:
            for obj in self.geometry.geometryObjects:
                mesh = _geometry_mesh(obj)
                mesh.apply_transform(obj.placement.homogeneous)
                parts[obj.parentJoint].append(mesh)
        out: list[trimesh.Trimesh] = []
        for p in parts:
            merged = trimesh.util.concatenate(p) if p else trimesh.Trimesh()
            out.append(merged if isinstance(merged, trimesh.Trimesh) else trimesh.Trimesh())
        return out


def _geometry_mesh(obj: pin.GeometryObject) -> trimesh.Trimesh:
    """Return a trimesh of one pinocchio geometry object in its own frame [m]."""
    g = obj.geometry
    kind = type(g).__name__
    if kind == "Box":
        return trimesh.creation.box(extents=2.0 * np.asarray(g.halfSide))
    if kind == "Cylinder":
        return trimesh.creation.cylinder(radius=g.radius, height=2.0 * g.halfLength)
    if kind == "Sphere":
        return trimesh.creation.icosphere(radius=g.radius)
    if kind == "Capsule":
        return trimesh.creation.capsule(height=2.0 * g.halfLength, radius=g.radius)
    path = Path(obj.meshPath)
    if not path.is_file():
        raise MeshError(f"urdf: mesh file {str(path)!r} of {obj.name!r} does not exist")
    try:
        mesh = trimesh.load(str(path), force="mesh")
    except Exception as exc:
        raise MeshError(f"urdf: cannot load mesh {str(path)!r} of {obj.name!r}: {exc}") from exc
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise MeshError(f"urdf: mesh {str(path)!r} of {obj.name!r} has no triangles")
    mesh.apply_scale(np.asarray(obj.meshScale, dtype=float))
    return mesh
