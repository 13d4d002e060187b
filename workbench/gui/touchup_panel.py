"""The Project tab's "Touch-up" folder: a program edited on the controller, compared with the
project's, its changes applied with undo.

- **Upload edited program**: any format the workbench writes (a RAPID .mod, a KRL .zip of
  .src + .dat, a FANUC .ls, a URScript .script, a NACHI program). The service matches it to
  the project's program move by move (`wb.touchup.compare`); the project stays as it is.
- The table lists each target's change (dx, dy, dz [mm], rotation [deg]) and whether it
  agrees with the one rigid correction of the work object fitted to the changes; the targets
  that do not agree are named.
- **Apply** (`wb.touchup.apply`) as chosen in "Apply to": the fitted correction into the work
  object, the touched-up targets into the program, or both; **Undo** puts the project before
  it back (`project_undo.py`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
import viser

from workbench.errors import InputError
from workbench.geometry.transforms import transform_to_xyz_rpy
from workbench.gui.fit_marks import FitMarks
from workbench.gui.notify import guarded, notify
from workbench.service.program_import import program_files

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp

MODES = {"Work object": "work_object", "Targets": "targets", "Both": "both"}
MM_PER_M, DEG_PER_RAD = 1000.0, 180.0 / np.pi  # display only


def _n(v: float | None, digits: int = 2) -> str:
    return "" if v is None else f"{v:.{digits}f}"


def rows_markdown(report: Any) -> str:
    """Return the report's rows as a markdown table: each move's change in its work object
    (dx, dy, dz [mm], rotation [deg]) and whether it fits the work object's correction."""
    head = (
        "| Move | Wobj | dx mm | dy mm | dz mm | rot deg | |\n|---|---|---:|---:|---:|---:|---|\n"
    )
    body = []
    for r in report.rows:
        dx, dy, dz = r.delta_mm if r.delta_mm is not None else (None, None, None)
        if r.status in ("added", "deleted"):
            verdict = f"{r.status} on the pendant"
        elif not r.moved:
            verdict = "same"
        else:
            verdict = {None: "moved", True: "fits", False: "**alone**"}[r.agrees]
        body.append(
            f"| {r.name} | {r.wobj} | {_n(dx)} | {_n(dy)} | {_n(dz)} | {_n(r.angle_deg, 3)}"
            f" | {verdict} |"
        )
    return head + "\n".join(body)


def corrections_markdown(report: Any) -> str:
    """Return each work object's fitted correction (xyz [mm], rpy [deg] in its own frame), its
    residuals and the targets that do not fit it; why none was fitted where targets moved."""
    out = []
    for c in report.corrections:
        if not c.fitted and any(r.moved and r.wobj == c.wobj for r in report.rows):
            out.append(f"Work object **{c.wobj}**: no correction fitted: {c.reason}")
        if not c.fitted:
            continue
        xyz, rpy = transform_to_xyz_rpy(c.T_correction)
        out.append(
            f"Work object **{c.wobj}**: correction xyz ({', '.join(_n(v * MM_PER_M, 3) for v in xyz)})"
            f" mm, rpy ({', '.join(_n(v * DEG_PER_RAD, 3) for v in rpy)}) deg in its frame;"
            f" residual rms {_n(c.rms * MM_PER_M, 3)} mm, max {_n(c.max * MM_PER_M, 3)} mm"
        )
        if c.outliers:
            out.append(f"moved alone (not folded into {c.wobj}): **{', '.join(c.outliers)}**")
    out += [f"note: {n}" for n in report.notes]
    return "  \n".join(out)


def changed_points(report: Any) -> tuple[dict[str, Any], dict[str, float], list[str]]:
    """Return the moved targets' taught positions [m, world], their change [m] and the labels
    of those that fit no correction ("pick (alone)"), for the 3D view."""
    points, change, alone = {}, {}, []
    for r in report.rows:
        if r.moved and r.taught is not None and r.delta is not None:
            label = r.name if r.agrees is not False else f"{r.name} (alone)"
            points[label] = r.taught.T_world_tcp[:3, 3]
            change[label] = float(np.linalg.norm(r.delta))
            if r.agrees is False:
                alone.append(label)
    return points, change, alone


