"""What a post writes: `ExportedProgram`, the files of a controller program (name -> text) and
the post's notes; a reader takes those files back (`controller_program.ReadProgram`)."""

from __future__ import annotations

import io
import zipfile
from dataclasses import dataclass
from pathlib import Path

from workbench.atomic_file import atomic_write_text
from workbench.errors import InputError


@dataclass(frozen=True)
class ExportedProgram:
    """The files of an exported program (name -> text, in writing order) and the post's notes
    (renamed identifiers, settings that applied), which posts also write as comments."""

    files: dict[str, str]
    notes: tuple[str, ...] = ()

    @property
    def text(self) -> str:
        """Return the one file's text (InputError when the program has several files)."""
        if len(self.files) != 1:
            raise InputError(
                f"this export has {len(self.files)} files ({', '.join(self.files)}); use .files,"
                " write_to(folder) or zip_bytes()"
            )
        return next(iter(self.files.values()))

    def write_to(self, folder: str | Path) -> list[Path]:
        """Write every file into `folder` (created if missing), each atomically; return the paths."""
        root = Path(folder)
        root.mkdir(parents=True, exist_ok=True)
        out = []
        for name, text in self.files.items():
            if Path(name).name != name or name in ("", ".", ".."):
                raise InputError(f"export file name {name!r} must be a plain file name")
            path = root / name
            atomic_write_text(path, text)
            out.append(path)
        return out

    def zip_bytes(self) -> bytes:
        """Return the files as one zip archive."""
        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
            for name, text in self.files.items():
                zf.writestr(name, text)
        return buf.getvalue()


def merge_exports(parts: list[ExportedProgram]) -> ExportedProgram:
    """Return one export holding the files and notes of several (one per robot); names must differ."""
    files: dict[str, str] = {}
    notes: list[str] = []
    for p in parts:
        for name, text in p.files.items():
            if name in files:
                raise InputError(
                    f"two programs write the file {name!r}; give the robots distinct names"
                )
            files[name] = text
        notes.extend(p.notes)
    return ExportedProgram(files, tuple(notes))
