"""The timeline's view of a press-brake bending cycle (`BendingCycle`): the part folded as far
as the cycle has bent it, where the cycle holds it, and the press's ram and back-gauge moving.

Every pose and fold step comes from the service (`part_pose_at`, `part_step_at`,
`press_poses_at`); only the redraw of the part's mesh is rationed here, because a new fold
means a new mesh sent to every page while moving bodies is only a pose.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from workbench.gui.scene import place

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp
    from workbench.service.bending import BendingResult

MESH_STEP = 0.01  # [bends] a fold change up to this keeps the mesh drawn
MESH_PERIOD = 0.1  # [s] at most one mesh rebuild this often (playback and scrubbing)


class CycleFollower:
    """`follow(t)` of the shared timeline for a bending cycle (`Timeline.load`).

    `show_fold(step)` draws the part folded to `step` [bends] in `part_frame` (the Bending
    panel's mesh). A fold that changes by more than `MESH_STEP` is redrawn at once, or, within
    `MESH_PERIOD` of the last redraw, once that period is over (with the latest step), so the
    picture always ends at the step of the time shown.
    """

    def __init__(
        self,
        app: WorkbenchApp,
        plan: BendingResult,
        *,
        part_frame: Any,
        show_fold: Callable[[float], None],
    ) -> None:
        self.app, self.plan = app, plan
        self.part_frame = part_frame
        self.show_fold = show_fold
        self._lock = threading.Lock()
        self._shown: float | None = None  # the fold step drawn [bends]
        self._want = 0.0  # the fold step of the time shown [bends]
        self._built = -float("inf")  # time.monotonic() of the last redraw
        self._timer: threading.Timer | None = None
        self._closed = False

    def __call__(self, t: float) -> None:
        """Place the part and the press's moving bodies at time `t` [s] of the cycle."""
        if self._closed:
            return
        svc = self.app.wb.bending
        place(self.part_frame, svc.part_pose_at(self.plan, t))
        self.app.scene.place_bodies(svc.press_poses_at(self.plan, t))
        self._fold(svc.part_step_at(self.plan, t))

    def _fold(self, step: float) -> None:
        with self._lock:
            if self._closed:
                return
            self._want = step
            if self._shown is not None and abs(step - self._shown) <= MESH_STEP:
                return
            wait = self._built + MESH_PERIOD - time.monotonic()
            if wait <= 0:
                self._redraw()
            elif self._timer is None:
                self._timer = threading.Timer(wait, self._flush)
                self._timer.daemon = True
                self._timer.start()

    def _flush(self) -> None:
        with self._lock:
            self._timer = None
            if self._closed:
                return
            if self._shown is None or abs(self._want - self._shown) > MESH_STEP:
                self._redraw()

    def _redraw(self) -> None:
        self.show_fold(self._want)
        self._shown = self._want
        self._built = time.monotonic()

    @property
    def shown_step(self) -> float | None:
        """Return the fold step the drawn mesh has [bends] (None before the first)."""
        return self._shown

    def close(self) -> None:
        """Stop following (the plan was replaced or the panel removed); no redraw after this."""
        with self._lock:
            self._closed = True
            if self._timer is not None:
                self._timer.cancel()
                self._timer = None
