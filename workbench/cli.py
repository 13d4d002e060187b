"""The `workbench` command line: serve the GUI, check a project, export programs, calibrate,
touch-ups."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path

from workbench import cli_calibrate, cli_polishing, cli_touchup
from workbench.cli_options import add_allow_dir
from workbench.errors import InputError, ServerError, WorkbenchError
from workbench.project.paths import read_regular_file

DEFAULT_PROJECT = Path(__file__).resolve().parent.parent / "projects" / "mz07_cell.json"


def _files_option(parser: argparse.ArgumentParser) -> None:
    """Add --files: how a saved project names its files elsewhere (`Workbench.save`)."""
    parser.add_argument(
        "--files",
        choices=["rebase", "copy"],
        default="rebase",
        help="saving to another folder: rebase the paths to name the same files (default),"
        " or copy the files beside the saved project",
    )


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="workbench", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)

    serve = sub.add_parser("serve", help="serve the workbench GUI in the browser")
    serve.add_argument("project", nargs="?", help="project JSON (default: the example MZ07 cell)")
    serve.add_argument(
        "--host", default="127.0.0.1", help="address to bind (default: loopback only)"
    )
    serve.add_argument("--port", type=int, default=8080, help="port (default: 8080)")
    serve.add_argument("--token", help="the access token the URL carries (default: a random one)")
    serve.add_argument(
        "--no-token", action="store_true", help="no access token (only with a loopback --host)"
    )
    serve.add_argument(
        "--allow-origin",
        action="append",
        default=[],
        metavar="ORIGIN",
        help="another origin whose pages may connect, e.g. https://cell-pc.example:8443 (repeat)",
    )

    check = sub.add_parser("check", help="validate a project and report the collision status")
    check.add_argument("project", help="project JSON")

    export = sub.add_parser("export", help="plan a workflow of the project and export its programs")
    export.add_argument("project", help="project JSON")
    export.add_argument(
        "--workflow",
        default="motion",
        choices=["motion", "bending", "assembly", "polishing"],
        help="the workflow whose plan is exported (default: motion, the project's program)",
    )
    export.add_argument(
        "--format",
        choices=["rapid", "krl", "ls", "urscript", "nachi", "csv", "json"],
        help="default: the robot's vendor's language (a preset robot); required for DH/URDF robots",
    )
    export.add_argument(
        "--out",
        help="output file (one-file exports), .zip, or folder: DIR/ (a trailing slash) or an"
        " existing folder gets the export's own file names (KRL .src + .dat, one program per"
        " robot), created if missing; default: the export's file names in the current folder",
    )
    export.add_argument(
        "--force",
        action="store_true",
        help="write the program even if the plan collides or breaks a limit (exit 0 once written)",
    )
    export.add_argument(
        "--any-vendor",
        action="store_true",
        help="write a robot program in another vendor's language than the preset robot's",
    )
    imp = sub.add_parser(
        "import", help="read a robot program written elsewhere into the project's program"
    )
    imp.add_argument("project", help="project JSON (the robot, tool and cell the program runs in)")
    imp.add_argument(
        "program", nargs="+", help="program file(s): .mod, .src with its .dat, .ls, ..."
    )
    imp.add_argument(
        "--format",
        choices=["rapid", "krl", "ls", "urscript", "nachi"],
        help="default: by file name",
    )
    imp.add_argument("--out", help="project JSON to write (default: overwrite PROJECT)")
    _files_option(imp)
    sweep = sub.add_parser(
        "sweep", help="search a workflow's plans: bending sequences x grasps x stations"
    )
    sweep.add_argument("workflow", choices=["bending"], help="the search (bending)")
    sweep.add_argument("project", help="project JSON with a bending section and a press")
    sweep.add_argument(
        "--engine",
        default="serial",
        choices=["serial", "ray"],
        help="serial: this process; ray: a local Ray on all cores, or --address (default serial)",
    )
    sweep.add_argument("--address", help="a running Ray cluster, e.g. 127.0.0.1:6379 (ray only)")
    sweep.add_argument(
        "--time-limit", type=float, help="stop after this many seconds with the best found so far"
    )
    sweep.add_argument(
        "--use",
        type=int,
        metavar="RANK",
        help="put the plan of this rank (1 = best) into the project and save it (--out)",
    )
    sweep.add_argument(
        "--out", help="project JSON to write with --use (default: overwrite PROJECT)"
    )
    _files_option(sweep)
    part = sub.add_parser(
        "import-part", help="recognise a bent part (STEP) or flat pattern (DXF) as a part JSON"
    )
    part.add_argument("file", help="a STEP (.step, .stp) of the bent part or a DXF flat pattern")
    part.add_argument("--out", required=True, help="the part JSON to write (mm/deg)")
    part.add_argument("--thickness", type=float, help="sheet thickness [mm] (needed for DXF)")
    part.add_argument("--bend-layer", help="the DXF layer of the bend lines (default BEND)")
    part.add_argument("--inner-radius", type=float, help="inner bend radius [mm]")
    part.add_argument("--k-factor", type=float, help="K for every bend (default: Table 1)")
    part.add_argument("--base", help="the base flange, e.g. F2 (STEP; default: the largest)")
    cli_calibrate.add_parser(sub)
    cli_touchup.add_parser(sub)
    cli_polishing.add_parser(sub)
    cache = sub.add_parser("cache", help="the disk cache of distance fields and sphere fits")
    cache_sub = cache.add_subparsers(dest="cache_command", required=True)
    cache_sub.add_parser(
        "clear", help="remove every cache entry ($WORKBENCH_CACHE, default ~/.cache/workbench)"
    )
    for p in (serve, check, export, imp, sweep):
        add_allow_dir(p)
    return parser


class _Progress:
    """Progress of a long job on stderr: a bar on a terminal, a line per stage in logs."""

    def __init__(self) -> None:
        self.tty = sys.stderr.isatty()
        self.stage = ""

    def __call__(self, fraction: float, message: str) -> None:
        if self.tty:
            print(
                f"\r  [{'#' * int(fraction * 30):<30}] {fraction * 100:5.1f}% {message:<30}",
                end="" if fraction < 1 else "\n",
                file=sys.stderr,
                flush=True,
            )
            return
        stage = message.split(" ")[0]
        if stage != self.stage:
            self.stage = stage
            print(f"  {fraction * 100:5.1f}% {message}", file=sys.stderr, flush=True)


def _export(args: argparse.Namespace) -> int:
    from workbench.atomic_file import atomic_write, atomic_write_text
    from workbench.service import Workbench
    from workbench.service.programs import check_vendor, plan_workflow

    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    fmt = args.format or wb.default_program_format()
    if fmt is None:
        print(
            "workbench export: error: the robot has no vendor (DH rows or a URDF): give"
            " --format (rapid, krl, ls, urscript, nachi, csv, json)",
            file=sys.stderr,
        )
        return 2
    check_vendor(wb, fmt, any_vendor=args.any_vendor)  # before planning: refused early
    folder = _out_folder(args.out)
    if args.out and folder is None and Path(args.out).suffix:  # a file or .zip: folder must exist
        _out_file(args.out)
    args.format = fmt
    plan = plan_workflow(wb, args.workflow, progress=_Progress())
    print(f"{args.project}: {plan.summary()}")
    if not plan.ok and not args.force:
        print(
            "workbench export: error: the plan has problems (above); fix the project, or pass"
            " --force to write it anyway",
            file=sys.stderr,
        )
        return 1
    exported = wb.export_program(args.format, args.workflow, force=True, any_vendor=args.any_vendor)
    out = folder or (Path(args.out) if args.out else Path.cwd())
    if folder is not None:  # DIR/ or an existing folder: the export's own file names in it
        written = [str(p) for p in exported.write_to(folder)]
    elif out.suffix.lower() == ".zip":  # its folder was checked before planning
        data = exported.zip_bytes()
        atomic_write(out, lambda fh: fh.write(data), binary=True)
        written = [f"{out} ({', '.join(exported.files)})"]
    elif len(exported.files) == 1 and args.out:
        atomic_write_text(_out_file(args.out), exported.text)
        written = [str(out)]
    else:
        written = [str(p) for p in exported.write_to(out)]
    for note in exported.notes:
        print(f"note: {note}")
    print(f"wrote {', '.join(written)} ({args.workflow}, {args.format})")
    if not plan.ok:  # --force: written as asked, so the command succeeded
        print(
            "workbench export: warning: the plan has problems (above); written anyway (--force)",
            file=sys.stderr,
        )
    return 0


def _sweep(args: argparse.Namespace) -> int:
    from workbench.pressbrake.bend_eval import grasp_label
    from workbench.service import Workbench

    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    res = wb.bending.find_sequences(
        engine=args.engine, address=args.address, time_limit=args.time_limit, progress=_Progress()
    )
    print(f"{args.project}: {res.stats.describe()}")
    if res.note:
        print(f"note: {res.note}")
    for rank, plan in enumerate(res.plans, 1):
        print(
            f"{rank}. {' '.join(plan.sequence)}: {plan.regrips} regrip(s), {plan.flips} flip(s),"
            f" cycle {plan.cycle_time:.1f} s{' (estimate)' if plan.estimated else ''}"
        )
        for b, g, st, o in zip(
            plan.sequence, plan.grasps, plan.stations, plan.orientations, strict=True
        ):
            print(f"     {b}: grasp {grasp_label(g)}, station {st}, {o}")
    firsts: dict[str, tuple[str, ...]] = {}
    for branch, reason in res.rejected:
        firsts.setdefault(reason, branch)
    print(f"rejected branches: {len(res.rejected)} ({len(firsts)} distinct first reasons)")
    for reason, branch in list(firsts.items())[:12]:
        print(f"  {' '.join(branch)}: {reason}")
    if args.use is not None:
        if not 1 <= args.use <= len(res.plans):
            print(
                f"workbench sweep: error: --use {args.use}: there are {len(res.plans)} plans",
                file=sys.stderr,
            )
            return 2
        wb.bending.use_plan(res.plans[args.use - 1])
        path = wb.save(args.out or args.project, files=args.files)
        print(f"wrote {path}: plan {args.use} ({' '.join(res.plans[args.use - 1].sequence)})")
    return 0 if res.plans else 1


def _import(args: argparse.Namespace) -> int:
    from workbench.service import Workbench

    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    from workbench.service.program_import import program_files

    files: dict[str, str] = {}
    for f in args.program:  # a .zip gives its members
        files.update(program_files(Path(f).name, read_regular_file(f, kind="program", field=f)))
    notes = wb.import_program(files, args.format)
    for note in notes:
        print(f"note: {note}")
    path = wb.save(args.out or args.project, files=args.files)
    moves = len(wb.project.program.moves) if wb.project.program else 0
    print(f"wrote {path}: program {wb.project.program.name} with {moves} items")  # type: ignore[union-attr]
    return 0


def _out_folder(out: str | None) -> Path | None:
    """Return `--out` as the folder to write into when it names one: it ends in a path
    separator (``DIR/``, created with its parents when missing) or is an existing folder;
    None when it names a file (or .zip), or is not given."""
    if not out:
        return None
    if out.endswith(("/", os.sep)) or Path(out).is_dir():
        return Path(out)
    return None


def _out_file(out: str) -> Path:
    """Return `--out` as a path; InputError when its folder does not exist (none is created)."""
    path = Path(out)
    folder = path.parent
    if not folder.is_dir():
        raise InputError(f"--out {out}: the folder {folder} does not exist; create it first")
    return path


def _import_part(args: argparse.Namespace) -> int:
    from workbench.project.part_import import write_part_json

    settings = {
        k: v
        for k, v in (
            ("thickness", args.thickness),
            ("bend_layer", args.bend_layer),
            ("inner_radius", args.inner_radius),
            ("k_factor", args.k_factor),
            ("base", args.base),
        )
        if v is not None
    }
    out = _out_file(args.out)
    data = read_regular_file(args.file, kind="part", field=args.file)
    for line in write_part_json(data, Path(args.file).name, settings, out):
        print(line)
    return 0


def _serve(args: argparse.Namespace) -> int:
    from workbench.gui.app import serve

    project = args.project
    if project is None and DEFAULT_PROJECT.is_file():
        project = str(DEFAULT_PROJECT)
    if args.no_token and args.token:
        raise ServerError("--token and --no-token: give one of them")
    serve(
        project,
        host=args.host,
        port=args.port,
        token=args.token,
        no_token=args.no_token,
        allowed_origins=args.allow_origin,
        allowed_dirs=args.allow_dir,
    )
    return 0


def _cache_clear() -> int:
    from workbench.disk_cache import cache_root, clear

    files, freed = clear()
    print(f"removed {files} cache files ({freed / 2**20:.1f} MB) from {cache_root()}")
    return 0


def _check(args: argparse.Namespace) -> int:
    from workbench.project.units import to_deg, to_mm
    from workbench.service import Workbench

    wb = Workbench.open(args.project, allowed_dirs=args.allow_dir)
    report = wb.collision_status()
    # the controller's joint values, as the project file and the pendant hold them (+ 0.0:
    # no "-0.00" of a value that rounds to zero)
    qc = to_deg(wb.robot.convention.to_controller(wb.joints))
    q = ", ".join(f"{round(float(v), 2) + 0.0:.2f}" for v in qc)
    print(
        f"{args.project}: valid; robot {wb.project.robot.name} ({wb.robot.dof} joints) at [{q}]"
        " deg (controller)"
    )
    if report.in_collision:
        pairs = ", ".join(f"{a}–{b}" for a, b in report.colliding)
        print(f"collision: {pairs}")
        return 1
    closest = " – ".join(report.closest_pair) if report.closest_pair else "none"
    print(f"collision-free; clearance {to_mm(report.min_distance):.1f} mm ({closest})")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the process exit code."""
    args = _parser().parse_args(argv)
    try:
        if args.command == "serve":
            return _serve(args)
        if args.command == "export":
            return _export(args)
        if args.command == "cache":
            return _cache_clear()
        if args.command == "import":
            return _import(args)
        if args.command == "sweep":
            return _sweep(args)
        if args.command == "import-part":
            return _import_part(args)
        if args.command == "calibrate":
            return cli_calibrate.run(args)
        if args.command == "touchup":
            return cli_touchup.run(args)
        if args.command == "polishing-faces":
            return cli_polishing.run(args)
        return _check(args)
    except WorkbenchError as exc:
        first = str(exc).strip().splitlines()
        print(f"workbench {args.command}: error: {first[0]}", file=sys.stderr)
        for line in first[1:]:
            print(line, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
