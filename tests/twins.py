"""Import a file by its path: a test module whose helpers another test uses as its twin, or an
example script whose name starts with a digit (neither is importable by `import` under
``--import-mode=importlib``)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[1]


def load_module(path: Path | str, name: str) -> ModuleType:
    """Import the Python file at `path` (relative to the repository root) as module `name`.

    The module is registered in ``sys.modules`` under `name` first, so its dataclasses and
    pickles resolve; a second call returns the module already imported.
    """
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, ROOT / path)
    assert spec is not None and spec.loader is not None, f"cannot import {path}"
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module