class TouchupPanel:
    """Upload, compare, apply and undo of a touched-up program (see the module doc)."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        s = self.server = app.server
        g = s.gui
        self.report: Any = None
        self.marks = FitMarks(s, "/touchup")
        with g.add_folder("Touch-up", expand_by_default=False):
            self.upload = g.add_upload_button(
                "Upload edited program",
                icon=viser.Icon.UPLOAD,
                hint="the program as the controller holds it after the touch-up (a KRL .zip of"
                " .src + .dat); compared with the project's, nothing changes yet",
            )
            self.summary = g.add_markdown("")
            self.table = g.add_markdown("")
            self.fits = g.add_markdown("")
            labels = tuple(MODES)
            self.mode = g.add_dropdown("Apply to", options=labels, initial_value=labels[0])
            self.apply = g.add_button("Apply touch-up", disabled=True)
            self.undo = g.add_button("Undo", disabled=True)
        self.upload.on_upload(guarded(s, "Touch-up")(self._on_upload))
        self.apply.on_click(guarded(s, "Apply touch-up")(self._on_apply))
        self.undo.on_click(guarded(s, "Undo")(self._on_undo))
        app.undo.listeners.append(self.refresh)
        self.refresh()

    @property
    def wb(self):  # type: ignore[no-untyped-def]  # the app's workbench (one per server)
        return self.app.wb

    def refresh(self) -> None:
        """Show what the next undo takes back."""
        last = self.app.undo.last
        self.undo.disabled = last is None
        self.undo.label = f"Undo {last}" if last else "Undo"

    def _on_upload(self, event: viser.GuiEvent) -> None:
        up = self.upload.value
        report = self.wb.touchup.compare(program_files(up.name, up.content))
        self.report = report
        moved = sum(r.moved for r in report.rows)
        self.summary.content = (
            f"**{up.name}** ({report.fmt}): {len(report.rows)} moves, {moved} moved"
        )
        self.table.content = rows_markdown(report)
        self.fits.content = corrections_markdown(report)
        self.apply.disabled = False
        points, change, alone = changed_points(report)
        best = report.correction
        self.marks.show(
            points,
            frame=None if best is None or not best.fitted else best.T_world_wobj_new,
            frame_name=f"{best.wobj} corrected" if best is not None else "",
            residuals_m=change,
            outliers=alone,
            bad_m=np.inf,  # red: the targets moved alone, not the size of the change
        )

    def _on_apply(self, event: viser.GuiEvent) -> None:
        report = self.report
        if report is None:
            raise InputError("nothing compared yet; upload the edited program first")
        mode = MODES[str(self.mode.value)]
        with self.app.jobs.job("applying a touch-up"):
            # then plans the program again, its progress in the banner
            previous = self.wb.touchup.apply(report, mode=mode, progress=self.app.jobs.progress)
            self.app.undo.push(f"touch-up ({mode.replace('_', ' ')})", previous)
            self.app.rebuild()
        self.report = None
        self.apply.disabled = True
        self.marks.clear()
        applied = self.wb.touchup.last_applied
        body = applied.summary() if applied is not None else str(self.mode.value)
        self.summary.content = f"```\n{body}\n```"
        self.table.content = self.fits.content = ""
        notify(self.server, event.client, "Touch-up applied", str(self.mode.value), color="green")

    def _on_undo(self, event: viser.GuiEvent) -> None:
        what = self.app.undo_last()
        notify(self.server, event.client, "Undone", what, color="green")

    def clear(self) -> None:
        """Forget the comparison and take its marks down (another project was opened)."""
        self.report = None
        self.summary.content = self.table.content = self.fits.content = ""
        self.apply.disabled = True
        self.marks.clear()
