"""The one path rule: a file a project names lies inside the project's folder or an allowed one.

Every reader of a project path (cell, tool, link and part meshes, the URDF and the meshes it
names, `bending.part_file`, the polishing workpiece) asks `ProjectFolders.resolve` for it:

- relative paths are taken from the project's folder; absolute ones are accepted only inside
  an allowed folder;
- the path is resolved with its symlinks, then must lie inside the project's folder, a folder
  allowed at start (`workbench serve --allow-dir`, `Workbench.open(..., allowed_dirs=[...])`)
  or the workbench's own `web_assets/`; otherwise an `InputError` names the field and the fix,
  with the same words whether or not the file exists;
- only regular files are read (no folders, devices or pipes), at most `size_limit(kind)` bytes.

The size limits are settings (environment variables, in bytes), listed in docs/security.md.
"""

from __future__ import annotations

import os
import re
import stat
import sys
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from workbench.env_setting import env_value
from workbench.errors import InputError, MeshError, ProjectError, WorkbenchError

PathArg = str | os.PathLike[str]

# The workbench's bundled meshes (parts, workpieces): the example projects name them. In a
# checkout or an editable install they lie beside the package; a wheel or `pip install .` puts
# them under <prefix>/share/workbench (pyproject.toml's data-files, beside the examples).
BUNDLED_ASSETS = Path(__file__).resolve().parents[2] / "web_assets"
INSTALLED_ASSETS = Path(sys.prefix) / "share" / "workbench" / "web_assets"

MiB = 1 << 20
# kind -> (environment variable, default bytes)
SIZE_LIMITS: dict[str, tuple[str, int]] = {
    "project": ("WORKBENCH_MAX_PROJECT_BYTES", 16 * MiB),
    "part": ("WORKBENCH_MAX_PART_FILE_BYTES", 4 * MiB),
    "urdf": ("WORKBENCH_MAX_URDF_BYTES", 8 * MiB),
    "mesh": ("WORKBENCH_MAX_MESH_BYTES", 200 * MiB),
    "program": ("WORKBENCH_MAX_PROGRAM_BYTES", 4 * MiB),
}


# kind -> what a missing file of that kind raises, and its message
_FIX = "fix the path (relative to the project file)"
_MISSING: dict[str, tuple[type[WorkbenchError], str]] = {
    "project": (ProjectError, "{where}: no such file"),
    "part": (ProjectError, "{where}: cannot read {shown}: no such file; " + _FIX),
    "urdf": (ProjectError, "{where}: file not found: {shown}; " + _FIX),
    "mesh": (MeshError, "{where}: mesh file not found: {shown}; " + _FIX),
    "program": (InputError, "{where}: no such file"),
}


def shown_path(path: object) -> str:
    """Return how a message names project path `path`: as given when relative, only its file
    name when absolute, so no message the browser shows tells the server's folders."""
    text = os.fspath(path) if isinstance(path, str | os.PathLike) else str(path)
    return os.path.basename(text) if os.path.isabs(text) or text.startswith("~") else text


def size_limit(kind: str) -> int:
    """Return the largest file of `kind` ('project', 'part', 'urdf', 'mesh') read [bytes]."""
    env, default = SIZE_LIMITS[kind]
    value = env_value(env, default, int, "a whole number of bytes")
    if value <= 0:
        raise InputError(f"{env}: {value} must be a positive number of bytes")
    return value


def _mb(n: int) -> str:
    return f"{n / MiB:.1f} MB"


