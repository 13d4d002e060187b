"""Robot workbench: an offline-programming workbench for industrial robots in the browser."""

from __future__ import annotations

from workbench.errors import WorkbenchError

__all__ = ["Workbench", "WorkbenchError"]
__version__ = "0.1.0"


def __getattr__(name: str) -> object:
    # Workbench pulls in pinocchio, fcl and trimesh; import it lazily so that
    # `import workbench.geometry` stays light.
    if name == "Workbench":
        from workbench.service import Workbench

        return Workbench
    raise AttributeError(f"module 'workbench' has no attribute {name!r}")
