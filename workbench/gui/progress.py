"""A long job run from a GUI button: buttons disabled, a progress bar and a status line meanwhile.

The job is the session's one job (`workbench/gui/jobs.py`): while it runs every other job and
every project load, from any page, is refused with "busy: <what>"; the banner on every page
shows it and its progress.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any, Protocol

import viser

from workbench.gui import jobs as gui_jobs
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
    what: str | None = None,
    jobs: gui_jobs.Jobs | None = None,
) -> Iterator[Progress]:
    """Yield a `progress(fraction, message)` callback that drives `bar` (and `status`).

    The block runs as the session's job `what` (default: `verb` in lower case) in `jobs`
    (default: the registry of `bar`'s server); `jobs.Busy` is raised, before anything is
    touched, when another job runs. The buttons are disabled and the bar shown for the
    duration of the block; both are restored however the block ends.
    """
    registry = jobs if jobs is not None else gui_jobs.of_handle(bar)
    label = what or verb.lower()
    if registry is not None:
        registry.acquire(label)
    try:
        for b in buttons:
            b.disabled = True
        bar.value = 0.0
        bar.visible = True

        def report(fraction: float, message: str) -> None:
            bar.value = 100.0 * fraction
            if status is not None:
                status.content = f"{verb}: {message}"
            if registry is not None:
                registry.progress(fraction, message)

        try:
            yield report
        finally:
            bar.visible = False
            for b in buttons:
                b.disabled = False
            release_memory()  # a plan frees hundreds of MB in pieces: give them back
    finally:
        if registry is not None:
            registry.release()
