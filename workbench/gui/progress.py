"""A long job run from a GUI button: buttons disabled, a progress bar and a status line meanwhile."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any, Protocol

import viser

from workbench.service.memory import release_memory
from workbench.service.motion_plan import Progress


class _Disableable(Protocol):
    disabled: bool


@contextmanager
def busy(
    bar: Any,  # viser's GuiProgressBarHandle, which viser does not export
    buttons: Sequence[_Disableable],
    status: viser.GuiMarkdownHandle | None = None,
    *,
    verb: str = "Planning",
) -> Iterator[Progress]:
    """Yield a `progress(fraction, message)` callback that drives `bar` (and `status`).

    The buttons are disabled and the bar shown for the duration of the block; both are
    restored however the block ends.
    """
    for b in buttons:
        b.disabled = True
    bar.value = 0.0
    bar.visible = True

    def report(fraction: float, message: str) -> None:
        bar.value = 100.0 * fraction
        if status is not None:
            status.content = f"{verb}: {message}"

    try:
        yield report
    finally:
        bar.visible = False
        for b in buttons:
            b.disabled = False
        release_memory()  # a plan frees hundreds of MB in pieces: give them back
