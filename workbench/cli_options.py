"""Options that several `workbench` commands share (cli.py and the cli_* command modules)."""

from __future__ import annotations

import argparse


def add_allow_dir(parser: argparse.ArgumentParser) -> None:
    """Add `--allow-dir DIR` (repeatable): a folder the project's files may lie in besides its
    own (the path rule of docs/security.md)."""
    parser.add_argument(
        "--allow-dir",
        action="append",
        default=[],
        metavar="DIR",
        help="a folder the project's files may lie in besides its own (repeat)",
    )
