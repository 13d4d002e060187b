"""assembly.part_moves: errors of a joint-space part move name the part's field and its robot."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from workbench.assembly import part_moves
from workbench.errors import CollisionError, PlanningError, UnreachableError


@pytest.mark.parametrize("error", [CollisionError, UnreachableError, PlanningError])
def test_a_joint_space_move_names_the_part_field_and_robot_in_its_errors(
    monkeypatch: pytest.MonkeyPatch, error: type[Exception]
) -> None:
    # A flip on the withdrawal is a PlanningError since carry_ik is follow_path (it was an
    # UnreachableError): it keeps naming the part's field, as before.
    def fail(*args: Any, **kwargs: Any) -> None:
        raise error("withdrawal from the start: the configuration flips")

    monkeypatch.setattr(part_moves, "plan_carried_path", fail)
    part = SimpleNamespace(name="screw_0", start=np.eye(4), goal=np.eye(4))
    arm = SimpleNamespace(name="MZ07", q_home=np.zeros(6))
    with pytest.raises(error) as info:
        part_moves.plan_joint_move(None, part, arm, {}, None, "assembly.parts[2]")  # type: ignore[arg-type]
    assert str(info.value) == (
        "assembly.parts[2] (screw_0) carried by MZ07: "
        "withdrawal from the start: the configuration flips"
    )
