"""Typed numbers in the browser: one source of truth per value (the service's state).

viser's number boxes parse on the client (Mantine drops a "," so "12,5" arrives as 125, and
clamps to min/max on blur), so the server cannot refuse what the user meant. A
`NumberField` is a text box instead: the server gets the raw text, parses it strictly (a dot
decimal, finite), hands the value to the service's setter (which validates with the
project's bounds) and then always shows the service's value: a refused value reverts the box
to the value in use and a notification names the field, the allowed range and the unit.
Its optional slider (drag only; its own number box is hidden by `hide_slider_boxes`) goes
through the same setter.

Typed text is committed after a short pause (`COMMIT_DELAY`), so the intermediate texts of
typing ("1", "12", "12.") are not applied one by one.
"""

from __future__ import annotations

import logging
import math
import re
import threading
import traceback
from collections.abc import Callable
from typing import Any

import viser

from workbench.errors import InputError, WorkbenchError
from workbench.gui.notify import notify

log = logging.getLogger("workbench.gui")
COMMIT_DELAY = 0.35  # [s] quiet time after the last keystroke before the text is committed
_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
# The slider's companion number box (Mantine NumberInput next to the track): hidden so a
# typed value goes through the strict text box.
_HIDE_SLIDER_BOXES = (
    "<style>.mantine-Slider-root + .mantine-NumberInput-root,"
    " .mantine-Slider-root ~ div:has(> .mantine-NumberInput-wrapper)"
    " {display: none !important;}</style>"
)


def parse_number(text: str, field: str, *, integer: bool = False) -> float:
    """Return the number `text` spells (a dot decimal, optional exponent, finite).

    Raises InputError naming `field`: a decimal comma ("12,5"), words ("nan", "inf", "abc"),
    an empty box, a number too large for a float, or a fraction where a whole number is due.
    """
    s = text.strip()
    if not s:
        raise InputError(f"{field}: the box is empty; type a number")
    if "," in s and _NUMBER.fullmatch(s.replace(",", ".")):
        raise InputError(
            f"{field}: {text!r} has a decimal comma; type the decimal point as a dot"
            f" ({s.replace(',', '.')})"
        )
    if not _NUMBER.fullmatch(s):
        raise InputError(f"{field}: {text!r} is not a number; type digits, e.g. 12.5")
    v = float(s)
    if not math.isfinite(v):
        raise InputError(f"{field}: {text!r} is too large to be a number")
    if integer and v != int(v):
        raise InputError(f"{field}: {text!r} is not a whole number")
    return v


def format_number(v: float, decimals: int = 3) -> str:
    """Return `v` with at most `decimals` decimals and no trailing zeros ('12.5', '-3', '0')."""
    s = f"{v:.{decimals}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def hide_slider_boxes(server: viser.ViserServer) -> viser.GuiHtmlHandle:
    """Add the page style that hides every slider's number box; returns its handle."""
    return server.gui.add_html(_HIDE_SLIDER_BOXES)


