"""Post-processors: robot programs (RAPID, KRL, FANUC LS, URScript) and joint samples (CSV, JSON)."""

from __future__ import annotations

from workbench.motion.programs.fanuc import to_ls
from workbench.motion.programs.formats import EXPORT_FORMATS, export
from workbench.motion.programs.krl import to_krl
from workbench.motion.programs.rapid import to_rapid
from workbench.motion.programs.samples import (
    csv_text,
    json_text,
    load_csv,
    load_json,
    save_csv,
    save_json,
)
from workbench.motion.programs.urscript import to_urscript

__all__ = [
    "EXPORT_FORMATS",
    "export",
    "csv_text",
    "json_text",
    "load_csv",
    "load_json",
    "save_csv",
    "save_json",
    "to_krl",
    "to_ls",
    "to_rapid",
    "to_urscript",
]
