"""Robot workbench: an offline-programming workbench for industrial robots in the browser."""

from __future__ import annotations

from typing import TYPE_CHECKING

from workbench.errors import WorkbenchError

if TYPE_CHECKING:  # type checkers see the class; at run time it is imported on first use
    from workbench.service import Workbench

__all__ = ["Workbench", "WorkbenchError"]
__version__ = "0.1.0"


def __getattr__(name: str) -> object:
    # Workbench pulls in pinocchio, fcl and trimesh; import it lazily so that
    # `import workbench.geometry` stays light.
    if name == "Workbench":
        from workbench.service import Workbench

        return Workbench
    raise AttributeError(f"module 'workbench' has no attribute {name!r}")
