"""JointConvention: a controller's joint values against the kinematic model's, per axis.

A robot controller numbers its joints from its own zero (the calibration posture) and in its
own sense of rotation; the kinematic model (a DH table, a URDF) has its own. Per axis,

    q_ctrl = sign * q_model + offset        q_model = sign * (q_ctrl - offset)

with sign +1 or -1 and offset [rad] (prismatic joints: [m]). Everything inside the domain
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
        return self.sign * q + self.offset

    def to_model(self, q_controller: ArrayLike) -> FloatArray:
        """Return the model's values (..., dof) [rad] of controller joints (..., dof)."""
        q = self._joints(q_controller, "q_controller")
        return self.sign * (q - self.offset)

    def limits_to_model(self, limits_ctrl: ArrayLike) -> FloatArray:
        """Return model limits (dof, 2) [lo, hi] of controller limits (dof, 2) [lo, hi] [rad].

        A joint of sign -1 swaps its ends, so every row stays sorted lo <= hi.
        """
        lim = np.asarray(limits_ctrl, dtype=float)
        if lim.shape != (self.dof, 2):
            raise InputError(
                f"limits: expected shape ({self.dof}, 2) [lo, hi] rad, got {lim.shape}"
            )
        ends = self.to_model(lim.T).T  # (dof, 2), each column one end
        return np.sort(ends, axis=1)

    def limits_to_controller(self, limits_model: ArrayLike) -> FloatArray:
        """Return controller limits (dof, 2) [lo, hi] of model limits (dof, 2) [rad], sorted."""
        lim = np.asarray(limits_model, dtype=float)
        if lim.shape != (self.dof, 2):
            raise InputError(
                f"limits: expected shape ({self.dof}, 2) [lo, hi] rad, got {lim.shape}"
            )
        return np.sort(self.to_controller(lim.T).T, axis=1)

    @property
    def is_identity(self) -> bool:
        """Return True when controller and model values are the same."""
        return bool(np.all(self.offset == 0.0) and np.all(self.sign == 1.0))

    def __repr__(self) -> str:
        deg = np.round(np.degrees(self.offset), 6).tolist()
        return f"JointConvention(offset_deg={deg}, sign={self.sign.tolist()})"


def model_convention(convention: JointConvention | None, dof: int) -> JointConvention:
    """Return `convention` checked against a model of dof joints (None: the identity)."""
    if convention is None:
        return JointConvention.identity(dof)
    if not isinstance(convention, JointConvention) or convention.dof != dof:
        raise InputError(
            f"convention: expected a JointConvention of {dof} joints, got {convention!r}"
        )
    return convention
