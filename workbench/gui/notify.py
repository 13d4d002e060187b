"""Error reporting in the browser: every callback's WorkbenchError becomes a notification."""

from __future__ import annotations

import functools
import logging
import re
import traceback
from collections.abc import Callable
from typing import Any, TypeVar

import viser

from workbench.errors import WorkbenchError
from workbench.gui.jobs import callback_scope

log = logging.getLogger("workbench.gui")
F = TypeVar("F", bound=Callable[..., Any])
INFORMING = ("green", "blue")  # notification colours that close by themselves
AUTO_CLOSE_S = 6.0  # [s] how long an informing notification stays
_LINK = re.compile(r"\[([^\]]+)\]\(([^)\s]+)\)")
_BOLD = re.compile(r"\*\*(.+?)\*\*")


def plain_text(text: str) -> str:
    """Return `text` without markdown marks: a notification shows its text as written.

    Bold (`**x**`) and code marks (backticks) are dropped, a link `[x](url)`
    becomes `x (url)`, a line break written as two trailing spaces a plain line break.
    Everything else (a lone asterisk, underscores in a name) is kept.
    """
    out = _LINK.sub(r"\1 (\2)", text)
    out = _BOLD.sub(r"\1", out)
    return out.replace("`", "").replace("  \n", "\n")


def notify(
    server: viser.ViserServer,
    client: viser.ClientHandle | None,
    title: str,
    body: str,
    *,
    color: str = "red",
) -> None:
    """Show a notification to `client`, or to every client when it is None."""
    targets = [client] if client is not None else list(server.get_clients().values())
    for c in targets:
        c.add_notification(
            plain_text(title),
            plain_text(body),
            color=color,
            with_close_button=True,  # type: ignore[call-overload]
            # what informs (green: done, blue: for your information) closes by itself;
            # warnings and errors stay until closed
            auto_close_seconds=AUTO_CLOSE_S if color in INFORMING else None,
        )


def guarded(server: viser.ViserServer, title: str) -> Callable[[F], F]:
    """Return a decorator that turns errors raised by a GUI callback into notifications."""

    def wrap(func: F) -> F:
        @functools.wraps(func)
        def inner(event: Any) -> Any:
            client = getattr(event, "client", None)
            try:
                with callback_scope():  # a job it starts is kept until it returns (jobs.py)
                    return func(event)
            except WorkbenchError as exc:
                log.info("%s: %s", title, exc)
                notify(server, client, title, str(exc))
            except Exception as exc:  # a bug: still tell the user, and log the traceback
                log.error("%s failed:\n%s", title, traceback.format_exc())
                notify(
                    server,
                    client,
                    f"{title}: internal error",
                    f"{type(exc).__name__}: {exc}. This is a bug; the log has the traceback.",
                )
            return None

        return inner  # type: ignore[return-value]

    return wrap
