"""A robot program as data: a start configuration and a list of joint and linear moves."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.pose_check import check_transform

JOINT = "joint"
LINEAR = "linear"


@dataclass(frozen=True)
class Move:
    """One move: a joint move (PTP/MoveJ) to joints [rad] or a linear move (LIN/MoveL) to a pose.

    `target` holds 6 joint angles [rad] for a joint move, or the 16 entries (row-major) of
    T_base_tcp [m] for a linear move. `speed` is a fraction (0, 1] of the joints' maximum
    speed for a joint move and the TCP speed [m/s] for a linear move. `zone` is the blend
    radius [m] around the target; 0 means an exact stop (fine).
    """

    kind: str
    target: tuple[float, ...]
    speed: float
    zone: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        if self.kind not in (JOINT, LINEAR):
            raise InputError(f"Move.kind must be 'joint' or 'linear', got {self.kind!r}")
        n = 6 if self.kind == JOINT else 16
        if len(self.target) != n or not np.all(np.isfinite(self.target)):
            raise InputError(
                f"Move {self.name!r}: target of a {self.kind} move must be {n} finite numbers"
            )
        if (
            not np.isfinite(self.speed)
            or self.speed <= 0
            or (self.kind == JOINT and self.speed > 1)
        ):
            allowed = "(0, 1] (fraction of max joint speed)" if self.kind == JOINT else "> 0 m/s"
            raise InputError(f"Move {self.name!r}: speed {self.speed!r} must be in {allowed}")
        if not np.isfinite(self.zone) or self.zone < 0:
            raise InputError(f"Move {self.name!r}: zone {self.zone!r} must be >= 0 m (0 = fine)")

    @classmethod
    def joint(cls, q: ArrayLike, *, speed: float = 1.0, zone: float = 0.0, name: str = "") -> Move:
        """Return a joint move to joints `q` (6,) [rad]."""
        return cls(
            JOINT, tuple(float(x) for x in np.asarray(q, float).reshape(-1)), speed, zone, name
        )

    @classmethod
    def linear(
        cls, T_base_tcp: ArrayLike, *, speed: float = 0.25, zone: float = 0.0, name: str = ""
    ) -> Move:
        """Return a linear move to the pose `T_base_tcp` (4, 4) [m]."""
        T = check_transform(T_base_tcp, f"Move {name!r}: T_base_tcp")
        return cls(LINEAR, tuple(float(x) for x in T.reshape(-1)), speed, zone, name)

    @property
    def q(self) -> NDArray[np.float64]:
        """Return the joint target (6,) [rad] of a joint move."""
        return np.array(self.target) if self.kind == JOINT else np.full(6, np.nan)

    @property
    def T(self) -> NDArray[np.float64]:
        """Return the pose target T_base_tcp (4, 4) [m] of a linear move."""
        return (
            np.array(self.target).reshape(4, 4) if self.kind == LINEAR else np.full((4, 4), np.nan)
        )


@dataclass(frozen=True)
class Program:
    """A named list of moves; `name` must be a valid identifier on every controller."""

    name: str
    moves: tuple[Move, ...]

    def __post_init__(self) -> None:
        if not self.name.isidentifier() or len(self.name) > 24:
            raise InputError(
                f"Program.name {self.name!r} must be an identifier of at most 24 characters"
            )
        if not self.moves:
            raise InputError("Program.moves is empty; add at least one move")
