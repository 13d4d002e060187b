"""A CSV text box with its upload button: paste the rows, or upload a file that fills the box.

What the box holds is what the next computation reads: an upload replaces the box's text (the
file must be UTF-8 text of at most `MAX_BYTES`), and the box can be edited after it. A refused
upload leaves the box as it was and says why in a notification naming the box.
"""

from __future__ import annotations

import viser

from workbench.errors import InputError
from workbench.gui.notify import guarded, notify
from workbench.gui.uploads import safe_name

MAX_BYTES = 1_000_000  # a readings file of a few hundred rows is a few kB


def decode_csv(label: str, name: str, content: bytes) -> str:
    """Return an uploaded CSV file's text; raise InputError naming the box `label` and the fix."""
    if len(content) > MAX_BYTES:
        raise InputError(
            f"{name}: {len(content)} bytes; a readings file is a few kB (at most {MAX_BYTES})",
            field=label,
        )
    try:
        text = content.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(
            f"{name} is not UTF-8 text; save it as CSV (UTF-8) and upload it again", field=label
        ) from None
    if "\x00" in text:
        raise InputError(f"{name} is a binary file; upload the CSV text", field=label)
    return text.replace("\r\n", "\n")


class CsvBox:
    """A multiline text box labelled `label` and an "Upload ..." button that fills it."""

    def __init__(self, server: viser.ViserServer, label: str, placeholder: str, hint: str) -> None:
        self.server = server
        self.label = label
        g = server.gui
        self.box = g.add_text(label, initial_value=placeholder, multiline=True, hint=hint)
        self.upload = g.add_upload_button(
            f"Upload {label.split(' (')[0].lower()}",
            icon=viser.Icon.UPLOAD,
            mime_type="text/csv,text/plain,.csv,.txt",
            hint=f"a CSV file; it fills the box '{label}'",
        )
        self.upload.on_upload(guarded(server, label)(self._on_upload))

    @property
    def text(self) -> str:
        """Return the box's text."""
        return str(self.box.value)

    @text.setter
    def text(self, value: str) -> None:
        self.box.value = value  # type: ignore[misc]

    def _on_upload(self, event: viser.GuiEvent) -> None:
        up = self.upload.value
        name = safe_name(up.name, "readings.csv")
        self.text = decode_csv(self.label, name, up.content)
        notify(self.server, event.client, self.label, f"{name} loaded into the box", color="blue")

    def remove(self) -> None:
        """Remove the box and its button."""
        self.box.remove()
        self.upload.remove()
