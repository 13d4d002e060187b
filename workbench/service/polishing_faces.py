"""The polishing workflow's solid workpiece: the faces of a STEP solid to pick from
(`faces`), the picked ones (`set_faces`, the project's `polishing.faces`), and the robot
checker whose cell holds the solid as an obstacle (`plan_checker`).

A mixin of `PolishingService` (kept apart for the service's size): it uses the service's
`wb`, `spec`, `_fitted` and `load_workpiece`.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from workbench.cad.step import is_step
from workbench.cad.step_faces import StepFace, read_step_faces
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import InputError, WorkbenchError
from workbench.polishing.fitted_workpiece import FittedWorkpiece
from workbench.polishing.solid_workpiece import CONTACT_MARGIN, obstacle_bodies
from workbench.project.cad import step_tolerance
from workbench.project.paths import shown_path
from workbench.project.polishing import PolishingSpec, _validated

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


class SolidFaces:
    """Picking the faces of a STEP solid to polish (see the module)."""

    wb: Workbench
    _fitted: FittedWorkpiece | None
    _plan_checker: tuple[FittedWorkpiece, float, RobotCollisionChecker] | None = None

    if TYPE_CHECKING:  # PolishingService's

        @property
        def spec(self) -> PolishingSpec: ...

        def _resolve(self, path: str | Path) -> Path: ...

        def load_workpiece(self, path: Any = None, *, units: str | None = None) -> Any: ...

    def faces(self, path: str | Path | None = None) -> tuple[StepFace, ...]:
        """Return every face of the workpiece's STEP file (or of `path`): index, surface type,
        area [mm²], centroid [mm] (the file's frame) and a planar face's normal (`StepFace`).

        InputError naming `polishing.workpiece` when the workpiece is a mesh file."""
        if path is None and self._fitted is not None and self._fitted.solid is not None:
            return self._fitted.solid.faces
        file = str(self.spec.workpiece if path is None else path)
        if not is_step(file):
            raise InputError(
                f"{shown_path(file)!r} is a mesh file: it has no faces to pick; "
                "give a STEP file to polish some of its faces",
                field="polishing.workpiece",
            )
        real = self._resolve(file)
        tol = step_tolerance(self.wb.project.cad)
        try:
            read = read_step_faces(real.read_bytes(), shown_path(file), "workpiece", tol)
        except WorkbenchError as exc:
            raise exc.within("polishing.workpiece") from exc
        return read.faces

    def set_faces(self, faces: Sequence[int] | None, path: str | Path | None = None) -> None:
        """Polish the faces `faces` (indices into `faces()`) of the STEP solid (of the file
        `path`, which becomes the workpiece); None: the whole file. The workpiece is loaded
        again; on an error (`polishing.faces` out of range, empty, repeated, or a mesh file)
        the section and workpiece stay as they were."""
        spec = self.spec
        old = (spec.workpiece, spec.faces)
        new = _validated({**spec.model_dump(), "faces": None if faces is None else list(faces)})
        spec.workpiece = spec.workpiece if path is None else str(path)
        spec.faces = new.faces
        try:
            self.load_workpiece()
        except WorkbenchError:
            spec.workpiece, spec.faces = old
            raise

    def solid_mesh(self) -> tuple[NDArray[np.float64], NDArray[np.int64]] | None:
        """Return (vertices [m], faces) of the whole solid in the world for display, or None
        when the workpiece is a surface file (no faces picked)."""
        fitted = self._fitted
        if fitted is None or fitted.solid is None:
            return None
        return np.asarray(fitted.solid.mesh.vertices), np.asarray(fitted.solid.mesh.faces)

    def suggested_faces(self, path: str | Path | None = None) -> list[int]:
        """Return a first pick for a solid (the user changes it): its largest face, of faces
        within 1 % of that area the highest in the world (a slab's top, not its bottom)."""
        faces = self.faces(path)
        big = max(f.area for f in faces)
        R = self.spec.to_si().T_world_workpiece[:3, :3]
        best = max((f for f in faces if f.area >= 0.99 * big), key=lambda f: (R @ f.centroid)[2])
        return [best.index]

    def plan_checker(self) -> RobotCollisionChecker:
        """Return the checker plans use: the project's, or with a solid workpiece the cell plus
        the solid (`obstacle_bodies`: every link against the whole solid, the tool against
        all of it beyond the polished faces' contact band: the contact offset F/k plus
        `CONTACT_MARGIN`)."""
        fitted = self._fitted
        if fitted is None or fitted.solid is None:
            return self.wb.checker
        si = self.spec.to_si()
        band = si.force / si.control.stiffness + CONTACT_MARGIN
        made = self._plan_checker
        if made is None or made[0] is not fitted or made[1] != band:
            try:
                bodies, ignore = obstacle_bodies(fitted.solid, band)
            except WorkbenchError as exc:
                raise exc.within("polishing") from exc
            setup, cell = self.wb.setup, self.wb.cell
            checker = RobotCollisionChecker(
                setup.model,
                setup.link_meshes,
                T_world_base=setup.T_world_base,
                tool=setup.tool_mesh,
                cell=[(b.solid, b.T_world_body) for b in cell if b.collide] + bodies,
                q_reference=setup.q0,
                ignore=ignore,
            )
            made = self._plan_checker = (fitted, band, checker)
        return made[2]
