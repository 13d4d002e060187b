"""The GUI's one job at a time: plans, sweeps, builds and project loads, shown on every page.

Every page of a server follows one session (one `Workbench`), so two long jobs at once would
fight over it, and a project load during a plan would remove the plan's widgets under it.
`Jobs` is the registry every Plan button (through `progress.busy`) and every project load or
rebuild goes through:

- `jobs.job("planning motion")` runs a block as the session's job; while it runs, any other
  job (from any page, any tab) is refused with `Busy` ("busy: planning motion ..."), which the
  callbacks' `guarded` wrapper shows as a notification. The same thread may nest jobs (a load
  rebuilds the tabs).
- Inside a GUI callback (`notify.guarded` enters `callback_scope`) the job is kept until the
  callback returns, so what the callback does after its long part (showing the result,
  loading the timeline) still happens before another job may replace the project.
- The banner (`attach`) shows the running job and its progress on every page.

Jobs run in viser's callback threads (one per event), so the event loop and other callbacks
(a jog) keep being served while a plan runs.
"""

from __future__ import annotations

import threading
import time
import weakref
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from workbench.errors import WorkbenchError

_scope = threading.local()  # .depth: guarded callbacks entered; .held: jobs kept until exit


class Busy(WorkbenchError):
    """Another job of the session is running; the message names it and says to wait."""


class Jobs:
    """The running job of one server's session (at most one); see the module doc."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._owner: int | None = None  # thread id holding the job
        self._depth = 0
        self.what: str | None = None  # e.g. "planning motion"
        self.started = 0.0
        self.fraction = 0.0
        self.message = ""
        self._banner: Any = None  # a GuiMarkdownHandle
        self._shown = 0.0

    # -- state ----------------------------------------------------------------------------
    @property
    def running(self) -> str | None:
        """Return what the running job does (e.g. "planning motion"), or None when idle."""
        return self.what

    def attach(self, banner: Any) -> None:
        """Show the running job in `banner` (a markdown handle seen by every page)."""
        self._banner = banner
        self._show(force=True)

    def progress(self, fraction: float, message: str) -> None:
        """Record the running job's progress (shown in the banner, a few times a second)."""
        self.fraction, self.message = float(fraction), message
        self._show()

    def _show(self, *, force: bool = False) -> None:
        banner = self._banner
        if banner is None:
            return
        now = time.monotonic()
        if not force and now - self._shown < 0.25:
            return
        self._shown = now
        if self.what is None:
            text = ""
        else:
            tail = f": {self.message}" if self.message else ""
            text = f"**Busy: {self.what}** ({100 * self.fraction:.0f} %{tail})"
        try:
            banner.content = text
            banner.visible = bool(text)
        except Exception:  # the banner went with its server: nothing to show it on
            self._banner = None

    # -- running --------------------------------------------------------------------------
    def _refusal(self, what: str) -> Busy:
        since = time.monotonic() - self.started
        return Busy(
            f"busy: {self.what} (for {since:.0f} s); {what} waits until it ends:"
            " try again then (every page shares this session)"
        )

    def acquire(self, what: str) -> bool:
        """Start job `what` for this thread; Busy when another runs. True if newly started."""
        me = threading.get_ident()
        if self._owner == me:
            self._depth += 1
            return False
        if not self._lock.acquire(blocking=False):
            raise self._refusal(what)
        self._owner, self._depth = me, 1
        self.what, self.started, self.fraction, self.message = what, time.monotonic(), 0.0, ""
        self._show(force=True)
        return True

    def release(self) -> None:
        """End one level of this thread's job (the job ends with its outermost level)."""
        if self._owner != threading.get_ident():
            return
        self._depth -= 1
        if self._depth > 0:
            return
        if getattr(_scope, "depth", 0) > 0:  # inside a callback: kept until it returns
            _scope.held.append(self)
            self._depth = 1
            return
        self._finish()

    def _finish(self) -> None:
        self._owner, self._depth, self.what, self.message = None, 0, None, ""
        self._lock.release()
        self._show(force=True)

    @contextmanager
    def job(self, what: str) -> Iterator[None]:
        """Run the block as the session's job `what`; Busy (nothing done) if another runs."""
        self.acquire(what)
        try:
            yield
        finally:
            self.release()


@contextmanager
def callback_scope() -> Iterator[None]:
    """Keep the jobs a GUI callback starts until the callback returns (`notify.guarded`)."""
    if not hasattr(_scope, "depth"):
        _scope.depth, _scope.held = 0, []
    _scope.depth += 1
    try:
        yield
    finally:
        _scope.depth -= 1
        if _scope.depth == 0:
            held, _scope.held = _scope.held, []
            for jobs in held:
                if jobs._owner == threading.get_ident():
                    jobs._finish()


_BY_SERVER: weakref.WeakKeyDictionary[Any, Jobs] = weakref.WeakKeyDictionary()


def of(server: Any) -> Jobs:
    """Return the job registry of viser server `server` (made on first use)."""
    jobs = _BY_SERVER.get(server)
    if jobs is None:
        jobs = _BY_SERVER.setdefault(server, Jobs())
    return jobs


def of_handle(handle: Any) -> Jobs | None:
    """Return the registry of the server a GUI handle belongs to (None if it cannot be told)."""
    try:
        owner = handle._impl.gui_api._owner  # viser 1.1.1 internals (pinned in the tests)
    except AttributeError:
        return None
    return of(owner) if owner is not None else None