class NumberField:
    """A text box (and optionally a drag slider) that shows and sets one value of the service.

    get() -> the value in use [display unit]; put(v) sets it through the service, raising a
    WorkbenchError when refused; allowed() -> the allowed range as text ('[-170, 170] deg');
    after an accepted change `changed()` updates what depends on the value.

    An optional value (a time limit: none when blank) passes `clear`, called for an empty box
    instead of refusing it; its get() returns None while there is no value (an empty box).
    """

    def __init__(
        self,
        server: viser.ViserServer,
        label: str,
        *,
        get: Callable[[], float | None],
        put: Callable[[float], None],
        allowed: Callable[[], str],
        changed: Callable[[], None] | None = None,
        decimals: int = 3,
        integer: bool = False,
        slider: tuple[float, float, float] | None = None,
        hint: str | None = None,
        delay: float = COMMIT_DELAY,
        clear: Callable[[], None] | None = None,
    ) -> None:
        self.server = server
        self.label = label
        self.get, self.put, self.allowed, self.changed = get, put, allowed, changed
        self.clear = clear
        self.decimals = 0 if integer else decimals
        self.integer = integer
        self.delay = delay
        self._lock = threading.RLock()
        self._timer: threading.Timer | None = None
        self._hint = hint
        text = self._text()
        self.text = server.gui.add_text(label, text, hint=self.hint())
        self.text.on_update(self._on_text)
        self.slider: Any = None
        if slider is not None:
            lo, hi, step = slider
            self.slider = server.gui.add_slider(
                "", min=lo, max=hi, step=step, initial_value=min(max(self._value(), lo), hi)
            )
            self.slider.on_update(self._on_slider)
        self.handles: list[Any] = [self.text] + ([self.slider] if self.slider is not None else [])

    # -- the value in use -> widgets ------------------------------------------------------------
    def _value(self) -> float:
        v = self.get()
        return 0.0 if v is None else float(v)

    def _text(self) -> str:
        v = self.get()
        return "" if v is None else format_number(float(v), self.decimals)

    def hint(self) -> str:
        """Return the box's tooltip: the given hint, or the range allowed now."""
        return self._hint or f"allowed {self.allowed()}"

    def refresh(self) -> None:
        """Show the service's value in the box and on the slider, and the tooltip of the
        range allowed now (it follows the value's range: a planned motion's duration)."""
        with self._lock:
            hint = self.hint()
            if self.text.hint != hint:
                self.text.hint = hint
            text = self._text()
            if self.text.value != text:
                self.text.value = text  # type: ignore[misc]  # event.client None: ignored by _on_text
            if self.slider is not None:
                v = min(max(self._value(), self.slider.min), self.slider.max)
                if abs(float(self.slider.value) - v) > 1e-12:
                    self.slider.value = v  # type: ignore[misc]

    def remove(self) -> None:
        """Remove the widgets and drop a pending commit."""
        with self._lock:
            if self._timer is not None:
                self._timer.cancel()
        for h in self.handles:
            h.remove()

    # -- widgets -> the service ---------------------------------------------------------------
    def _on_text(self, event: Any) -> None:
        if event.client is None:  # our own refresh
            return
        with self._lock:
            if self._timer is not None:
                self._timer.cancel()
            self._timer = threading.Timer(
                self.delay, self._commit_text, args=(str(self.text.value), event.client)
            )
            self._timer.daemon = True
            self._timer.start()

    def _on_slider(self, event: Any) -> None:
        if event.client is None:
            return
        self.commit(float(self.slider.value), event.client)

    def _commit_text(self, text: str, client: Any) -> None:
        with self._lock:
            if str(self.text.value) != text:
                return  # typed on meanwhile: a later commit takes it
            if not text.strip() and self.clear is not None:
                self._apply(self.clear, client)
                return
            try:
                v = parse_number(text, self.label, integer=self.integer)
            except InputError as exc:
                self._refuse(str(exc), client)
                return
            self.commit(v, client)

    def commit(self, v: float, client: Any = None) -> bool:
        """Set `v` through the service; return True when taken. A refusal reverts and notifies."""

        def put() -> None:
            if not math.isfinite(v):
                raise InputError(f"{self.label}: {v!r} is not a number")
            self.put(v)

        return self._apply(put, client)

    def _apply(self, action: Callable[[], None], client: Any) -> bool:
        """Run `action` (a setter); True when taken. A refusal reverts and notifies."""
        with self._lock:
            try:
                action()
            except WorkbenchError as exc:
                self._refuse(str(exc), client)
                return False
            except Exception as exc:  # a bug: revert, tell the user, log the traceback
                log.error("%s failed:\n%s", self.label, traceback.format_exc())
                self._refuse(f"{type(exc).__name__}: {exc}. This is a bug.", client)
                return False
            self.refresh()
        if self.changed is not None:
            try:
                self.changed()
            except WorkbenchError as exc:
                notify(self.server, client, self.label, str(exc))
        return True

    def _refuse(self, message: str, client: Any) -> None:
        self.refresh()
        log.info("%s refused: %s", self.label, message)
        notify(
            self.server,
            client,
            f"{self.label}: refused",
            f"{message.rstrip('.')}. Allowed: {self.allowed()};"
            f" kept {self.text.value or 'the box blank'}.",
        )


def schema_range(model: Any, field: str, unit: str) -> str:
    """Return the range the project file allows for `field` of a pydantic section ('[0.1, 1000] mm').

    Read from the model's JSON schema, which publishes the project's bounds (`Range`). For a
    list field (a pose's `xyz`), the range of its items.
    """
    prop = type(model).model_json_schema()["properties"][field]
    prop = prop.get("items", prop) if prop.get("type") == "array" else prop
    for option in prop.get("anyOf", [prop]):
        if "maximum" in option:
            lo = option.get("minimum", option.get("exclusiveMinimum"))
            left = "[" if "minimum" in option else "("
            return f"{left}{format_number(lo)}, {format_number(option['maximum'])}] {unit}".strip()
    return f"any number {unit}".strip()
