"""Tests of workbench/motion/program.py: a motion program's moves refuse bad input."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.motion.program import Move, Program


def test_bad_program_inputs():
    with pytest.raises(InputError, match="speed"):
        Move.joint(np.zeros(6), speed=1.5)
    with pytest.raises(InputError, match="zone"):
        Move.joint(np.zeros(6), zone=-0.01)
    with pytest.raises(InputError, match="target"):
        Move.joint(np.zeros(5))
    with pytest.raises(InputError, match="rotation"):
        Move.linear(np.diag([1.0, 1.0, -1.0, 1.0]))
    with pytest.raises(InputError, match="name"):
        Program("2bad name", (Move.joint(np.zeros(6)),))
