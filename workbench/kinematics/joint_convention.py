"""JointConvention: a controller's joint values against the kinematic model's, per axis.

A robot controller numbers its joints from its own zero (the calibration posture) and in its
own sense of rotation; the kinematic model (a DH table, a URDF) has its own. Per axis,

    q_ctrl = sign * q_model + offset        q_model = sign * (q_ctrl - offset)

with sign +1 or -1 and offset [rad] (prismatic joints: [m]). A controller may also count a
joint relative to an earlier one (FANUC shows J3 as the forearm's angle to the horizontal,
i.e. the model's J2 and J3 together): an optional `coupling` (dof, dof), strictly lower
triangular, adds

    q_ctrl[i] += sum_{j < i} coupling[i, j] * q_model[j]

and `to_model` undoes it by forward substitution, so the two stay exact inverses (to
rounding). With a coupling, a box of controller limits is not a box of model values:
`limits_to_model` returns the smallest model box that holds it (a superset), and
`within_controller_limits` is the exact test (see `limits_to_model`).

`flip_sign` says which sign of the controller's J5 its vendor calls a flipped wrist: -1 (ABB
"axis 5 negative", KUKA Status bit 2 "A5 < 0", and NACHI as this workbench writes it), +1 for
FANUC, whose J5 turns the other way (J5 = -90 deg points the flange down in its usual
posture, "N U T"). Everything inside the domain
works in the model's values; what a person or a controller sees (project file, GUI, exported
programs) is in the controller's. Robots without a preset convention carry the identity.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

FloatArray = NDArray[np.float64]


def _vector(value: ArrayLike, name: str) -> FloatArray:
    try:
        arr = np.array(value, dtype=float).reshape(-1)
    except (TypeError, ValueError) as exc:
        raise InputError(f"JointConvention.{name}: expected numbers, got {value!r}") from exc
    if arr.size == 0 or not np.all(np.isfinite(arr)):
        raise InputError(
            f"JointConvention.{name}: expected one finite number per joint, got {arr.tolist()}"
        )
    arr.flags.writeable = False
    return arr


@dataclass(frozen=True, eq=False)
class JointConvention:
    """Controller joint values against the kinematic model's: q_ctrl = sign * q_model + offset."""

    offset: FloatArray  # (dof,) [rad]
    sign: FloatArray  # (dof,) of +1.0 / -1.0
    coupling: FloatArray | None = None  # (dof, dof) strictly lower triangular, or None
    flip_sign: float = -1.0  # the sign of the controller's J5 its vendor calls a flipped wrist

    def __post_init__(self) -> None:
        offset = _vector(self.offset, "offset")
        sign = _vector(self.sign, "sign")
        if offset.shape != sign.shape:
            raise InputError(
                f"JointConvention: offset has {offset.size} entries and sign {sign.size}; "
                "give one of each per joint"
            )
        if not np.all(np.abs(sign) == 1.0):
            raise InputError(
                f"JointConvention.sign: every entry must be +1 or -1, got {sign.tolist()}"
            )
        object.__setattr__(self, "offset", offset)
        object.__setattr__(self, "sign", sign)
        if self.coupling is not None:
            object.__setattr__(self, "coupling", self._checked_coupling(self.coupling))
        if self.flip_sign not in (-1.0, 1.0):
            raise InputError(f"JointConvention.flip_sign: must be +1 or -1, got {self.flip_sign!r}")
        object.__setattr__(self, "flip_sign", float(self.flip_sign))

    def _checked_coupling(self, value: ArrayLike) -> FloatArray | None:
        n = self.offset.size
        try:
            c = np.array(value, dtype=float)
        except (TypeError, ValueError) as exc:
            raise InputError(f"JointConvention.coupling: expected numbers, got {value!r}") from exc
        if c.shape != (n, n) or not np.all(np.isfinite(c)):
            raise InputError(
                f"JointConvention.coupling: expected a finite ({n}, {n}) matrix, got shape"
                f" {c.shape}"
            )
        if np.any(np.triu(c) != 0.0):
            raise InputError(
                "JointConvention.coupling: must be strictly lower triangular (a joint may count"
                " from earlier joints only), got nonzero entries on or above the diagonal"
            )
        if not np.any(c):
            return None
        c.flags.writeable = False
        return c

    @classmethod
    def identity(cls, dof: int = 6) -> JointConvention:
        """Return the convention of a controller that shows the model's own values."""
        if not isinstance(dof, int | np.integer) or dof < 1:
            raise InputError(f"JointConvention.identity: dof must be an integer >= 1, got {dof!r}")
        return cls(offset=np.zeros(int(dof)), sign=np.ones(int(dof)))

    @property
    def dof(self) -> int:
        """Return the number of joints."""
        return int(self.offset.size)

    def _joints(self, q: ArrayLike, what: str) -> FloatArray:
        try:
            arr = np.asarray(q, dtype=float)
        except (TypeError, ValueError) as exc:
            raise InputError(f"{what}: expected numbers, got {q!r}") from exc
        if arr.ndim == 0 or arr.shape[-1] != self.dof:
            raise InputError(f"{what}: expected shape (..., {self.dof}) [rad], got {arr.shape}")
        return arr

    def to_controller(self, q_model: ArrayLike) -> FloatArray:
        """Return the controller's values (..., dof) [rad] of model joints q_model (..., dof)."""
        q = self._joints(q_model, "q_model")
        out = self.sign * q + self.offset
        if self.coupling is not None:
            out = out + q @ self.coupling.T
        return out

    def to_model(self, q_controller: ArrayLike) -> FloatArray:
        """Return the model's values (..., dof) [rad] of controller joints (..., dof)."""
        q = self._joints(q_controller, "q_controller")
        if self.coupling is None:
            return self.sign * (q - self.offset)
        out = np.array(q - self.offset, dtype=float)
        c = self.coupling
        for i in range(self.dof):  # forward substitution: joint i counts from joints j < i
            if np.any(c[i]):
                out[..., i] = out[..., i] - out[..., :i] @ c[i, :i]
            out[..., i] = self.sign[i] * out[..., i]
        return out

    def limits_to_model(self, limits_ctrl: ArrayLike) -> FloatArray:
        """Return model limits (dof, 2) [lo, hi] of controller limits (dof, 2) [lo, hi] [rad].

        A joint of sign -1 swaps its ends, so every row stays sorted lo <= hi. With a
        coupling the controller's box maps to a slanted region: this returns the smallest
        model box holding it (interval arithmetic through the forward substitution), a
        superset; `within_controller_limits` tells whether a model joint vector is inside.
        """
        lim = np.asarray(limits_ctrl, dtype=float)
        if lim.shape != (self.dof, 2):
            raise InputError(
                f"limits: expected shape ({self.dof}, 2) [lo, hi] rad, got {lim.shape}"
            )
        if self.coupling is None:
            ends = self.to_model(lim.T).T  # (dof, 2), each column one end
            return np.sort(ends, axis=1)
        out = np.zeros((self.dof, 2))
        for i in range(self.dof):
            lo, hi = lim[i, 0] - self.offset[i], lim[i, 1] - self.offset[i]
            for j in range(i):
                c = self.coupling[i, j]
                # q_ctrl_i - offset_i - c * q_model_j over q_model_j in [out_j0, out_j1]
                lo, hi = (
                    lo - max(c * out[j, 0], c * out[j, 1]),
                    hi - min(c * out[j, 0], c * out[j, 1]),
                )
            out[i] = np.sort([self.sign[i] * lo, self.sign[i] * hi])
        return out

    def within_controller_limits(
        self, q_model: ArrayLike, limits_ctrl: ArrayLike, tol: float = 0.0
    ) -> NDArray[np.bool_]:
        """Return whether model joints (..., dof) [rad] lie within controller limits (dof, 2)."""
        qc = self.to_controller(q_model)
        lim = np.asarray(limits_ctrl, dtype=float)
        return np.all((qc >= lim[:, 0] - tol) & (qc <= lim[:, 1] + tol), axis=-1)

    def limits_to_controller(self, limits_model: ArrayLike) -> FloatArray:
        """Return controller limits (dof, 2) [lo, hi] of model limits (dof, 2) [rad], sorted."""
        lim = np.asarray(limits_model, dtype=float)
        if lim.shape != (self.dof, 2):
            raise InputError(
                f"limits: expected shape ({self.dof}, 2) [lo, hi] rad, got {lim.shape}"
            )
        if self.coupling is None:
            return np.sort(self.to_controller(lim.T).T, axis=1)
        # interval arithmetic: the controller's range of each joint over the model box
        ends = np.sort(self.sign[:, None] * lim, axis=1) + self.offset[:, None]
        for i in range(self.dof):
            for j in range(i):
                c = self.coupling[i, j] * lim[j]
                ends[i] += [c.min(), c.max()]
        return ends

    def coupled_rule(
        self, i: int, q_controller: ArrayLike, limits_model: ArrayLike
    ) -> tuple[str, float, float, float] | None:
        """Return the rule model limits (dof, 2) [rad] set on controller joint `i` counted from
        earlier joints, as ``(expression, value, lo, hi)``: e.g. FANUC's ``("J3 + J2", 3.82,
        -pi, pi)`` [rad], the sum of the controller's values that must lie in [lo, hi]. None
        for a joint counted on its own (or from a joint that is itself coupled)."""
        if self.coupling is None or not np.any(self.coupling[i]):
            return None
        partners = [j for j in range(i) if self.coupling[i, j] != 0.0]
        if any(np.any(self.coupling[j]) for j in partners):
            return None
        qc = self._joints(q_controller, "q_controller")
        lim = np.asarray(limits_model, dtype=float)
        # q_ctrl_i = s_i q_i + o_i + sum_j c_ij q_j, with q_j = s_j (q_ctrl_j - o_j)
        text, value = f"J{i + 1}", float(qc[i])
        shift = float(self.offset[i])
        for j in partners:
            coef = -float(self.coupling[i, j] * self.sign[j])
            shown = "" if abs(coef) == 1.0 else f"{abs(coef):g}*"
            text += f" {'+' if coef > 0 else '-'} {shown}J{j + 1}"
            value += coef * float(qc[j])
            shift += coef * float(self.offset[j])
        lo, hi = np.sort(self.sign[i] * lim[i]) + shift
        return text, value, float(lo), float(hi)

    @property
    def is_identity(self) -> bool:
        """Return True when controller and model values are the same."""
        return bool(
            np.all(self.offset == 0.0)
            and np.all(self.sign == 1.0)
            and self.coupling is None
            and self.flip_sign == -1.0
        )

    def __repr__(self) -> str:
        deg = np.round(np.degrees(self.offset), 6).tolist()
        extra = "" if self.coupling is None else f", coupling={self.coupling.tolist()}"
        extra += "" if self.flip_sign == -1.0 else f", flip_sign={self.flip_sign}"
        return f"JointConvention(offset_deg={deg}, sign={self.sign.tolist()}{extra})"


def model_convention(convention: JointConvention | None, dof: int) -> JointConvention:
    """Return `convention` checked against a model of dof joints (None: the identity)."""
    if convention is None:
        return JointConvention.identity(dof)
    if not isinstance(convention, JointConvention) or convention.dof != dof:
        raise InputError(
            f"convention: expected a JointConvention of {dof} joints, got {convention!r}"
        )
    return convention
