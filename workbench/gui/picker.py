"""The example projects a server offers, and the picker shown when it starts without a project.

Examples are the `*.json` files of the first `projects/` folder found: beside the package (a
checkout or editable install), under `<prefix>/share/workbench/projects` (a wheel or `pip
install .`: pyproject.toml's data-files), or in the working folder. Their meshes lie in the
`web_assets/` folder beside `projects/`, which is allowed while an example is open.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import viser

from workbench.gui.notify import guarded

PACKAGE = Path(__file__).resolve().parents[1]  # .../workbench


@dataclass(frozen=True)
class Example:
    """An example project: its file, the name it gives itself, the folders it may read."""

    path: Path
    title: str

    @property
    def allowed(self) -> tuple[Path, ...]:
        """Return the folders besides its own that the example's files lie in (web_assets/)."""
        assets = self.path.parent.parent / "web_assets"
        return (assets,) if assets.is_dir() else ()


def example_folders() -> list[Path]:
    """Return the folders that hold example projects, first the one beside the package."""
    candidates = [
        PACKAGE.parent / "projects",
        Path(sys.prefix) / "share" / "workbench" / "projects",
        Path.cwd() / "projects",
    ]
    seen: set[str] = set()
    out = []
    for c in candidates:
        real = os.path.realpath(c)
        if real not in seen and c.is_dir():
            seen.add(real)
            out.append(Path(real))
    return out


def examples() -> list[Example]:
    """Return the example projects of the first example folder, by file name."""
    for folder in example_folders():
        found = []
        for p in sorted(folder.glob("*.json")):
            try:
                title = str(json.loads(p.read_text()).get("name") or p.stem)
            except (OSError, ValueError, AttributeError):
                continue
            found.append(Example(p, title))
        if found:
            return found
    return []


def example_index(found: list[Example], path: Path | None) -> int | None:
    """Return the index in `found` of the example at `path` (the same file, however named),
    or None when `path` is no example of the list (an upload, a saved copy, no file)."""
    if path is None:
        return None
    real = Path(os.path.realpath(path))
    for i, e in enumerate(found):
        if Path(os.path.realpath(e.path)) == real:
            return i
    return None


def is_example(path: Path | None) -> bool:
    """Return True when `path` lies in an example folder (read-only to "Save")."""
    if path is None:
        return False
    real = Path(os.path.realpath(path))
    return any(real.is_relative_to(f) for f in example_folders())


class Picker:
    """Buttons that open each example, and the note that says how to upload a project."""

    def __init__(
        self, server: viser.ViserServer, open_example: Callable[[Example, viser.GuiEvent], None]
    ) -> None:
        g = server.gui
        self.handles: list[object] = []
        self.examples = examples()
        self.intro = g.add_markdown(
            "**Open a project**: pick an example, or upload a project (.json, or a .zip of"
            " the project and its meshes) in the **Project** tab."
            if self.examples
            else "**Open a project**: upload one (.json, or a .zip with its meshes) in the"
            " **Project** tab; no example projects were found."
        )
        self.buttons = []
        for ex in self.examples:
            b = g.add_button(f"Open {ex.title}", hint=str(ex.path))
            b.on_click(guarded(server, "Open example")(lambda e, ex=ex: open_example(ex, e)))
            self.buttons.append(b)

    def remove(self) -> None:
        """Remove the picker's widgets."""
        self.intro.remove()
        for b in self.buttons:
            b.remove()
