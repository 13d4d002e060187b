"""`workbench polishing-faces PROJECT`: the faces of the polishing workpiece's STEP solid (index,
surface type, area, centroid, a planar face's normal), the picked ones marked; with `--pick
3,5 --out PROJECT.json` the faces to polish set (`polishing.faces`) and the project saved."""

from __future__ import annotations

import argparse
from typing import Any

from workbench.cli_options import add_allow_dir
from workbench.errors import InputError


def add_parser(sub: Any) -> argparse.ArgumentParser:
    """Add the `polishing-faces` command to the command line's subparsers; return its parser."""
    p: argparse.ArgumentParser = sub.add_parser(
        "polishing-faces",
        help="list the faces of the polishing workpiece's STEP solid; pick the ones to polish",
    )
    p.add_argument("project", help="project JSON with a polishing section on a STEP file")
    p.add_argument("--pick", help="the face indices to polish, e.g. 5 or 3,5 (with --out)")
    p.add_argument("--out", help="the project JSON to write with --pick (may be PROJECT)")
    add_allow_dir(p)
    return p


def _indices(text: str) -> list[int]:
    try:
        return [int(t) for t in text.replace(" ", "").split(",") if t]
    except ValueError:
        raise InputError(
            f"--pick {text!r}: give face indices separated by commas, e.g. 3,5", field="--pick"
        ) from None


def run(args: argparse.Namespace) -> int:
    """Run `workbench polishing-faces`; return the exit code (0; WorkbenchError: the caller's
    one-line refusal, exit 2)."""
    from workbench.service import Workbench

    if bool(args.pick) != bool(args.out):
        raise InputError("--pick and --out go together: the faces to polish and where to save")
    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    if args.pick:
        wb.polishing.set_faces(_indices(args.pick))
    picked = set(wb.project.polishing.faces or ()) if wb.project.polishing else set()
    for face in wb.polishing.faces():
        normal = (
            "" if face.normal is None else " normal ({:.3f}, {:.3f}, {:.3f})".format(*face.normal)
        )
        print(f"{'*' if face.index in picked else ' '} {face.label()}{normal}")
    if args.out:
        print(f"wrote {wb.save(args.out)} (polishing.faces = {sorted(picked)})")
    return 0
