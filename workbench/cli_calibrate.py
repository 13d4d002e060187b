"""`workbench calibrate tcp|wobj|base`: a calibration from a readings file, printed, and applied.

The command reads the readings (and known points) CSV, asks `wb.calibration`, prints the
result with its residuals and, with `--apply`, stores it in the project and writes the project
atomically (the project's one save, `Workbench.save`) to `--out` (default: PROJECT itself).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from workbench.cli_options import add_allow_dir
from workbench.errors import InputError
from workbench.project.paths import read_regular_file
from workbench.project.units import MM


def add_parser(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add `calibrate` and its three commands to the command line's subparsers."""
    cal = sub.add_parser(
        "calibrate",
        help="calibrate the tool's TCP, a work object or the robot's base from readings (CSV)",
        description="Readings: CSV with a header, label,j1,...,j6 [deg, as the controller shows"
        " them] or label,x,y,z [mm, in the robot's base]. See docs/calibration.md.",
    )
    what = cal.add_subparsers(dest="calibrate_command", required=True)
    tcp = what.add_parser("tcp", help="the TCP: the tool tip on one fixed point, 4+ orientations")
    wobj = what.add_parser("wobj", help="a work object: 3 points (origin, x, y) or N known points")
    wobj.add_argument("--name", required=True, help="the work object (created if missing)")
    wobj.add_argument(
        "--method",
        default="3point",
        choices=["3point", "fit"],
        help="3point: labels origin, x, y (KUKA, FANUC) or x1, x2, y1 (ABB); fit: --known",
    )
    base = what.add_parser("base", help="the robot's base in the cell from reference points")
    for p in (tcp, wobj, base):
        p.add_argument("project", help="project JSON")
        p.add_argument("readings", help="readings CSV")
        p.add_argument(
            "--apply", action="store_true", help="store the result in the project and write it"
        )
        p.add_argument("--out", help="project JSON to write with --apply (default: PROJECT)")
        add_allow_dir(p)
    for p in (wobj, base):
        p.add_argument(
            "--known",
            required=p is base,
            help="known points CSV label,x,y,z [mm]: in the work object (fit) or the world (base)",
        )
        p.add_argument(
            "--tolerance",
            type=float,
            default=1.0,
            help="residual [mm] above which a point is dropped as an outlier (default 1)",
        )


def _text(path: str) -> str:
    data = read_regular_file(path, kind="program", field=path)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(
            f"not UTF-8 text (byte {exc.start}); save it as CSV (UTF-8)", field=path
        ) from None


def run(args: argparse.Namespace) -> int:
    """Run `workbench calibrate ...`; return the exit code (errors raise WorkbenchError)."""
    from workbench.service import Workbench

    if args.out and not args.apply:
        raise InputError("--out writes the calibrated project: give --apply with it")
    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    readings = _text(args.readings)
    name = Path(args.readings).name
    if args.calibrate_command == "tcp":
        result = wb.calibration.tcp(readings, source=name)
    else:
        known = None if args.known is None else _text(args.known)
        known_name = "known" if args.known is None else Path(args.known).name
        tolerance = args.tolerance * MM
        if args.calibrate_command == "wobj":
            result = wb.calibration.work_object(
                readings,
                name=args.name,
                method=args.method,
                known_csv=known,
                source=name,
                known_source=known_name,
                tolerance=tolerance,
            )
        else:
            result = wb.calibration.base(
                readings,
                known_csv=known or "",
                source=name,
                known_source=known_name,
                tolerance=tolerance,
            )
    print(f"{args.project}: {name}")
    print(result.summary())
    if args.apply:
        wb.calibration.apply(result)
        path = wb.save(args.out or args.project)
        print(f"wrote {path}: {result.kind.replace('_', ' ')} {result.name!r} calibrated")
    return 0