def read_regular_file(path: PathArg, *, kind: str, field: str, shown: str | None = None) -> bytes:
    """Return the bytes of the regular file `path`, refusing other kinds and oversized files.

    The file is opened without following a FIFO's block (O_NONBLOCK) and checked on the open
    descriptor, so what is checked is what is read. `field` names the input in errors, `shown`
    the file (default: `path` as it is).
    """
    limit = size_limit(kind)
    name = os.fspath(path)
    shown = name if shown is None else shown
    where = field if field == name else f"{field} ({shown})"
    try:
        fd = os.open(name, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        cls, message = _MISSING[kind]
        raise cls(message.format(where=field, shown=shown)) from None
    except OSError as exc:
        raise InputError(f"cannot read ({exc.strerror})", field=where) from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise InputError(
                "not a regular file (a folder, device or pipe); give a file", field=where
            )
        if st.st_size > limit:
            raise InputError(_too_big(where, st.st_size, kind, limit))
        chunks, total = [], 0
        while True:
            chunk = os.read(fd, min(1 << 20, limit + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > limit:  # the file grew while being read
                raise InputError(_too_big(where, total, kind, limit))
        return b"".join(chunks)
    except OSError as exc:
        raise InputError(f"cannot read ({exc.strerror})", field=where) from None
    finally:
        os.close(fd)


def _too_big(where: str, size: int, kind: str, limit: int) -> str:
    env = SIZE_LIMITS[kind][0]
    return (
        f"{where}: over {_mb(size)}, larger than the {kind} file limit of {_mb(limit)};"
        f" simplify the file, or raise the limit with {env}=BYTES"
    )


@dataclass(frozen=True)
class ProjectFolders:
    """The project's folder and the folders allowed beside it; `os.fspath` gives `base`.

    `allowed` are given at start (`--allow-dir`, `allowed_dirs=`) and hold for the project
    once saved; `session` are allowed for this run only (the GUI's upload folders): a save
    copies what the project needs from them beside it (`service.project_save`)."""

    base: Path
    allowed: tuple[Path, ...] = field(default=())
    session: tuple[Path, ...] = field(default=())

    def __init__(
        self,
        base: PathArg | None = None,
        allowed: Iterable[PathArg] = (),
        session: Iterable[PathArg] = (),
    ) -> None:
        object.__setattr__(self, "base", Path(base) if base is not None else Path.cwd())
        object.__setattr__(self, "allowed", tuple(Path(a) for a in allowed))
        object.__setattr__(self, "session", tuple(Path(a) for a in session))

    @classmethod
    def of(cls, where: ProjectFolders | PathArg | None) -> ProjectFolders:
        """Return `where` as folders: a `ProjectFolders` as is, a path as the project's folder."""
        return where if isinstance(where, ProjectFolders) else cls(where)

    def __fspath__(self) -> str:
        return os.fspath(self.base)

    def with_allowed(self, *folders: PathArg) -> ProjectFolders:
        """Return these folders with `folders` allowed too (for good: see the class doc)."""
        return ProjectFolders(self.base, (*self.allowed, *folders), self.session)

    def with_session(self, *folders: PathArg) -> ProjectFolders:
        """Return these folders with `folders` allowed for this run only (uploads)."""
        return ProjectFolders(self.base, self.allowed, (*self.session, *folders))

    def moved_to(self, base: PathArg) -> ProjectFolders:
        """Return these folders for the project's file in folder `base` (the others kept)."""
        return ProjectFolders(base, self.allowed, self.session)

    def without(self, folder: PathArg) -> ProjectFolders:
        """Return these folders with `folder` no longer allowed."""
        gone = os.path.realpath(folder)

        def keep(folders: tuple[Path, ...]) -> list[Path]:
            return [a for a in folders if os.path.realpath(a) != gone]

        return ProjectFolders(self.base, keep(self.allowed), keep(self.session))

    def roots(self) -> list[Path]:
        """Return every folder a project path may resolve into, symlinks resolved."""
        out = [Path(os.path.realpath(self.base))]
        out += [Path(os.path.realpath(a)) for a in (*self.allowed, *self.session)]
        out += [Path(os.path.realpath(a)) for a in (BUNDLED_ASSETS, INSTALLED_ASSETS) if a.is_dir()]
        return out

    def resolve(self, path: object, field: str) -> Path:
        """Return the real path of project path `path`; InputError naming `field` if it leaves.

        The refusal reads the same whether or not the file exists.
        """
        if not isinstance(path, str | os.PathLike):
            raise InputError(f"expected a file path (text), got {type(path).__name__}", field=field)
        text = os.fspath(path)
        if not text or "\x00" in text:
            raise InputError(f"{text!r} is not a file path; give a relative path", field=field)
        p = Path(text).expanduser() if text.startswith("~") else Path(text)
        candidate = p if p.is_absolute() else Path(self.base) / p
        real = Path(os.path.realpath(candidate))
        if not any(real == r or real.is_relative_to(r) for r in self.roots()):
            raise InputError(
                f"{text!r} lies outside the project's folder and the allowed folders;"
                " put the file in the project's folder and give a path relative to the project"
                " file, or allow its folder (workbench serve --allow-dir DIR;"
                " Workbench.open(path, allowed_dirs=[DIR]))",
                field=field,
            )
        return real

    def read(self, path: object, field: str, *, kind: str) -> tuple[Path, bytes]:
        """Return the real path and the bytes of project path `path` (see `resolve`)."""
        real = self.check_file(path, field, kind=kind)
        # Name the path as the project gave it, not where its symlinks lead.
        shown = repr(shown_path(path))
        return real, read_regular_file(real, kind=kind, field=field, shown=shown)

    def check_file(self, path: object, field: str, *, kind: str) -> Path:
        """Return the real path of `path` after checking it is a regular file within the limit.

        For files another library reads by name (pinocchio's URDF, the polishing workpiece).
        """
        real = self.resolve(path, field)
        shown = repr(shown_path(path))
        try:
            st = os.stat(real)
        except OSError:
            cls, message = _MISSING[kind]
            raise cls(message.format(where=field, shown=shown)) from None
        if not stat.S_ISREG(st.st_mode):
            raise InputError(
                f"{shown} is not a regular file (a folder, device or pipe); give a file",
                field=field,
            )
        if st.st_size > size_limit(kind):
            raise InputError(_too_big(f"{field} ({shown})", st.st_size, kind, size_limit(kind)))
        return real

    def check_urdf(self, path: object, field: str) -> Path:
        """Return the URDF's real path after checking it and every mesh it names by the rule.

        Mesh names: relative (to the URDF's folder), absolute, ``file://`` or
        ``package://pkg/rest`` (looked up as ``pkg/rest`` and ``rest`` beside the URDF).
        """
        real = self.check_file(path, field, kind="urdf")
        data = read_regular_file(real, kind="urdf", field=field)
        if b"<!ENTITY" in data or b"<!DOCTYPE" in data:
            raise InputError("the URDF declares a DOCTYPE or entities; remove them", field=field)
        try:
            root = ET.fromstring(data)
        except ET.ParseError as exc:
            raise InputError(f"the URDF is not valid XML ({exc})", field=field) from None
        here = real.parent
        for i, mesh in enumerate(root.iter("mesh")):
            name = mesh.get("filename", "")
            where = f"{field} (mesh {i + 1}: {name!r})"
            for candidate in _urdf_mesh_candidates(name, here):
                self.check_file(candidate, where, kind="mesh")
        return real


def _urdf_mesh_candidates(name: str, here: Path) -> list[str]:
    if name.startswith("package://"):
        rest = name[len("package://") :]
        pkg_rest = str(here / rest)
        tail = str(here / rest.partition("/")[2]) if "/" in rest else pkg_rest
        found = [c for c in (pkg_rest, tail) if os.path.lexists(c)]
        return found or [pkg_rest]
    name = re.sub(r"^file://", "", name)
    return [name if os.path.isabs(name) else str(here / name)]
