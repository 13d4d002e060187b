"""Export formats, and `export`: one planned motion as the text of a robot program or of its joint samples."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.motion.program import Program
from workbench.motion.programs.fanuc import to_ls
from workbench.motion.programs.krl import to_krl
from workbench.motion.programs.rapid import to_rapid
from workbench.motion.programs.samples import csv_text, json_text
from workbench.motion.programs.urscript import to_urscript

#: Export formats and the file extension each is written with.
EXPORT_FORMATS = {
    "rapid": ".mod",
    "krl": ".src",
    "ls": ".ls",
    "urscript": ".script",
    "csv": ".csv",
    "json": ".json",
}
_POSTS = {"rapid": to_rapid, "krl": to_krl, "ls": to_ls, "urscript": to_urscript}


def export(
    fmt: str, program: Program, times: NDArray[np.float64], joints: NDArray[np.float64]
) -> str:
    """Return `program` as `fmt` text: rapid, krl, ls or urscript from its moves; csv or json
    from the timed joint samples `times` (N,) [s], `joints` (N, dof) [rad].

    Raises InputError naming the format and the formats there are.
    """
    if fmt not in EXPORT_FORMATS:
        raise InputError(f"format: {fmt!r} is not one of {', '.join(EXPORT_FORMATS)}")
    if fmt == "csv":
        return csv_text(times, joints)
    if fmt == "json":
        return json_text(times, joints)
    return str(_POSTS[fmt](program))
