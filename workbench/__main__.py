"""`python -m workbench`: the same command line as the `workbench` entry point."""

from __future__ import annotations

from workbench.cli import main

raise SystemExit(main())
