"""The "Project" tab: open an example, upload a project with its files, download, save, save as.

- **Open example**: the example projects (`picker.py`), loaded from their files.
- **Upload**: a project JSON, a .zip of the JSON and its meshes, or the JSON then each file it
  names (`project_upload.py`); relative paths resolve in the upload's own folder.
- **Download project** gives a .zip of the JSON and every file it names (`Workbench.to_zip`),
  which **Upload** takes back.
- **Files when saving**: rebase (name the same files from the new folder) or copy (copy them
  beside the saved project): `Workbench.save`'s `files`.
- **Save** writes the file the project was opened from; an example (`projects/`) is read-only
  to it, and an uploaded project has no file yet: both need **Save as**.
- **Save as** writes `name` atomically in the server's working folder (`workbench serve`'s
  current folder, shown on the tab); an existing file is replaced only with **Overwrite**
  ticked.

Every load runs as the session's job: refused with "busy: ..." while a plan runs.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import viser

from workbench.errors import InputError
from workbench.gui import project_upload
from workbench.gui.notify import guarded, notify
from workbench.gui.picker import Example, example_index, examples, is_example
from workbench.service.project_files import save_target
from workbench.service.project_save import SavedProject, save_project_file
from workbench.service.project_zip import zip_stem

FILE_CHOICES = ("rebase: the same files", "copy: beside the project")

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp


class ProjectPanel:
    """Open / upload / download / save of the whole project; loads go through `app.open_project`."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        s = self.server = app.server
        g = s.gui
        self.staged: project_upload.Staged | None = None
        self.info = g.add_markdown("")
        self.examples = examples()
        titles = [f"{e.title} ({e.path.name})" for e in self.examples] or ["(no examples found)"]
        self.example = g.add_dropdown("Example", options=tuple(titles), initial_value=titles[0])
        self.open_example = g.add_button("Open example", disabled=not self.examples)
        self.upload = g.add_upload_button(
            "Upload project or its files",
            icon=viser.Icon.UPLOAD,
            hint="A project .json, a .zip of the project and its meshes, or (after a .json)"
            " each file it names",
        )
        self.pending = g.add_markdown("")
        self.download = g.add_button(
            "Download project (.zip)",
            icon=viser.Icon.DOWNLOAD,
            hint="The project JSON and every file it names; Upload takes it back",
        )
        self.files = g.add_dropdown(
            "Files when saving",
            options=FILE_CHOICES,
            initial_value=FILE_CHOICES[0],
            hint="rebase: the saved project names the same files from its folder (copying only"
            " what it could not read there); copy: every file copied beside it",
        )
        self.save = g.add_button("Save", icon=viser.Icon.DEVICE_FLOPPY)
        with g.add_folder("Save as", expand_by_default=True):
            self.where = g.add_markdown("")
            self.name = g.add_text(
                "File name",
                initial_value="",
                hint="a plain name (.json is added), in the folder above",
            )
            self.overwrite = g.add_checkbox("Overwrite", initial_value=False)
            self.save_as = g.add_button("Save as")
        self.open_example.on_click(guarded(s, "Open example")(self._on_open_example))
        self.upload.on_upload(guarded(s, "Load project")(self._on_upload))
        self.download.on_click(guarded(s, "Download project")(self._on_download))
        self.save.on_click(guarded(s, "Save project")(self._on_save))
        self.save_as.on_click(guarded(s, "Save as")(self._on_save_as))
        self.refresh()

    @property
    def wb(self):  # type: ignore[no-untyped-def]  # the app's workbench (one per server)
        return self.app.wb

    @property
    def folder(self) -> Path:
        """Return the folder "Save as" writes to: the server's working folder."""
        return self.app.save_folder

    def refresh(self) -> None:
        """Show the project's name, its file and where Save and Save as write."""
        wb = self.wb
        if wb.path is None:
            where = "not saved to a file yet: **Save as** gives it a name"
        elif is_example(wb.path):
            where = f"`{wb.path}` (an example: read-only to Save, use **Save as**)"
        else:
            where = f"`{wb.path}`"
        self.info.content = f"**{wb.project.name}**  \n{where}"
        shown = example_index(self.examples, wb.path)
        if shown is not None:  # the dropdown shows the example open (else the last chosen)
            self.example.value = self.example.options[shown]  # type: ignore[misc]
        self.where.content = f"Writes in `{self.folder}`"
        self.save.disabled = wb.path is None or is_example(wb.path)
        self.save.label = f"Save to {wb.path.name}" if wb.path is not None else "Save"
        self.pending.content = self.staged.describe() if self.staged is not None else ""

    # -- loading --------------------------------------------------------------------------
    def _on_open_example(self, event: viser.GuiEvent) -> None:
        titles = list(self.example.options)
        ex = self.examples[titles.index(str(self.example.value))]
        self.open(ex, event)

    def open(self, ex: Example, event: viser.GuiEvent | None) -> None:
        """Open example `ex` from its file (its meshes' folder allowed)."""
        self.app.open_file(ex.path, allowed=ex.allowed)
        self._drop_staged()
        notify(
            self.server,
            _client(event),
            "Project loaded",
            f"{ex.path.name}: {ex.title}",
            color="green",
        )

    def _on_upload(self, event: viser.GuiEvent) -> None:
        file = self.upload.value
        name = file.name.lower()
        if self.staged is not None and self.staged.wants(file.name):
            filled = self.staged.add(file.name, file.content)
            if not self.staged.ready:
                self.refresh()
                notify(self.server, event.client, "File added", filled, color="green")
                return
            staged = self.staged
        elif name.endswith(".zip"):
            staged = project_upload.stage_zip(file.name, file.content)
            if not staged.ready:  # a zip is the whole project: refused, not half-loaded
                project_upload.remove_folder(staged.root)
                lacking = ", ".join(staged.missing)
                raise InputError(
                    f"upload: {file.name} lacks files its project names ({lacking}); add them"
                    " to the zip at those paths, relative to the project file"
                )
            self._drop_staged()
        elif name.endswith(".json"):
            staged = self._restage(project_upload.stage_json(file.name, file.content))
        elif self.staged is not None:
            self.staged.add(file.name, file.content)  # raises: says which files it waits for
            return
        else:
            raise InputError(
                f"upload: {file.name}: expected a project (.json or .zip); upload a mesh after"
                " the project that names it"
            )
        if not staged.ready:
            self.refresh()
            notify(
                self.server, event.client, "Project needs files", staged.describe(), color="yellow"
            )
            return
        self.staged = None
        try:
            self.app.open_upload(staged.json_path, staged.root)
        except BaseException:
            project_upload.remove_folder(staged.root)
            self.refresh()
            raise
        notify(
            self.server,
            event.client,
            "Project loaded",
            f"{file.name}: {staged.name}",
            color="green",
        )

    def _restage(self, staged: project_upload.Staged) -> project_upload.Staged:
        self._drop_staged()
        self.staged = staged
        return staged

    def _drop_staged(self) -> None:
        if self.staged is not None:
            project_upload.remove_folder(self.staged.root)
            self.staged = None

    # -- saving ---------------------------------------------------------------------------
    def _on_download(self, event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        with self.app.jobs.job("packing the project"):
            data = self.wb.to_zip()
        name = zip_stem(self.wb) + ".zip"
        event.client.send_file_download(name, data, save_immediately=True)

    def _on_save(self, event: viser.GuiEvent) -> None:
        wb = self.wb
        if wb.path is None:
            raise InputError("save: this project was uploaded and has no file; use Save as")
        if is_example(wb.path):
            raise InputError(
                f"save: {wb.path.name} is an example (read-only to Save); use Save as with a"
                " new name"
            )
        with self.app.jobs.job("saving the project"):
            saved = save_project_file(wb, wb.path, files=self._files())
        self._saved(event, saved)

    def _on_save_as(self, event: viser.GuiEvent) -> None:
        target = save_target(self.folder, str(self.name.value))
        with self.app.jobs.job("saving the project"):
            saved = save_project_file(
                self.wb, target, overwrite=bool(self.overwrite.value), files=self._files()
            )
        self.overwrite.value = False  # type: ignore[misc]
        self.refresh()
        self._saved(event, saved)

    def _files(self) -> str:
        """Return the save mode chosen: "rebase" or "copy"."""
        return str(self.files.value).split(":")[0]

    def _saved(self, event: viser.GuiEvent, saved: SavedProject) -> None:
        body = str(saved.path) + "".join(f"\n- {n}" for n in saved.notes)
        color = "yellow" if saved.notes else "green"
        notify(self.server, event.client, "Saved", body, color=color)

    def remove(self) -> None:
        """Remove the tab's widgets and any upload still waiting for files."""
        self._drop_staged()
        for h in (
            self.info,
            self.example,
            self.open_example,
            self.upload,
            self.pending,
            self.download,
            self.files,
            self.save,
            self.where,
            self.name,
            self.overwrite,
            self.save_as,
        ):
            h.remove()


def _client(event: viser.GuiEvent | None) -> viser.ClientHandle | None:
    return getattr(event, "client", None)
