"""`WorkflowSlot`: a Workbench attribute holding one workflow service, made on first use.

`bending = WorkflowSlot(BendingService, "...")` on the Workbench class gives
`wb.bending`: the one `BendingService(wb)` of that workbench (made under its lock, kept until
the project is replaced), typed as the service class, with the given docstring.
"""

from __future__ import annotations

from typing import Any, Generic, TypeVar

S = TypeVar("S")


class WorkflowSlot(Generic[S]):
    """A read-only attribute of the Workbench: its `cls(wb)`, made once per project."""

    def __init__(self, cls: type[S], doc: str) -> None:
        self.cls = cls
        self.__doc__ = doc
        self.name = cls.__name__

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def __get__(self, wb: Any, owner: type | None = None) -> S:
        if wb is None:
            return self  # type: ignore[return-value]  # the class attribute: the slot itself
        return wb._workflow(self.name, self.cls)  # type: ignore[no-any-return]
