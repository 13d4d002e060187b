"""DHRobot: a serial arm given by standard DH rows and joint limits (FK, IK, Jacobian, singularities)."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, UnreachableError
from workbench.kinematics import presets
from workbench.kinematics.dh_chain import (
    as_finite_array,
    dh_fk,
    dh_frames,
    dh_frames_one,
    joint_array,
    transform_array,
    validate_dh,
)
from workbench.kinematics.ik_report import unreachable_reason
from workbench.kinematics.joint_convention import JointConvention, model_convention
from workbench.kinematics.joint_turns import all_turns, joint_turn, turns_scalar
from workbench.kinematics.link_shapes import dh_link_meshes
from workbench.kinematics.numeric_ik import numeric_ik
from workbench.kinematics.opw import opw_geometry, solve_batch
from workbench.kinematics.opw_single import solve_single
from workbench.kinematics.pinocchio_dh import build_dh_model
from workbench.kinematics.singularity import Singularities, arm_singularities
from workbench.kinematics.ur_ik import ur_geometry, ur_solutions

FloatArray = NDArray[np.float64]
IK_TOL = 1e-9
"""Largest accepted deviation of fk(solution) from the target: m for position, unitless for R."""
_CHUNK = 2048  # poses per vectorised IK chunk
_LAST_ROW = [0.0, 0.0, 0.0, 1.0]


def _rate(value: ArrayLike | None, default: FloatArray, name: str, unit: str) -> FloatArray:
    if value is None:
        return np.array(default, dtype=float)
    try:
        arr = np.broadcast_to(np.asarray(value, dtype=float), default.shape)
    except (TypeError, ValueError) as exc:
        raise InputError(
            f"{name}: expected a number or {default.shape[0]} numbers [{unit}], got {value!r}"
        ) from exc
    arr = as_finite_array(arr, name, (None,))
    if np.any(arr <= 0.0):
        raise InputError(f"{name}: every entry must be > 0 [{unit}], got {arr.tolist()}")
    return arr


class DHRobot:
    """A serial arm of revolute joints, standard DH ``A_i = Rz(q_i + offset) Tz(d) Tx(a) Rx(alpha)``.

    dh: (n, 4) rows [theta_offset rad, d m, a m, alpha rad]; limits: (n, 2) [lower, upper] rad.
    max_velocity [rad/s], max_acceleration [rad/s^2], max_jerk [rad/s^3]: (n,) or scalars;
    defaults: pi rad/s, velocity / 0.25 s, acceleration / 0.05 s. Joint values and limits are
    the model's; `convention` relates them to the controller's (identity unless given).
    Arms of the OPW family (offset shoulder, parallel shoulder-elbow axes, spherical wrist)
    get the analytic IK; others a numeric one (pinocchio CLIK from several seeds).
    """

    def __init__(
        self,
        dh: ArrayLike,
        limits: ArrayLike,
        *,
        name: str = "robot",
        max_velocity: ArrayLike | None = None,
        max_acceleration: ArrayLike | None = None,
        max_jerk: ArrayLike | None = None,
        convention: JointConvention | None = None,
        controller_limits: ArrayLike | None = None,
    ) -> None:
        self.dh, self.limits = validate_dh(dh, limits)
        if not isinstance(name, str) or not name:
            raise InputError(f"name: expected a non-empty string, got {name!r}")
        self.name = name
        self.dof = int(self.dh.shape[0])
        n = self.dof
        self.convention = model_convention(convention, n)
        self.controller_limits = self._controller_limits(controller_limits)
        self.max_velocity = _rate(
            max_velocity, np.full(n, presets.DEFAULT_MAX_VELOCITY), "max_velocity", "rad/s"
        )
        self.max_acceleration = _rate(
            max_acceleration,
            self.max_velocity / presets.ACCELERATION_TIME,
            "max_acceleration",
            "rad/s^2",
        )
        self.max_jerk = _rate(
            max_jerk, self.max_acceleration / presets.JERK_TIME, "max_jerk", "rad/s^3"
        )
        self.opw = opw_geometry(self.dh)
        self.ur = ur_geometry(self.dh) if self.opw is None else None
        self._pin: tuple[pin.Model, pin.Data] | None = None
        self._flange_id = -1
        self._lo = self.limits[:, 0].tolist()
        self._hi = self.limits[:, 1].tolist()
        self._off = self.dh[:, 0].tolist()
        self._specs = [
            (o, lo, hi, lo >= -math.pi and hi <= math.pi)
            for o, lo, hi in zip(self._off, self._lo, self._hi, strict=False)
        ]
        self._zeros = np.zeros(n)
        self._zeros.flags.writeable = False

    def _controller_limits(self, value: ArrayLike | None) -> FloatArray | None:
        """Return the controller's limits (n, 2) [rad] when they are not the model box's image."""
        if value is None:
            return None
        lim = as_finite_array(value, "controller_limits", (self.dof, 2))
        if np.any(lim[:, 0] >= lim[:, 1]):
            raise InputError("controller_limits: every row needs lower < upper [rad]")
        lim.flags.writeable = False
        return lim

    def within_limits(self, q: ArrayLike, tol: float = 0.0) -> NDArray[np.bool_]:
        """Return whether joints (..., n) [rad] lie within the limits: the model's box and,
        where a coupled convention makes it slanted, the controller's (`controller_limits`)."""
        qa = joint_array(q, self.dof)
        ok = np.all((qa >= self.limits[:, 0] - tol) & (qa <= self.limits[:, 1] + tol), axis=-1)
        if self.controller_limits is not None:
            ok &= self.convention.within_controller_limits(qa, self.controller_limits, tol)
        return np.asarray(ok)

    @property
    def is_analytic(self) -> bool:
        """Return True when `ik` uses the closed-form OPW solver."""
        return self.opw is not None

    def __repr__(self) -> str:
        return f"DHRobot(name={self.name!r}, dof={self.dof}, analytic_ik={self.is_analytic})"

    # -- forward kinematics -------------------------------------------------------------
    def fk(self, q: ArrayLike) -> FloatArray:
        """Return base -> flange transforms (..., 4, 4) [m] for joint values q (..., n) [rad]."""
        if isinstance(q, np.ndarray) and q.shape == (self.dof,) and q.dtype == np.float64:
            # One configuration: pinocchio's C++ FK (~1 us) beats numpy's per-call overhead.
            if math.isfinite(sum(q.tolist())):
                model, data = self.pinocchio_model()
                pin.forwardKinematics(model, data, q)
                return pin.updateFramePlacement(model, data, self._flange_id).homogeneous
        return dh_fk(self.dh, joint_array(q, self.dof))

    def link_transforms(self, q: ArrayLike) -> FloatArray:
        """Return base -> DH frame i (..., n+1, 4, 4) for i = 0..n; frame n is the flange."""
        if isinstance(q, np.ndarray) and q.dtype == np.float64 and q.size == self.dof:
            # One configuration ((n,) or (1, n)): the chain in scalar math (~10 us, not ~0.2 ms).
            vals = q.reshape(-1).tolist()
            if q.ndim <= 2 and q.shape[-1] == self.dof and math.isfinite(sum(vals)):
                frames = dh_frames_one(self.dh.tolist(), vals)
                return frames[None] if q.ndim == 2 else frames
        return dh_frames(self.dh, joint_array(q, self.dof))

    def link_meshes(self) -> list[trimesh.Trimesh]:
        """Return n+1 convex link shapes [m] generated from the DH lengths, mesh i in frame i."""
        return dh_link_meshes(self.dh, self.limits)

    # -- inverse kinematics -------------------------------------------------------------
    def ik(self, T: ArrayLike, *, q_near: ArrayLike | None = None) -> FloatArray:
        """Return IK solutions (k, n) [rad], k <= 8, each within limits with fk(row) == T.

        T: (4, 4) base -> flange [m]. Joints spanning more than 360 deg take the turn nearest
        q_near (or 0). Rows are sorted by distance to q_near when given, else by branch
        (shoulder, elbow, wrist). Raises UnreachableError saying why when there is none.
        """
        T_arr, T_rows = self._single_pose(T)
        ref = self._ref(q_near)
        if self.opw is None:
            if self.ur is not None:
                return self._ur(T_arr, ref, q_near is not None)
            return self._numeric(T_arr, ref, q_near is not None)
        ref_l = ref.tolist()
        specs = self._specs
        rows: list[list[float]] = []
        sols = solve_single(self.opw, T_rows, ref_l[3] + self._off[3], distinct=True)
        for i in range(0, len(sols), 2):  # (no flip, flip) pairs share joints 1-3
            if not sols[i][6] < IK_TOL:
                continue
            arm = turns_scalar(sols[i], specs, ref_l, 0, 3)
            if arm is None:
                continue
            for sol in (sols[i], sols[i + 1]):
                wrist = turns_scalar(sol, specs, ref_l, 3, 6)
                if wrist is not None:
                    rows.append(arm + wrist)
        if rows and self.controller_limits is not None:
            rows = [r for r, ok in zip(rows, self.within_limits(np.array(rows)), strict=True) if ok]
        if not rows:
            raise UnreachableError(unreachable_reason(self, T_arr))
        out = np.array(rows)
        if q_near is not None:
            out = out[np.argsort(np.linalg.norm(out - ref, axis=1), kind="stable")]
        return out

    def ik_all(self, T: ArrayLike, *, q_near: ArrayLike | None = None) -> FloatArray:
        """Return `ik` solutions plus every +-360 deg turn variant the limits allow (k, n) [rad]."""
        base = self.ik(T, q_near=q_near)
        rows = np.concatenate([all_turns(r, self.limits) for r in base], axis=0)
        ref = self._ref(q_near)
        return rows[np.argsort(np.linalg.norm(rows - ref, axis=1), kind="stable")]

    def ik_batch(
        self, Ts: ArrayLike, *, q_near: ArrayLike | None = None
    ) -> tuple[FloatArray, NDArray[np.bool_]]:
        """Return (solutions (N, 8, n) [rad], valid (N, 8)) for poses Ts (N, 4, 4), vectorised.

        Branch b = 4 * shoulder + 2 * elbow + wrist; rows of missing branches are NaN.
        q_near: (n,) or (N, n) picks the turn of wide joints. Analytic (OPW) robots only.
        """
        if self.opw is None:
            raise InputError(
                f"ik_batch: robot {self.name!r} is not of the OPW family (offset shoulder, "
                "parallel axes 2-3, spherical wrist); call ik() per pose for its numeric IK"
            )
        T_arr = transform_array(Ts, "Ts")
        if T_arr.ndim != 3:
            raise InputError(f"Ts: expected shape (N, 4, 4), got {T_arr.shape}")
        N = T_arr.shape[0]
        ref = np.zeros((N, self.dof))
        if q_near is not None:
            qn = joint_array(q_near, self.dof, "q_near")
            if qn.shape not in ((self.dof,), (N, self.dof)):
                raise InputError(
                    f"q_near: expected shape ({self.dof},) or ({N}, {self.dof}), got {qn.shape}"
                )
            ref = np.broadcast_to(qn, (N, self.dof))
        off, lo, hi = self._off, self._lo, self._hi
        q = np.empty((N, 8, self.dof))
        valid = np.empty((N, 8), dtype=bool)
        # Chunks keep the temporaries in cache (and below malloc's mmap threshold): ~20 % faster.
        for start in range(0, N, _CHUNK):
            sl = slice(start, start + _CHUNK)
            ref_t = np.ascontiguousarray(ref[sl].T)

            def to_joint(
                j: int, theta: FloatArray, ref_t: FloatArray = ref_t
            ) -> tuple[FloatArray, NDArray[np.bool_]]:
                return joint_turn(theta - off[j], lo[j], hi[j], ref_t[j])

            q[sl], err = solve_batch(self.opw, T_arr[sl], ref_t[3] + off[3], to_joint)
            valid[sl] = err < IK_TOL
        if self.controller_limits is not None:
            valid &= self.within_limits(np.nan_to_num(q))
        q[~valid] = np.nan
        return q, valid

    def _numeric(self, T: FloatArray, ref: FloatArray, sort: bool) -> FloatArray:
        model, data = self.pinocchio_model()
        rng = np.random.default_rng(0)
        lo, hi = self.limits[:, 0], self.limits[:, 1]
        seeds = np.vstack(
            [ref, np.clip(0.0, lo, hi), 0.5 * (lo + hi), rng.uniform(lo, hi, (12, self.dof))]
        )
        sols = numeric_ik(model, data, model.getFrameId("flange"), T, seeds)
        if len(sols):
            dev = np.abs(self.fk(sols) - T).max(axis=(1, 2))
            sols = sols[(dev < 1e-8) & self.within_limits(sols)]
        if not len(sols):
            raise UnreachableError(unreachable_reason(self, T))
        return sols[np.argsort(np.linalg.norm(sols - ref, axis=1), kind="stable")] if sort else sols

    def _ur(self, T: FloatArray, ref: FloatArray, sort: bool) -> FloatArray:
        assert self.ur is not None
        cand = ur_solutions(self.ur, T, float(ref[5]))
        rows: list[list[float]] = []
        ref_l = ref.tolist()
        if len(cand):
            dev = np.abs(dh_fk(self.dh, cand - self.dh[:, 0]) - T).max(axis=(1, 2))
            for sol in cand[dev < IK_TOL]:
                q = turns_scalar(tuple(sol.tolist()), self._specs, ref_l, 0, self.dof)
                if q is not None and not any(np.allclose(q, r, atol=1e-9) for r in rows):
                    rows.append(q)
        if rows and self.controller_limits is not None:
            rows = [r for r, ok in zip(rows, self.within_limits(np.array(rows)), strict=True) if ok]
        if not rows:
            raise UnreachableError(unreachable_reason(self, T))
        out = np.array(rows)
        return out[np.argsort(np.linalg.norm(out - ref, axis=1), kind="stable")] if sort else out

    def _single_pose(self, T: ArrayLike) -> tuple[FloatArray, list[list[float]]]:
        """Return (T (4, 4), its rows as lists) after scalar checks (numpy calls cost ~us each)."""
        try:
            T_arr = np.asarray(T, dtype=float)
        except (TypeError, ValueError):
            transform_array(T)  # raises the InputError
            raise
        if T_arr.shape != (4, 4):
            raise InputError(f"T: expected one (4, 4) transform, got shape {T_arr.shape}")
        rows = T_arr.tolist()
        (a, b, c, x), (d, e, f, y), (g, h, i, z), last = rows
        ok = math.isfinite(a + b + c + x + d + e + f + y + g + h + i + z) and last == _LAST_ROW
        if ok:
            dots = (
                a * a + d * d + g * g - 1.0,
                b * b + e * e + h * h - 1.0,
                c * c + f * f + i * i - 1.0,
                a * b + d * e + g * h,
                a * c + d * f + g * i,
                b * c + e * f + h * i,
            )
            det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
            ok = max(dots) < 1e-6 and min(dots) > -1e-6 and det > 0.0  # det < 0: a reflection
        if not ok:
            transform_array(T_arr)  # raises the InputError with details
        return T_arr, rows

    def _ref(self, q_near: ArrayLike | None) -> FloatArray:
        if q_near is None:
            return self._zeros
        return joint_array(q_near, self.dof, "q_near").reshape(self.dof)

    # -- pinocchio twin, Jacobian, singularities ----------------------------------------
    def pinocchio_model(self) -> tuple[pin.Model, pin.Data]:
        """Return (pin.Model, pin.Data) built from the same DH rows; frames "link_i" and "flange"."""
        if self._pin is None:
            model = build_dh_model(self.dh, self.limits, self.max_velocity)
            self._pin = (model, model.createData())
            self._flange_id = model.getFrameId("flange")
        return self._pin

    def jacobian(self, q: ArrayLike) -> FloatArray:
        """Return the flange Jacobian (6, n): rows [v m/s; omega rad/s], LOCAL_WORLD_ALIGNED."""
        qa = joint_array(q, self.dof).reshape(-1)
        if qa.shape != (self.dof,):
            raise InputError(f"q: expected shape ({self.dof},), got {np.shape(q)}")
        model, data = self.pinocchio_model()
        fid = model.getFrameId("flange")
        return np.array(pin.computeFrameJacobian(model, data, qa, fid, pin.LOCAL_WORLD_ALIGNED))

    def singularities(
        self, q: ArrayLike, margin: float = math.radians(5.0), shoulder_margin: float = 0.05
    ) -> Singularities:
        """Return which of wrist, elbow, shoulder singularities apply at q (n,) [rad].

        margin [rad]: wrist (joint-4 vs joint-6 axis) and elbow (stretched/folded) angles below
        it count; shoulder_margin [m]: wrist-centre distance below it counts. 6R arms only.
        """
        if self.dof != 6:
            raise InputError(f"singularities: defined for 6-joint arms, this robot has {self.dof}")
        if not (margin >= 0.0 and shoulder_margin >= 0.0):
            raise InputError(
                f"margin, shoulder_margin: expected >= 0, got {margin}, {shoulder_margin}"
            )
        frames = self.link_transforms(q)
        if frames.shape != (7, 4, 4):
            raise InputError(f"q: expected shape (6,), got {np.shape(q)}")
        return arm_singularities(frames, self.jacobian(q), margin, shoulder_margin)
