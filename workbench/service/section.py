"""`SectionService`: the base of each workflow service, bound to one section of the project."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

from workbench.errors import InputError

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

S = TypeVar("S")


class SectionService(Generic[S]):
    """A workflow of the open project, built from its section `section` (e.g. ``"bending"``).

    Subclasses name the section and say how to add one when it is missing (`missing`).
    """

    section: ClassVar[str]
    missing: ClassVar[str]

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb

    def _section(self) -> Any:
        return getattr(self.wb.project, self.section)

    @property
    def spec(self) -> S:
        """Return the project's section; InputError naming the section when there is none."""
        spec = self._section()
        if spec is None:
            raise InputError(
                f"{self.section}: the project has no {self.section!r} section; {self.missing}"
            )
        return spec  # type: ignore[no-any-return]

    @property
    def available(self) -> bool:
        """Return True when the project has this section."""
        return self._section() is not None
