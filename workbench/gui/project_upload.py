"""A project uploaded with its files: a .zip of the JSON and its meshes, or the JSON then each file.

Each upload is unpacked into its own temporary folder (`/tmp/workbench-project-<pid>-*`), where
the project's relative paths are resolved, so an uploaded project reads its own meshes and
never the served project's. The JSON is placed deep enough in that folder that every
relative path it names (even ``../web_assets/x.stl``) lands inside it. While files it names
are missing, the upload waits for them (each later upload whose name matches one is put in
its place); the project loads once none is missing. The folder is removed when the next
project replaces it, when its load fails, and at exit (`uploads.remove_all`).
"""

from __future__ import annotations

import os
import posixpath
from dataclasses import dataclass, field
from pathlib import Path

from workbench.errors import InputError
from workbench.gui import uploads
from workbench.service.project_files import named_files, parse_project
from workbench.service.project_zip import unpack_project_zip


def new_folder() -> Path:
    """Return a fresh upload folder, removed at exit unless removed before."""
    return uploads.new_folder("project")


def remove_folder(folder: Path | None) -> None:
    """Remove an upload folder (nothing when None)."""
    uploads._remove(folder)


def _depth(rel: str) -> int:
    """Return how many folders above its own the relative path `rel` climbs at most."""
    level = top = 0
    for part in rel.replace("\\", "/").split("/"):
        if part == "..":
            level -= 1
            top = min(top, level)
        elif part not in ("", "."):
            level += 1
    return -top


@dataclass
class Staged:
    """A project unpacked in `root`, its JSON at `json_path`, waiting for `missing` files."""

    root: Path
    json_path: Path
    name: str
    missing: dict[str, Path] = field(default_factory=dict)  # project path -> where it goes

    @property
    def ready(self) -> bool:
        """Return True when every file the project names by a relative path is present."""
        return not self.missing

    def describe(self) -> str:
        """Return the markdown that lists the files still missing."""
        names = ", ".join(f"`{k}`" for k in self.missing)
        return (
            f"**{self.name}** waits for {len(self.missing)} file(s): {names}. Upload each"
            " (or a .zip of the project with them) with the button above."
        )

    def wants(self, name: str) -> bool:
        """Return True when an upload called `name` is one of the files still missing."""
        base = uploads.safe_name(name, "file")
        return any(posixpath.basename(k.replace("\\", "/")) == base for k in self.missing)

    def add(self, name: str, content: bytes) -> str:
        """Put an uploaded file where the project expects it; return the project path it fills."""
        base = uploads.safe_name(name, "file")
        hits = [k for k in self.missing if posixpath.basename(k.replace("\\", "/")) == base]
        if not hits:
            wanted = ", ".join(f"`{k}`" for k in self.missing)
            raise InputError(
                f"upload: {base} is not a file the project {self.name} waits for ({wanted});"
                " upload one of those, or a project (.json or .zip) to start again"
            )
        for k in hits:  # the same file named twice fills both places
            target = self.missing.pop(k)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(content)
        return hits[0]


def _missing(project_paths: list[str], json_dir: Path, root: Path) -> dict[str, Path]:
    out: dict[str, Path] = {}
    real_root = Path(os.path.realpath(root))
    for rel in project_paths:
        if os.path.isabs(rel) or rel.startswith("~"):
            continue  # absolute paths: the path rule decides (allowed folders only)
        target = Path(os.path.normpath(json_dir / rel))
        if not Path(os.path.realpath(target)).is_relative_to(real_root):
            continue  # cannot happen with the depth below; the path rule refuses it anyway
        if not target.exists():
            out[rel] = target
    return out


def stage_json(name: str, content: bytes) -> Staged:
    """Unpack an uploaded project JSON into a new folder; ProjectError if it is not a project."""
    project = parse_project(content, source=name)
    rels = [p for _, p in named_files(project)]
    depth = max((_depth(r) for r in rels if not os.path.isabs(r)), default=0)
    root = new_folder()
    try:
        json_dir = root.joinpath(*(["project"] * depth)) if depth else root
        json_dir.mkdir(parents=True, exist_ok=True)
        json_path = json_dir / uploads.safe_name(name, "project.json")
        json_path.write_bytes(content)
        return Staged(root, json_path, project.name, _missing(rels, json_dir, root))
    except BaseException:
        remove_folder(root)
        raise


def stage_zip(name: str, content: bytes) -> Staged:
    """Unpack an uploaded .zip of a project and its files into a new upload folder
    (`service.project_zip`: every member checked first, the project the .json nearest the
    top, a zip lacking a file refused whole); InputError/ProjectError if unusable."""
    root = new_folder()
    try:
        json_path = unpack_project_zip(content, root, source=f"upload: {name}")
        project = parse_project(json_path.read_bytes(), source=name)
        return Staged(root, json_path, project.name, {})
    except BaseException:
        remove_folder(root)
        raise
