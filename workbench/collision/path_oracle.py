"""What the path certifier works with: the engine it asks (`PathOracle`), its nodes and outcome.

`chord_bound` is the certifier's one inequality: along a joint segment an item whose
clearance changes by at most its lever times the travel is clear by at least
``max(a - x, b - (travel - x))`` at travel x from the end a.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
Pair = tuple[str, str]


def chord_bound(a: FloatArray, b: FloatArray, travel: FloatArray) -> FloatArray:
    """Return the least clearance along a joint segment [m] from end bounds a, b and travel.

    Clearance at travel x from a is at least max(a - x, b - (travel - x)); its minimum over
    x in [0, travel] is (a + b - travel) / 2 where |a - b| <= travel, else max(a, b) - travel.
    """
    return np.where(np.abs(a - b) <= travel, (a + b - travel) / 2, np.maximum(a, b) - travel)


class PathOracle(Protocol):
    """What the certifier needs of an engine (see `CollisionEngine`)."""

    dof: int
    item_group: NDArray[np.int64]
    group_start: NDArray[np.int64]
    group_pairs: list[list[Pair]]
    always_pairs: list[Pair]
    pair_lever: dict[Pair, FloatArray]
    margin: float

    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]: ...

    def contained(self, qs: FloatArray) -> NDArray[np.bool_]: ...

    def poses(self, qs: FloatArray) -> FloatArray: ...

    def place(self, poses: FloatArray) -> None: ...

    def aabb_gaps(self, poses: FloatArray) -> FloatArray: ...

    def table_bounds(self, qs: FloatArray, mask: NDArray[np.bool_]) -> FloatArray: ...

    def pair_collides(self, pair: Pair) -> bool: ...

    def pair_distance(self, pair: Pair) -> float: ...


@dataclass
class PathNode:
    t: float
    q: FloatArray
    clr: FloatArray  # (G,) least item clearance per group [m] (the between-samples items)
    gmin: FloatArray  # (G,) least item clearance per group [m]
    poses: FloatArray  # (B, 4, 4) world poses of the moving bodies
    gaps: FloatArray  # (P,) bounding-box gaps of the exact pairs, less the margin [m]
    tab: FloatArray  # (P,) pair-table lower bounds, less the margin [m]; NaN: not looked up
    hits: tuple[Pair, ...] = ()
    dist: dict[tuple[Pair, int], float] = field(default_factory=dict)


@dataclass
class PathOutcome:
    """What the certifier found (SI units); `events` are (time, interval start, q, hits)."""

    sample_hits: dict[int, tuple[Pair, ...]]
    flagged: int
    events: list[tuple[float, int, FloatArray, tuple[Pair, ...]]]
    clearance: float
    evaluated: int
    exact_pairs: int
