"""The Polishing tab's list of a STEP solid's faces: one checkbox per face with its index,
surface type and area; ticking them sets `polishing.faces` through the service."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import viser

from workbench.errors import WorkbenchError
from workbench.gui.handles import Removable

#: Most faces listed (a part with more is picked with `workbench polishing-faces`).
MAX_LISTED = 80


class FacesChecklist:
    """A folder "Faces to polish" of the workpiece's STEP faces (none for a mesh file).

    `changed()` runs after the service took a new set of faces (the panel shows the new
    surface); a refused set (the service's error) puts the boxes back to the section's."""

    def __init__(
        self,
        server: viser.ViserServer,
        svc: Any,
        guard: Callable[..., Any],
        changed: Callable[[], None],
    ) -> None:
        self.server, self.svc, self.changed = server, svc, changed
        self.guard = guard
        self.folder: Removable | None = None
        self.boxes: dict[int, Any] = {}
        self.note: Removable | None = None
        self.rebuild()

    def rebuild(self) -> None:
        """List the faces of the section's workpiece again (a new file: new faces)."""
        self.remove()
        try:
            faces = self.svc.faces()
        except WorkbenchError:
            return  # a mesh file (or a file that does not load: the panel says why)
        picked = set(self.svc.spec.faces or ())
        g = self.server.gui
        self.folder = g.add_folder("Faces to polish", expand_by_default=True)
        with self.folder:  # type: ignore[attr-defined]
            self.note = g.add_markdown(
                f"{len(faces)} faces; tick the ones to polish (the rest of the solid is an"
                " obstacle)."
                + (f" The first {MAX_LISTED} are listed." if len(faces) > MAX_LISTED else "")
            )
            for face in faces[:MAX_LISTED]:
                box = g.add_checkbox(
                    f"{face.index}: {face.kind}, {face.area:.0f} mm²",
                    initial_value=face.index in picked,
                    hint=face.label(),
                )
                box.on_update(self.guard(self._on_tick))
                self.boxes[face.index] = box

    def _on_tick(self, event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        ticked = [i for i, box in self.boxes.items() if box.value]
        try:
            self.svc.set_faces(ticked or None)
        finally:
            picked = set(self.svc.spec.faces or ())
            for i, box in self.boxes.items():
                box.value = i in picked
        self.changed()

    def remove(self) -> None:
        """Remove the folder and its boxes."""
        for box in self.boxes.values():
            box.remove()
        self.boxes = {}
        for h in (self.note, self.folder):
            if h is not None:
                h.remove()
        self.note = self.folder = None
