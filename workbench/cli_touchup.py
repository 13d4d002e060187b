"""`workbench touchup PROJECT PROGRAM_FILE...`: a program edited on the controller compared with
the project's (each target's change, the work objects' fitted corrections), and with `--apply
MODE --out PROJECT.json` applied, planned again and saved atomically (the project's save)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from workbench.cli_options import add_allow_dir
from workbench.errors import InputError
from workbench.project.paths import read_regular_file

MODES = ("work_object", "targets", "both")


def add_parser(sub: Any) -> argparse.ArgumentParser:
    """Add the `touchup` command to the command line's subparsers; return its parser."""
    p: argparse.ArgumentParser = sub.add_parser(
        "touchup",
        help="compare a program touched up on the robot with the project's; fit and apply",
    )
    p.add_argument("project", help="project JSON (the program the robot's one was exported from)")
    p.add_argument(
        "program", nargs="+", help="program file(s) read from the robot: .mod, .src with .dat, ..."
    )
    p.add_argument(
        "--format", choices=["rapid", "krl", "ls", "urscript", "nachi"], help="default: by name"
    )
    p.add_argument(
        "--apply",
        choices=MODES,
        help="work_object: fold each shared correction into its work object, targets that do"
        " not fit kept as taught; targets: every moved target as taught; both",
    )
    p.add_argument("--out", help="the project JSON to write with --apply (may be PROJECT)")
    add_allow_dir(p)
    return p


def run(args: argparse.Namespace) -> int:
    """Run `workbench touchup`; return the exit code (0: done, 1: applied but the new plan has
    problems; WorkbenchError: the caller's one-line refusal, exit 2)."""
    from workbench.service import Workbench
    from workbench.service.program_import import program_files

    if args.apply and not args.out:
        raise InputError(
            "--apply needs --out PROJECT.json (the project to write; give PROJECT itself to"
            " replace it)"
        )
    if args.out and not args.apply:
        raise InputError(f"--out {args.out}: nothing to write without --apply {'|'.join(MODES)}")
    if args.out and not Path(args.out).resolve().parent.is_dir():
        raise InputError(f"--out {args.out}: the folder does not exist; create it first")
    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    files: dict[str, str] = {}
    for f in args.program:  # a .zip gives its members
        files.update(program_files(Path(f).name, read_regular_file(f, kind="program", field=f)))
    report = wb.touchup.compare(files, args.format)
    print(report.summary())
    if not args.apply:
        return 0
    wb.touchup.apply(report, mode=args.apply)
    applied = wb.touchup.last_applied
    assert applied is not None
    path = wb.save(args.out)
    print(applied.summary())
    print(f"wrote {path} ({args.apply})")
    if applied.plan is None or not applied.plan.ok:
        print(
            "workbench touchup: warning: the touched-up program's plan has problems (above);"
            " the project was written so you can fix it",
            file=sys.stderr,
        )
        return 1
    return 0
