"""A fit in the 3D view: the measured points, labelled with their residuals, and the fitted frame.

Drawn from plain arrays under one parent node placed at `T_world_ref` (the frame the points are
given in; default the world), so the GUI does no frame arithmetic: viser composes the poses.
Residuals are shown in mm (a display conversion); a point whose residual is over `bad_m`, or
that the fit named an outlier, is red. Points that (nearly) coincide, as a TCP calibration's
tips do, share one label listing each on its own line, instead of labels drawn over each other.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import viser
from numpy.typing import ArrayLike, NDArray

from workbench.gui.scene import place

ROOT = "/fit"
POINT_COLOR = (20, 160, 80)
BAD_COLOR = (230, 40, 40)
POINT_RADIUS = 0.009  # [m]
FRAME_AXES = 0.12  # [m]
MM_PER_M = 1000.0  # display only
LABEL_UP_M = 0.012  # [m] a label above its point
STACK_M = 0.02  # [m] points closer than this share a label


def residual_text(label: str, residual_m: float | None) -> str:
    """Return a point's label as the view shows it: its name and residual [mm]."""
    if residual_m is None:
        return label
    return f"{label}  {residual_m * MM_PER_M:.2f} mm"


class FitMarks:
    """The scene nodes of one fit; `show` replaces them, `clear` removes them."""

    def __init__(self, server: viser.ViserServer, root: str = ROOT) -> None:
        self.server = server
        self.root = root
        self.nodes: list[viser.SceneNodeHandle] = []
        self.labels: list[str] = []  # the texts shown, for tests and the panel

    def show(
        self,
        points_m: Mapping[str, ArrayLike],
        *,
        T_world_ref: NDArray[np.float64] | None = None,
        frame: NDArray[np.float64] | None = None,
        frame_name: str = "fitted",
        residuals_m: Mapping[str, float] | None = None,
        outliers: Sequence[str] = (),
        bad_m: float = 1e-3,
    ) -> None:
        """Draw `points_m` {label: (3,) [m] in the reference frame}, each labelled with its
        residual [m] if given, and the fitted `frame` (4, 4) [m, in the reference frame]."""
        self.clear()
        s = self.server
        parent = s.scene.add_frame(self.root, show_axes=False)
        if T_world_ref is not None:
            place(parent, np.asarray(T_world_ref, float))
        self.nodes.append(parent)
        residuals = dict(residuals_m or {})
        stacks: list[tuple[NDArray[np.float64], list[str]]] = []  # (where, texts) per label
        for k, (label, p) in enumerate(points_m.items()):
            r = residuals.get(label)
            bad = label in outliers or (r is not None and r > bad_m)
            xyz = np.asarray(p, float).reshape(3)
            dot = s.scene.add_icosphere(
                f"{self.root}/p{k}",
                radius=POINT_RADIUS,
                color=BAD_COLOR if bad else POINT_COLOR,
                position=xyz,
                cast_shadow=False,
            )
            self.nodes.append(dot)
            text = residual_text(label, r)
            self.labels.append(text)
            near = next((t for q, t in stacks if np.abs(q - xyz).max() < STACK_M), None)
            if near is None:
                stacks.append((xyz, [text]))
            else:
                near.append(text)
        for k, (xyz, texts) in enumerate(stacks):
            self.nodes.append(
                s.scene.add_label(
                    f"{self.root}/l{k}",
                    "\n".join(texts),
                    position=xyz + (0.0, 0.0, LABEL_UP_M),
                    anchor="bottom-left",
                )
            )
        if frame is not None:
            axes = s.scene.add_frame(
                f"{self.root}/frame", axes_length=FRAME_AXES, axes_radius=0.005
            )
            place(axes, np.asarray(frame, float))
            # below and left of its origin: clear of the points' labels, which go above right
            name = s.scene.add_label(f"{self.root}/frame/name", frame_name, anchor="top-right")
            self.nodes += [axes, name]
            self.labels.append(frame_name)

    def clear(self) -> None:
        """Remove every node of the fit."""
        for h in reversed(self.nodes):
            h.remove()
        self.nodes.clear()
        self.labels.clear()
