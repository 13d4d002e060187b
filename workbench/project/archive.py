"""A project and its files as one .zip: written with relative member names, read with every
member checked first (docs/security.md, "Project zips").

`write_zip` packs files under the names given (relative, ``/``-separated). `read_zip` returns
the members of an uploaded zip as (name, bytes) and refuses, naming the member and the fix:

- a name that is absolute (``/x``, ``C:/x``), climbs (``..``), is empty, holds a control
  character or a ``:`` or a part over 200 characters, or repeats another member's name;
- a symlink, or an encrypted member;
- more than ``WORKBENCH_MAX_ZIP_MEMBERS`` files, one over the mesh file limit
  (``WORKBENCH_MAX_MESH_BYTES``), more than ``WORKBENCH_MAX_ZIP_BYTES`` unpacked in all, or a
  member over 1 MiB that unpacks to more than ``WORKBENCH_MAX_ZIP_RATIO`` times its packed
  size (a zip bomb).

Sizes are checked on the bytes actually unpacked, not only on what the zip's directory says:
a member that unpacks to more than it declares is refused before the excess is held.
"""

from __future__ import annotations

import io
import re
import stat
import zipfile
from collections.abc import Iterable
from pathlib import Path

from workbench.env_setting import env_value
from workbench.errors import InputError
from workbench.project.paths import MiB, read_regular_file, size_limit

# setting -> (environment variable, default)
ZIP_LIMITS: dict[str, tuple[str, int]] = {
    "members": ("WORKBENCH_MAX_ZIP_MEMBERS", 2000),
    "bytes": ("WORKBENCH_MAX_ZIP_BYTES", 512 * MiB),
    "ratio": ("WORKBENCH_MAX_ZIP_RATIO", 100),
}
RATIO_FLOOR = MiB  # members up to this size may compress as well as they like
_PART = re.compile(r"[^\x00-\x1f\x7f/\\:]{1,200}")
_DATE = (2000, 1, 1, 0, 0, 0)  # every member's time: the same project gives the same bytes


def zip_limit(setting: str) -> int:
    """Return the zip limit `setting` ('members', 'bytes', 'ratio') in effect."""
    env, default = ZIP_LIMITS[setting]
    value = env_value(env, default, int, "a whole number")
    if value <= 0:
        raise InputError(f"{env}: {value} must be positive")
    return value


def write_zip(files: Iterable[tuple[str, Path | bytes]]) -> bytes:
    """Return a .zip of `files`: (member name, a file's path or its bytes), deflated."""
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, content in files:
            data = (
                content
                if isinstance(content, bytes)
                else read_regular_file(content, kind="mesh", field=name)
            )
            info = zipfile.ZipInfo(name, date_time=_DATE)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (stat.S_IFREG | 0o644) << 16
            archive.writestr(info, data)
    return out.getvalue()


def member_name(info: zipfile.ZipInfo, source: str) -> str:
    """Return the member's relative ``/``-separated name; InputError if it is not a plain file
    inside the zip's folder."""
    raw = info.filename
    name = raw.replace("\\", "/")
    parts = [p for p in name.split("/") if p not in ("", ".")]
    where = f"{source}: the member {raw[:120]!r}"
    fix = "zip the project's folder from inside it (relative names, no links)"
    if name.startswith("/") or re.match(r"^[A-Za-z]:", name):
        raise InputError(f"{where} has an absolute name; {fix}")
    if ".." in parts or not parts:
        raise InputError(f"{where} leaves the zip's folder (..); {fix}")
    if not all(_PART.fullmatch(p) for p in parts):
        raise InputError(f"{where} has an unusable name (a control character, ':' or too long)")
    if stat.S_ISLNK(info.external_attr >> 16):
        raise InputError(f"{where} is a symbolic link; {fix}")
    if info.flag_bits & 0x1:
        raise InputError(f"{where} is encrypted; zip it without a password")
    return "/".join(parts)


def read_zip(data: bytes, source: str) -> list[tuple[str, bytes]]:
    """Return the files of the .zip `data` as (relative name, bytes); InputError naming
    `source`, the member and the fix for anything the module docstring refuses."""
    try:
        archive = zipfile.ZipFile(io.BytesIO(data))
        infos = [i for i in archive.infolist() if not i.is_dir()]
    except (zipfile.BadZipFile, ValueError, OSError) as exc:
        raise InputError(f"{source}: not a readable zip file ({exc})") from None
    members = zip_limit("members")
    if len(infos) > members:
        raise InputError(
            f"{source}: holds {len(infos)} files, at most {members}; zip only the project and"
            f" the files it names, or raise {ZIP_LIMITS['members'][0]}"
        )
    names = [member_name(i, source) for i in infos]
    seen: set[str] = set()
    for name in names:
        if name in seen:
            raise InputError(f"{source}: the member {name!r} appears twice; keep one")
        seen.add(name)
    out: list[tuple[str, bytes]] = []
    total = 0
    for info, name in zip(infos, names, strict=True):
        _check_declared(info, name, source)
        body = _read_member(archive, info, name, source)
        total += len(body)
        if total > zip_limit("bytes"):
            raise InputError(_too_much(source, name, "bytes"))
        out.append((name, body))
    return out


def _too_much(source: str, name: str, setting: str) -> str:
    env = ZIP_LIMITS[setting][0]
    if setting == "ratio":
        what = f"unpacks to over {zip_limit('ratio')} times its packed size (a zip bomb?)"
    else:
        what = f"takes the files unpacked over {_size(zip_limit('bytes'))}"
    return f"{source}: the member {name!r} {what}; refused. Raise {env} if the file is genuine"


def _size(n: int) -> str:
    return f"{n / MiB:.1f} MiB" if n >= MiB else f"{n} bytes"


def _check_declared(info: zipfile.ZipInfo, name: str, source: str) -> None:
    limit = size_limit("mesh")
    if info.file_size > limit:
        raise InputError(
            f"{source}: the member {name!r} is {_size(info.file_size)}, over the file limit of"
            f" {_size(limit)}; raise WORKBENCH_MAX_MESH_BYTES if it is genuine"
        )
    if info.file_size > RATIO_FLOOR and info.file_size > zip_limit("ratio") * max(
        info.compress_size, 1
    ):
        raise InputError(_too_much(source, name, "ratio"))


def _read_member(archive: zipfile.ZipFile, info: zipfile.ZipInfo, name: str, source: str) -> bytes:
    """Return the member's bytes, reading at most one byte past what it declares."""
    ratio_cap = max(RATIO_FLOOR, zip_limit("ratio") * max(info.compress_size, 1))
    cap = min(info.file_size, size_limit("mesh"), ratio_cap)
    try:
        with archive.open(info) as src:
            body = src.read(cap + 1)
    except (zipfile.BadZipFile, NotImplementedError, RuntimeError, OSError, EOFError) as exc:
        raise InputError(f"{source}: the member {name!r} cannot be unpacked ({exc})") from None
    except Exception as exc:  # zlib.error and the like: a damaged member
        raise InputError(f"{source}: the member {name!r} is damaged ({exc})") from None
    if len(body) > cap:
        raise InputError(
            f"{source}: the member {name!r} unpacks to more than the zip declares; refused"
        )
    return body
