"""`workbench <args>` run in the test's own process: the command line's `main` with its exit
code, standard output and standard error captured, from the repository root (as the tests'
`python -m workbench` subprocesses ran it). A subprocess pays a fresh interpreter and the
package's imports (about 1 s here) per call; `main` is what `python -m workbench` runs
(workbench/__main__.py: `raise SystemExit(main())`), so an exit code and the streams are the
same. Tests that need a separate process (a server, Ray, the entry point itself) keep one."""

from __future__ import annotations

import contextlib
import io
import subprocess
from pathlib import Path

from workbench.cli import main

ROOT = Path(__file__).resolve().parents[1]


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    """Return `workbench *args` run in this process, from the repository root."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.chdir(ROOT), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return subprocess.CompletedProcess(["workbench", *args], code, out.getvalue(), err.getvalue())
