"""The service API: `Workbench` turns a project into domain objects and runs them."""

from __future__ import annotations

from workbench.service.cell import CellBody
from workbench.service.workbench import IKSolution, Workbench

__all__ = ["CellBody", "IKSolution", "Workbench"]
