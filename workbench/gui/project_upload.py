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

import io
import os
import posixpath
import re
import stat
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from workbench.errors import InputError
from workbench.gui import uploads
from workbench.gui.server_guard import max_upload_bytes
from workbench.service.project_files import named_files, parse_project

MAX_MEMBERS = 2000  # files in an uploaded zip
_PART = re.compile(r"[^\x00-\x1f\x7f/\\:]+")


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


def _member_path(info: zipfile.ZipInfo) -> str:
    name = info.filename.replace("\\", "/")
    parts = [p for p in name.split("/") if p not in ("", ".")]
    if name.startswith("/") or ".." in parts or not parts:
        raise InputError(f"upload: the zip member {info.filename!r} leaves the zip's folder")
    if not all(_PART.fullmatch(p) for p in parts) or any(len(p) > 200 for p in parts):
        raise InputError(f"upload: the zip member {info.filename!r} has an unusable name")
    mode = info.external_attr >> 16
    if stat.S_ISLNK(mode):
        raise InputError(f"upload: the zip member {info.filename!r} is a symlink; zip the file")
    return "/".join(parts)


def stage_zip(name: str, content: bytes) -> Staged:
    """Unpack an uploaded .zip of a project and its files; InputError/ProjectError if unusable.

    The project is the .json file nearest the zip's top that is a project (part files and
    other JSON deeper down are its files).
    """
    try:
        archive = zipfile.ZipFile(io.BytesIO(content))
    except zipfile.BadZipFile:
        raise InputError(f"upload: {name} is not a zip file") from None
    members = [i for i in archive.infolist() if not i.is_dir()]
    if len(members) > MAX_MEMBERS:
        raise InputError(f"upload: {name} holds {len(members)} files, at most {MAX_MEMBERS}")
    limit = max_upload_bytes()
    if sum(i.file_size for i in members) > limit:
        raise InputError(
            f"upload: {name} unpacks to more than the upload limit of {limit >> 20} MB;"
            " raise it with WORKBENCH_MAX_MESH_BYTES=BYTES"
        )
    paths = [_member_path(i) for i in members]
    jsons = sorted((p.count("/"), p) for p in paths if p.lower().endswith(".json"))
    if not jsons:
        raise InputError(f"upload: {name} holds no project .json file")
    top = [p for d, p in jsons if d == jsons[0][0]]
    root = new_folder()
    try:
        for info, rel in zip(members, paths, strict=True):
            target = root / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            with archive.open(info) as src:
                data = src.read(limit + 1)
            if len(data) > info.file_size:  # the zip lied about a size
                raise InputError(f"upload: {name}: {rel} is larger than the zip says")
            target.write_bytes(data)
        if len(top) > 1:
            shown = ", ".join(top)
            raise InputError(f"upload: {name} holds several project files ({shown}); keep one")
        json_path = root / top[0]
        project = parse_project(json_path.read_bytes(), source=f"{name}:{top[0]}")
        rels = [p for _, p in named_files(project)]
        return Staged(root, json_path, project.name, _missing(rels, json_path.parent, root))
    except BaseException:
        remove_folder(root)
        raise
