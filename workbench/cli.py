"""The `workbench` command line: serve the GUI, check a project, export programs."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from workbench.errors import WorkbenchError

DEFAULT_PROJECT = Path(__file__).resolve().parent.parent / "projects" / "mz07_cell.json"


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="workbench", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)

    serve = sub.add_parser("serve", help="serve the workbench GUI in the browser")
    serve.add_argument("project", nargs="?", help="project JSON (default: the example MZ07 cell)")
    serve.add_argument("--host", default="127.0.0.1", help="address to bind (default: loopback only)")
    serve.add_argument("--port", type=int, default=8080, help="port (default: 8080)")

    check = sub.add_parser("check", help="validate a project and report the collision status")
    check.add_argument("project", help="project JSON")
    return parser


def _serve(args: argparse.Namespace) -> int:
    from workbench.gui.app import serve

    project = args.project
    if project is None and DEFAULT_PROJECT.is_file():
        project = str(DEFAULT_PROJECT)
    serve(project, host=args.host, port=args.port)
    return 0


def _check(args: argparse.Namespace) -> int:
    from workbench.service import Workbench

    wb = Workbench.open(args.project)
    report = wb.collision_status()
    q = ", ".join(f"{v:.2f}" for v in wb.joints * 180 / 3.141592653589793)
    print(f"{args.project}: valid; robot {wb.project.robot.name} ({wb.robot.dof} joints) at [{q}] deg")
    if report.in_collision:
        pairs = ", ".join(f"{a}–{b}" for a, b in report.colliding)
        print(f"collision: {pairs}")
        return 1
    closest = " – ".join(report.closest_pair) if report.closest_pair else "none"
    print(f"collision-free; clearance {report.min_distance * 1000:.1f} mm ({closest})")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the process exit code."""
    args = _parser().parse_args(argv)
    try:
        if args.command == "serve":
            return _serve(args)
        return _check(args)
    except WorkbenchError as exc:
        first = str(exc).strip().splitlines()
        print(f"workbench {args.command}: error: {first[0]}", file=sys.stderr)
        for line in first[1:]:
            print(line, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
