"""The small test cell the collision tests share: an MZ07 with a box tool facing one block."""

from __future__ import annotations

import copy
from typing import Any

BLOCK = {
    "name": "block",
    "shape": "box",
    "size": [300, 400, 300],
    "pose": {"xyz": [600, 0, 300]},
}


def block_cell(*extra: dict[str, Any]) -> dict[str, Any]:
    """Return a new project dict (mm, deg): the MZ07, its box tool, the block and `extra` objects."""
    return {
        "schema_version": 1,
        "robot": {"preset": "mz07"},
        "tool": {"tcp": {"xyz": [0, 0, 150]}, "size": [60, 80, 120]},
        "cell": {"objects": [copy.deepcopy(BLOCK), *copy.deepcopy(list(extra))]},
    }
